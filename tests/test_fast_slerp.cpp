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

TEST_CASE("slerp_fast in double is within the fitted polynomial's 1e-8 rad of the exact slerp",
          "[fast_slerp]") {
    // The weights' own error is 8.3e-9 at worst (bench/fit_slerp_fast.py, on a grid). Measured here:
    // rotation angle 4.8e-9 rad, | |r| - 1 | 1.6e-8; `quat_accuracy --slerp-fast`, 1.3 million
    // samples against a __float128 slerp: 4.9e-9 rad and 1.6e-8. The angle is taken after
    // normalizing: angle_between of a non-unit quaternion would count the norm error as angle too.
    quat::test::random_rotations random;
    double worst_angle = 0, worst_norm = 0;
    for (int i = 0; i < 2000; ++i) {
        const quat::quatd a = random.unit_quaternion<double>(),
                          b = random.unit_quaternion<double>();
        const double t = random.uniform<double>(0, 1);
        const quat::quatd fast = quat::slerp_fast(a, b, t);
        worst_angle =
            std::max(worst_angle, quat::angle_between(quat::normalize(fast), quat::slerp(a, b, t)));
        worst_norm = std::max(worst_norm, std::abs(quat::norm(fast) - 1));
    }
    INFO("largest angular error " << worst_angle << " rad, largest | |r| - 1 | " << worst_norm);
    CHECK(worst_angle <= 1e-8);
    CHECK(worst_norm <= 2e-8);
}

TEST_CASE("slerp, nlerp and slerp_fast take a plain double or int t with float rotations",
          "[interpolation][first-use]") {
    quat::test::random_rotations random;
    const quat::quatf a = random.unit_quaternion<float>(), b = random.unit_quaternion<float>();
    CHECK(quat::slerp(a, b, 0.5) == quat::slerp(a, b, 0.5f));
    CHECK(quat::nlerp(a, b, 0.25) == quat::nlerp(a, b, 0.25f));
    CHECK(quat::slerp_fast(a, b, 0.75) == quat::slerp_fast(a, b, 0.75f));
    CHECK(quat::slerp(a, b, 1) == quat::slerp(a, b, 1.0f));
    CHECK(quat::slerp(a, b, 0.1) == quat::slerp(a, b, static_cast<float>(0.1)));
    const quat::rotation_matrix<float> m = quat::to_matrix(a);
    CHECK(quat::try_to_quaternion(m, 1e-3) == quat::try_to_quaternion(m, 1e-3f));
}
