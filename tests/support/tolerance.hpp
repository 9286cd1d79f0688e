// Test tolerances, in units of the scalar type's epsilon, named by what they bound.
#pragma once

#include <limits>

namespace quat::test {

template <class T>
constexpr T eps = std::numeric_limits<T>::epsilon();

/// Bounds for one scalar type; every literal tolerance used by a test lives here.
template <class T>
struct tolerance {
    static constexpr T product = 8 * eps<T>;            // component error of a few products
    static constexpr T rotate = 8 * eps<T>;             // per component of a rotated unit vector
    static constexpr T conversion = 8 * eps<T>;         // one conversion between representations
    static constexpr T round_trip = 16 * eps<T>;        // two conversions, as rotation angle (rad)
    static constexpr T euler_round_trip = 32 * eps<T>;  // Euler -> quaternion -> Euler -> rotation
    static constexpr T slerp_angle = 16 * eps<T>;  // angle of slerp(a, b, t) vs t * angle(a, b)
    static constexpr T unit_norm = 4 * eps<T>;     // |q| - 1 of a normalized result
    static constexpr T glm = 64 * eps<T>;          // against GLM, which rounds differently
    static constexpr T sclerp = 12 * eps<T>;  // sclerp vs a exp(t log(a^-1 b)), per entry scale
    static constexpr T constexpr_vs_runtime = 8 * eps<T>;  // compile-time math against <cmath>
};

}  // namespace quat::test
