// The average of many rotations: the chordal L2 mean, as scipy's Rotation.mean computes it.
#ifndef QUAT_FITTING_MEAN_HPP_INCLUDED
#define QUAT_FITTING_MEAN_HPP_INCLUDED

#include <cstddef>
#include <limits>
#include <optional>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"
#include "detail/symmetric_eigen.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

// The rotation matrices' mean M minimizing sum w_i |M - R_i|_F^2 has the quaternion of the largest
// eigenvalue of K = sum w_i q_i q_i^T (Markley, Cheng, Crassidis, Oshman, "Averaging quaternions",
// J. Guidance 30(4), 2007): |M - R_i|_F^2 = 8 - 8 (q . q_i)^2 for unit quaternions, so the sign of
// each q_i drops out. K is divided by its trace sum w_i, making the eigenvalues fractions of the
// total weight. `rotation(i)` gives q_i and `weight(i)` w_i; `valid` is false for no rotations, a
// weight below zero or a
// non-positive or non-finite total (a NaN or infinite component gives NaN eigenvalues), and, when
// `checked` (try_mean), for a rotation that is not a unit quaternion.
template <class T>
struct mean_solution {
    symmetric_eigen4<T> eigen;
    bool valid;
};

template <bool checked, class T, class Rotation, class Weight>
[[nodiscard]] constexpr mean_solution<T> solve_mean_of(Rotation rotation, std::size_t count,
                                                       Weight weight) noexcept {
    // The weights are divided by the largest first: the sums are ratios of weights, so the mean is
    // the same, and weights near max() do not overflow the sums nor subnormal ones underflow
    // them. A NaN or infinite weight makes the largest non-finite and the result invalid.
    T largest = T(0), lowest = T(0);
    bool units = true;
    for (std::size_t i = 0; i < count; ++i) {
        const T w = weight(i);
        lowest = w < lowest ? w : lowest;
        largest = w > largest || !(w == w) ? w : largest;
        if constexpr (checked) {
            units = units && detail::is_near_unit(rotation(i));
        } else {
            QUAT_ASSERT(detail::is_near_unit(rotation(i)),
                        "quat::mean: a rotation is not a unit quaternion");
        }
    }
    if constexpr (!checked) QUAT_ASSERT(!(lowest < T(0)), "quat::mean: a weight is negative");
    const T scale = largest > T(0) && detail::is_finite(largest) ? largest : T(1);
    // Blocked sums (see summation_block): for 1e6 rotations in float the plain running sums put
    // the mean 327 eps from its long double value, the blocked ones 0.8 eps (double: 145, 7.6).
    T sum[10] = {};
    for_each_block(count, [&](std::size_t start, std::size_t end) {
        T ww = T(0), wx = T(0), wy = T(0), wz = T(0), xx = T(0), xy = T(0), xz = T(0), yy = T(0),
          yz = T(0), zz = T(0);
        for (std::size_t i = start; i < end; ++i) {
            const quaternion<T>& q = rotation(i);
            const T w = weight(i) / scale;
            const T a = w * q.w, b = w * q.x, c = w * q.y;
            ww += a * q.w;
            wx += a * q.x;
            wy += a * q.y;
            wz += a * q.z;
            xx += b * q.x;
            xy += b * q.y;
            xz += b * q.z;
            yy += c * q.y;
            yz += c * q.z;
            zz += w * q.z * q.z;
        }
        const T block[10] = {ww, wx, wy, wz, xx, xy, xz, yy, yz, zz};
        for (int n = 0; n < 10; ++n) sum[n] += block[n];
    });
    const T ww = sum[0], wx = sum[1], wy = sum[2], wz = sum[3], xx = sum[4], xy = sum[5],
            xz = sum[6], yy = sum[7], yz = sum[8], zz = sum[9];
    const T trace = ww + xx + yy + zz;
    const bool valid = count > 0 && units && !(lowest < T(0)) && trace > T(0) &&
                       detail::is_finite(trace) && detail::is_finite(largest);
    const T s = valid ? T(1) / trace : T(1);
    const T k[4][4] = {{ww * s, wx * s, wy * s, wz * s},
                       {wx * s, xx * s, xy * s, xz * s},
                       {wy * s, xy * s, yy * s, yz * s},
                       {wz * s, xz * s, yz * s, zz * s}};
    return {detail::symmetric_eigen(k), valid};
}

// solve_mean_of over an array of rotations.
template <bool checked, class T, class Weight>
[[nodiscard]] constexpr mean_solution<T> solve_mean(const quaternion<T>* rotations,
                                                    std::size_t count, Weight weight) noexcept {
    return solve_mean_of<checked, T>(
        [rotations](std::size_t i) -> const quaternion<T>& { return rotations[i]; }, count, weight);
}

template <class T>
[[nodiscard]] constexpr quaternion<T> mean_of(const mean_solution<T>& solution) noexcept {
    const T nan = detail::quiet_nan<T>();
    if (!solution.valid) return {nan, nan, nan, nan};
    const quaternion<T>& q = solution.eigen.vectors[0];
    return normalize(q.w < T(0) ? -q : q);
}

// The mean, or nothing when solve_mean found the input invalid or the top two eigenvalues of the
// normalized K lie within sqrt(epsilon) of each other (NaN fails the comparison too).
template <class T>
[[nodiscard]] constexpr std::optional<quaternion<T>> unique_mean_of(
    const mean_solution<T>& solution) noexcept {
    const T gap = solution.eigen.values[0] - solution.eigen.values[1];
    if (!solution.valid || !(gap > detail::sqrt(detail::epsilon<T>()))) return std::nullopt;
    return mean_of(solution);
}

}  // namespace detail

/// The chordal L2 mean of unit quaternions (a contiguous container of quaternion<T> with data() and
/// size(), or a C array): the rotation M minimizing the sum of |M - R_i|^2 over the rotation
/// matrices, as scipy's Rotation.mean. Insensitive to the signs of the inputs; the result has
/// w >= 0. Where the mean is not unique (try_mean reports it), one of the minimizers. NaN for an
/// empty container or a NaN or infinite component. Precondition: unit quaternions (QUAT_ASSERT);
/// unchecked, longer ones count more.
template <class Rotations, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr quaternion<T> mean(const Rotations& rotations) noexcept {
    return detail::mean_of(detail::solve_mean<false>(
        detail::data_of(rotations), detail::size_of(rotations), [](std::size_t) { return T(1); }));
}

/// The weighted chordal L2 mean: M minimizing the sum of weights[i] |M - R_i|^2. weights is a
/// container of scalars convertible to T (any finite size, subnormal to max(): only their ratios
/// count), as long as rotations (QUAT_ASSERT); a zero weight drops that rotation. Precondition:
/// weights >= 0 (QUAT_ASSERT); the result is NaN when no weight is positive, a weight is negative,
/// NaN or infinite, or the two containers differ in size.
template <class Rotations, class Weights, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr quaternion<T> mean(const Rotations& rotations,
                                           const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(rotations, weights),
                "quat::mean: weights and rotations differ in size");
    if (!detail::same_size(rotations, weights)) return detail::mean_of(detail::mean_solution<T>{});
    const auto* w = detail::data_of(weights);
    return detail::mean_of(
        detail::solve_mean<false>(detail::data_of(rotations), detail::size_of(rotations),
                                  [w](std::size_t i) { return static_cast<T>(w[i]); }));
}

/// mean(rotations), or std::nullopt for any input it does not average uniquely: an empty
/// container, a NaN or infinite component, a rotation that is not a unit quaternion (|q|^2 not
/// within 1/4096 of 1, as the debug check of mean), or a mean that is not unique: the two largest
/// eigenvalues of sum q_i q_i^T differ by at most sqrt(epsilon) times the number of rotations (two
/// rotations half a turn apart, for one). Never asserts.
template <class Rotations, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_mean(const Rotations& rotations) noexcept {
    return detail::unique_mean_of(detail::solve_mean<true>(
        detail::data_of(rotations), detail::size_of(rotations), [](std::size_t) { return T(1); }));
}

/// mean(rotations, weights), or std::nullopt as try_mean(rotations) and also when weights and
/// rotations differ in size, no weight is positive, a weight is negative, NaN or infinite, or the
/// mean is not unique: the two largest eigenvalues of sum w_i q_i q_i^T differ by at most
/// sqrt(epsilon) times the sum of the weights. Never asserts.
template <class Rotations, class Weights, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_mean(const Rotations& rotations,
                                                              const Weights& weights) noexcept {
    if (!detail::same_size(rotations, weights)) return std::nullopt;
    const auto* w = detail::data_of(weights);
    return detail::unique_mean_of(
        detail::solve_mean<true>(detail::data_of(rotations), detail::size_of(rotations),
                                 [w](std::size_t i) { return static_cast<T>(w[i]); }));
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_FITTING_MEAN_HPP_INCLUDED
