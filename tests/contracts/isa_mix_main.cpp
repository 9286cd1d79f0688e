// One definition across instruction sets. Three translation units compute the same things with quat
// built for the baseline (x86-64), for AVX2 + FMA and for AVX-512; each must run its own code. If
// the linker kept one unit's copy of a quat function for all three (a function whose name does not
// say which instruction set it was compiled for), the baseline unit would run AVX code, and the
// CTest run of this program under `qemu-x86_64 -cpu Nehalem` (no AVX) ends with SIGILL. On a CPU
// with AVX2 or AVX-512 the other units run too: each must hold its own copy of quat's functions
// (compared by address: the scalar to_matrix and the batch rotate) and agree with the baseline's
// values.
// This unit includes no quat header.
#include <cmath>
#include <cstdio>
#include <cstring>

#include "isa_mix.hpp"

namespace {

isa_mix_results baseline, other;

bool agree(const double* a, const double* b, std::size_t n, const char* what, const char* unit) {
    for (std::size_t i = 0; i < n; ++i) {
        // Relative to the value's size: the units round differently (FMA contraction, wider loops).
        if (!(std::fabs(a[i] - b[i]) <= 1e-5 * (1 + std::fabs(a[i])))) {
            std::printf("FAIL: %s of the %s unit differs at %zu: %.9g against %.9g\n", what, unit,
                        i, b[i], a[i]);
            return false;
        }
    }
    return true;
}

bool agrees_with_baseline(const char* unit) {
    const isa_mix_results& a = baseline;
    const isa_mix_results& b = other;
    const std::size_t n = isa_mix_results::samples;
    // Its own functions, whichever unit the linker met first.
    if (a.to_matrix == b.to_matrix || a.batch_rotate == b.batch_rotate) {
        std::printf("FAIL: the %s unit and the baseline share quat's functions\n", unit);
        return false;
    }
    bool ok = agree(&a.rotated[0][0], &b.rotated[0][0], 3 * n, "rotate", unit);
    ok = agree(&a.rotated_soa[0][0], &b.rotated_soa[0][0], 3 * n, "rotate (soa)", unit) && ok;
    ok = agree(&a.transformed[0][0], &b.transformed[0][0], 3 * n, "transform", unit) && ok;
    ok = agree(&a.rotated_each[0][0], &b.rotated_each[0][0], 3 * n, "rotate_each", unit) && ok;
    ok = agree(a.matrix, b.matrix, 9, "to_matrix", unit) && ok;
    ok = agree(a.slerped, b.slerped, 4, "slerp", unit) && ok;
    ok = agree(&a.slerped_batch[0][0], &b.slerped_batch[0][0], 4 * n, "batch slerp", unit) && ok;
    ok = agree(a.between, b.between, 4, "rotation_between", unit) && ok;
    ok = agree(a.looking, b.looking, 4, "look_rotation", unit) && ok;
    ok = agree(&a.propagated[0][0], &b.propagated[0][0], 36, "matrix product", unit) && ok;
    if (std::strcmp(a.printed, b.printed) != 0) {
        std::printf("FAIL: the %s unit printed\n%s\nthe baseline\n%s\n", unit, b.printed,
                    a.printed);
        ok = false;
    }
    return ok;
}

// Spot checks of the baseline's own values against numbers worked out by hand.
bool baseline_is_right() {
    // rotation_between((1, 1e-9, 0), (-1, 0, 1e-9)): a half turn (w ~ 0) about the axis a x b,
    // (1e-18, -1e-9, 1e-9) normalized, which only the compensated cross product gets right.
    const double* b = baseline.between;
    const double h = std::sqrt(0.5);
    if (!(std::fabs(b[0]) < 1e-6 && std::fabs(b[1]) < 1e-6 && std::fabs(b[2] + h) < 1e-6 &&
          std::fabs(b[3] - h) < 1e-6)) {
        std::printf("FAIL: rotation_between gave (%g, %g, %g, %g)\n", b[0], b[1], b[2], b[3]);
        return false;
    }
    // to_matrix gives an orthogonal matrix: row 0 has unit length.
    const double* m = baseline.matrix;
    if (!(std::fabs(m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - 1) < 1e-12)) {
        std::printf("FAIL: to_matrix's first row is not unit\n");
        return false;
    }
    // The batch slerp starts at a and ends at b = (0, 1, 0, 0) or -b.
    const double* end = baseline.slerped_batch[isa_mix_results::samples - 1];
    if (!(std::fabs(std::fabs(end[1]) - 1) < 1e-6)) {
        std::printf("FAIL: batch slerp does not end at b\n");
        return false;
    }
    // J C J^T with J = I + sum 0.5 i e_{i+1 mod 6} e_i^T and C = diag(1, ..., 6): (0, 0) is
    // 1 + 2.5^2 * 6 and (2, 2) is 3 + 0.5^2 * 2.
    if (!(baseline.propagated[0][0] == 38.5 && baseline.propagated[2][2] == 3.5)) {
        std::printf("FAIL: J C J^T gave %g and %g on the diagonal\n", baseline.propagated[0][0],
                    baseline.propagated[2][2]);
        return false;
    }
    const char* printed_start = "quaternion{0.5, -0.5, 0.5, 0.5} matrix{{38.5, ";
    if (std::strncmp(baseline.printed, printed_start, std::strlen(printed_start)) != 0) {
        std::printf("FAIL: printed %s\n", baseline.printed);
        return false;
    }
    return true;
}

}  // namespace

int main() {
    isa_mix_baseline(baseline);
    std::printf("baseline unit ran\n");
    bool ok = baseline_is_right();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
        isa_mix_avx2(other);
        ok = agrees_with_baseline("AVX2") && ok;
        std::printf("AVX2 unit ran\n");
    }
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
        __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq")) {
        isa_mix_avx512(other);
        ok = agrees_with_baseline("AVX-512") && ok;
        std::printf("AVX-512 unit ran\n");
    }
    std::printf(ok ? "every unit ran its own code and agreed\n" : "FAIL\n");
    return ok ? 0 : 1;
}
