// One definition across instruction sets: quat's batch functions compiled with and without
// AVX-512 are different functions (inline namespaces keyed by instruction set), so the linker
// cannot keep one and drop the other, which would run AVX-512 code in a baseline caller on a CPU
// without it, or silently skip the streaming branch. Both must also compute the right values,
// on an array large enough (over 16 MiB) to take the AVX-512 build's streaming branch.
#include <cmath>
#include <cstdio>
#include <vector>

#include "isa_mix.hpp"

namespace {

bool rotates_correctly(rotate_function rotate, const char* name) {
    const quat::quatf q = quat::normalize(quat::quatf{0.3f, -0.5f, 0.7f, 0.2f});
    const auto m = quat::to_matrix(q);
    std::vector<quat::vec3<float>> points(std::size_t(3) << 19), out(points.size());  // 18 MiB
    for (std::size_t i = 0; i < points.size(); ++i) {
        const float f = static_cast<float>(i % 1000);
        points[i] = {f, 1 - f, 0.5f * f};
    }
    rotate(m, points.data(), out.data(), points.size());
    for (std::size_t i = 0; i < points.size(); i += 997) {
        const quat::vec3<float> expected = quat::rotate(m, points[i]);
        if (std::abs(out[i].x - expected.x) > 1e-3f || std::abs(out[i].y - expected.y) > 1e-3f ||
            std::abs(out[i].z - expected.z) > 1e-3f) {
            std::printf("FAIL: %s rotate differs at point %zu\n", name, i);
            return false;
        }
    }
    return true;
}

}  // namespace

int main() {
    if (baseline_rotate() == avx512_rotate()) {
        std::printf(
            "FAIL: the baseline and AVX-512 translation units share one quat::rotate<float>\n");
        return 1;
    }
    bool ok = rotates_correctly(baseline_rotate(), "baseline");
    if (__builtin_cpu_supports("avx512f")) {
        ok = rotates_correctly(avx512_rotate(), "AVX-512") && ok;
    } else {
        std::printf("this CPU has no AVX-512: only the baseline unit's values are checked\n");
    }
    std::printf(ok ? "two definitions, both correct\n" : "FAIL\n");
    return ok ? 0 : 1;
}
