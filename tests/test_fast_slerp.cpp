// slerp_fast (quat/fast_slerp.hpp) stays within 1e-6 rad of the exact slerp in float.
#include <algorithm>
#include <cmath>

#include <quat/fast_slerp.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

namespace {

quat::quatd widen(const quat::quatf& q) { return {q.w, q.x, q.y, q.z}; }

}  // namespace

TEST_CASE("slerp_fast: rotation-angle error at most 1e-6 rad in float against the exact slerp",
          "[fast_slerp]") {
    quat::test::random_rotations random;
    double worst = 0;
    for (int pair = 0; pair < 4000; ++pair) {
        const quat::quatf a = random.unit_quaternion<float>();
        quat::quatf b = random.unit_quaternion<float>();
        // Adversarial pairs too: nearly equal, nearly opposite (dot near 0 = 180 degrees apart), -a.
        if (pair % 4 == 1) b = quat::normalize(a + quat::quatf{1e-4f, -2e-4f, 1e-4f, 3e-4f});
        if (pair % 4 == 2) b = quat::normalize(quat::quatf{-a.x, a.w, -a.z, a.y + 1e-3f});
        if (pair % 40 == 3) b = -a;
        for (int i = 0; i <= 64; ++i) {
            const float t = float(i) / 64.0f;
            // Reference: the exact slerp in double of the same float inputs, normalized in double.
            const quat::quatd exact =
                quat::slerp(quat::normalize(widen(a)), quat::normalize(widen(b)), double(t));
            const quat::quatd fast = widen(quat::slerp_fast(a, b, t));
            worst = std::max(worst, quat::angle_between(quat::normalize(fast), exact));
            // Its magnitude stays unit, so it can be used without renormalizing.
            CHECK(std::abs(quat::norm(fast) - 1.0) <= 1e-6);
        }
    }
    INFO("largest angular error " << worst << " rad");
    CHECK(worst <= 1e-6);
}

TEST_CASE("slerp_fast is exact at t = 0 and t = 1 and takes the shorter arc", "[fast_slerp]") {
    quat::test::random_rotations random;
    for (int i = 0; i < 100; ++i) {
        const quat::quatf a = random.unit_quaternion<float>(), b = random.unit_quaternion<float>();
        CHECK(quat::slerp_fast(a, b, 0.0f) == a);
        CHECK(quat::slerp_fast(a, b, 1.0f) == (quat::dot(a, b) < 0 ? -b : b));
        // The midpoint is within a hair of the exact one, also when b is given with the far sign.
        CHECK(quat::angle_between(quat::slerp_fast(a, -b, 0.5f), quat::slerp(a, b, 0.5f)) <= 2e-6f);
    }
}

TEST_CASE("slerp_fast in double is accurate to the fitted polynomial's 1e-8", "[fast_slerp]") {
    quat::test::random_rotations random;
    double worst = 0;
    for (int i = 0; i < 2000; ++i) {
        const quat::quatd a = random.unit_quaternion<double>(),
                          b = random.unit_quaternion<double>();
        const double t = random.uniform<double>(0, 1);
        worst =
            std::max(worst, quat::angle_between(quat::slerp_fast(a, b, t), quat::slerp(a, b, t)));
    }
    INFO("largest angular error " << worst << " rad");
    CHECK(worst <= 5e-8);
}
