// Uniformly distributed random rotations from any standard random bit generator.
#ifndef QUAT_RANDOM_HPP_INCLUDED
#define QUAT_RANDOM_HPP_INCLUDED

#include <limits>
#include <type_traits>

#include "constants.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"

namespace quat {

#include "detail/isa_namespace.inc"
namespace detail {

/// A uniform number in [0, 1) from generator's bits, as std::generate_canonical defines it (enough
/// calls for T's digits, combined in base max - min + 1) without <random>, which would double the
/// parse time of quat.hpp; a rounding up to 1 (LWG 2524) moves to the largest value below 1.
template <class T, class Generator>
[[nodiscard]] T uniform_unit_interval(Generator& generator) noexcept(noexcept(generator())) {
    constexpr long double range =
        static_cast<long double>(Generator::max() - Generator::min()) + 1.0L;
    // The fewest calls k with range^k >= 2^digits(T).
    constexpr int calls = [] {
        long double needed = 1;
        for (int i = 0; i < std::numeric_limits<T>::digits; ++i) needed *= 2;
        int k = 1;
        for (long double reach = range; reach < needed; reach *= range) ++k;
        return k;
    }();
    T sum = T(0), scale = T(1);
    for (int i = 0; i < calls; ++i) {
        sum += static_cast<T>(generator() - Generator::min()) * scale;
        scale *= static_cast<T>(range);
    }
    const T u = sum / scale;
    return u < T(1) ? u : T(1) - detail::epsilon<T>() / T(2);
}

}  // namespace detail

/// A unit quaternion with w >= 0 drawn uniformly over the rotations (the Haar measure: the rotation
/// angle has density (1 - cos(angle)) / pi on [0, pi] and the rotated axes are uniform on the
/// sphere). Shoemake's method ("Uniform random rotations", Graphics Gems III, 1992) from three
/// uniforms, with the second circle's angle in [-pi/2, pi/2] so that w >= 0; negate with
/// probability 1/2 for a uniform point of the unit 3-sphere. `generator` is any
/// UniformRandomBitGenerator (std::mt19937, std::mt19937_64, std::minstd_rand, ...); the result
/// depends only on its state, and no memory is allocated. T is float, double or long double.
template <class T, class Generator>
[[nodiscard]] quaternion<T> random_rotation(Generator& generator) noexcept(noexcept(generator())) {
    static_assert(std::is_floating_point_v<T>, "quat::random_rotation: T must be floating-point");
    const T u1 = detail::uniform_unit_interval<T>(generator);
    const T u2 = detail::uniform_unit_interval<T>(generator);
    const T u3 = detail::uniform_unit_interval<T>(generator);
    // (x, y) on a circle of radius sqrt(1 - u1) and (w, z) on one of radius sqrt(u1): the squared
    // radii are uniform, which makes the point uniform on the 3-sphere.
    const T r1 = detail::sqrt(T(1) - u1), r2 = detail::sqrt(u1);
    const T theta1 = T(2) * numbers::pi_v<T> * u2, theta2 = numbers::pi_v<T> * (u3 - T(0.5));
    // |cos|: pi rounded to float exceeds pi, so theta2 can land just past -pi/2 (u3 = 2^-31 gave
    // w = -3.1e-8); mirroring that sliver keeps w >= 0 and moves no probability.
    return {r2 * detail::abs(detail::cos(theta2)), r1 * detail::sin(theta1),
            r1 * detail::cos(theta1), r2 * detail::sin(theta2)};
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_RANDOM_HPP_INCLUDED
