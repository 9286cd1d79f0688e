// Geodesic means on the groups: the Karcher mean of rotations (the rotation minimizing the sum of
// squared angles to the inputs) beside the chordal mean of fitting/mean.hpp, and its counterpart
// for rigid motions, the bi-invariant mean. Both iterate on the logarithm map.
#ifndef QUAT_LIE_GEODESIC_MEAN_HPP_INCLUDED
#define QUAT_LIE_GEODESIC_MEAN_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../detail/summation.hpp"
#include "../fitting/mean.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../vec3.hpp"
#include "se3.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

// Where the Karcher iteration stopped: the mean, whether its last step was below the tolerance, and
// the largest angle (rotations) from the mean to an input of positive weight.
template <class Group, class T>
struct karcher_outcome {
    Group mean;
    bool converged;
    T spread;
};

inline constexpr int karcher_iteration_limit = 100;

// The Karcher iteration mean <- mean exp(delta), delta = sum w_i log(mean^-1 x_i) / sum w_i (the
// gradient step of sum w_i |log(mean^-1 x_i)|^2 with unit step: H. Karcher, "Riemannian center of
// mass and mollifier smoothing", Comm. Pure Appl. Math. 30, 1977; R. Hartley, J. Trumpf, Y. Dai,
// H. Li, "Rotation averaging", IJCV 103, 2013, Algorithm 1). `step(mean)` returns delta and its
// rotation angle |omega|; `move(mean, delta)` is mean exp(delta). Stops when |omega| <= 8 eps, or
// once |omega| is below sqrt(eps) and no longer halves per step (rounding in the sum has the last
// word: the step no longer shrinks, so the mean no longer moves), or after 100 steps (converged is
// then false). Within a ball of radius pi/2 the iteration converges (Hartley et al., Theorem 4.3,
// after Manton 2004), at a rate that improves as the inputs cluster.
template <class T, class Group, class Step, class Move>
[[nodiscard]] constexpr karcher_outcome<Group, T> karcher_iterate(Group mean, Step step,
                                                                  Move move) noexcept {
    const T tolerance = T(8) * epsilon<T>();
    T previous = largest<T>();
    for (int k = 0; k < karcher_iteration_limit; ++k) {
        const auto [delta, angle] = step(mean);
        if (!(angle == angle)) return {move(mean, delta), false, angle};
        if (angle <= tolerance) return {move(mean, delta), true, T(0)};
        if (angle < sqrt(epsilon<T>()) && !(angle < previous * T(0.5)))
            return {move(mean, delta), true, T(0)};
        mean = move(mean, delta);
        previous = angle;
    }
    return {mean, false, T(0)};
}

template <class T>
struct rotation_step {
    vec3<T> delta;
    T angle;
};

// The weighted mean of log(mean^-1 q_i), summed in blocks (see summation_block) so that a million
// float rotations keep their digits; NaN for no rotations or a non-positive total weight.
template <class T, class Weight>
[[nodiscard]] constexpr rotation_step<T> mean_rotation_vector(const quaternion<T>& mean,
                                                              const quaternion<T>* rotations,
                                                              std::size_t count,
                                                              Weight weight) noexcept {
    const quaternion<T> back = conjugate(mean);
    const weighted_sum<vec3<T>, T> s = blocked_weighted_sum<T>(
        count, vec3<T>{T(0), T(0), T(0)},
        [&](std::size_t i) { return to_rotation_vector(back * rotations[i]); }, weight);
    const vec3<T> delta = s.total > T(0) ? s.sum / s.total : s.sum * quiet_nan<T>();
    return {delta, norm(delta)};
}

// The largest angle from mean to rotation(i), over the i of positive weight.
template <class T, class Rotation, class Weight>
[[nodiscard]] constexpr T rotation_spread(const quaternion<T>& mean, Rotation rotation,
                                          std::size_t count, Weight weight) noexcept {
    T spread = T(0);
    for (std::size_t i = 0; i < count; ++i)
        if (weight(i) > T(0))
            spread = max(spread, norm(to_rotation_vector(conjugate(mean) * rotation(i))));
    return spread;
}

// The Karcher mean from the chordal mean (a close start: the two agree to second order in the
// spread), with the spread of the inputs about it.
// `checked` false asserts the preconditions; either way a broken one gives a NaN start (solve_mean
// reports it), which the iteration carries to its end.
template <bool checked, class T, class Weight>
[[nodiscard]] constexpr karcher_outcome<quaternion<T>, T> solve_geodesic_mean(
    const quaternion<T>* rotations, std::size_t count, Weight weight) noexcept {
    if constexpr (!checked) {
        for (std::size_t i = 0; i < count; ++i) {
            QUAT_ASSERT(is_near_unit(rotations[i]),
                        "quat::geodesic_mean: a rotation is not a unit quaternion");
            QUAT_ASSERT(!(weight(i) < T(0)), "quat::geodesic_mean: a weight is negative");
        }
    }
    const mean_solution<T> chordal = solve_mean<true>(rotations, count, weight);
    const quaternion<T> start = mean_of(chordal);
    karcher_outcome<quaternion<T>, T> outcome = karcher_iterate<T>(
        start,
        [&](const quaternion<T>& mean) {
            return mean_rotation_vector(mean, rotations, count, weight);
        },
        [](const quaternion<T>& mean, const vec3<T>& delta) {
            const quaternion<T> moved = normalize(mean * from_rotation_vector(delta));
            return moved.w < T(0) ? -moved : moved;
        });
    outcome.converged = outcome.converged && chordal.valid;
    outcome.spread = rotation_spread(
        outcome.mean, [rotations](std::size_t i) { return rotations[i]; }, count, weight);
    return outcome;
}

// The mean if the iteration converged and every input of positive weight lies within pi/2 of it,
// where the Karcher mean is unique (Hartley et al., Theorem 4.3).
template <class Group, class T>
[[nodiscard]] constexpr std::optional<Group> unique_karcher_mean(
    const karcher_outcome<Group, T>& outcome) noexcept {
    if (!outcome.converged || !(outcome.spread < pi<T>() / T(2))) return std::nullopt;
    return outcome.mean;
}

// The step of the bi-invariant mean of rigid motions, the weighted mean of log(mean^-1 X_i) with
// its size max(|omega|, |rho| / length) for the criterion: the translation in units of the largest
// translation, so that the test does not depend on the unit of length.
template <class T>
struct rigid_step {
    se3::twist<T> delta;
    T angle;
};

template <class T, class Weight>
[[nodiscard]] constexpr rigid_step<T> mean_twist(const dual_quaternion<T>& mean,
                                                 const dual_quaternion<T>* motions,
                                                 std::size_t count, Weight weight,
                                                 T length) noexcept {
    const dual_quaternion<T> back = se3::inverse(mean);
    const vec3<T> zero{T(0), T(0), T(0)};
    const weighted_sum<se3::twist<T>, T> s = blocked_weighted_sum<T>(
        count, se3::twist<T>{zero, zero},
        [&](std::size_t i) { return se3::log(back * motions[i]); }, weight);
    const se3::twist<T> delta = s.sum * (s.total > T(0) ? T(1) / s.total : quiet_nan<T>());
    return {delta, max(norm(delta.angular), norm(delta.linear) / length)};
}

// The bi-invariant mean from the chordal mean of the rotations and the weighted mean of the
// translations; the spread is the rotations' about it.
template <bool checked, class T, class Weight>
[[nodiscard]] constexpr karcher_outcome<dual_quaternion<T>, T> solve_rigid_geodesic_mean(
    const dual_quaternion<T>* motions, std::size_t count, Weight weight) noexcept {
    if constexpr (!checked) {
        for (std::size_t i = 0; i < count; ++i) {
            QUAT_ASSERT(is_near_unit(motions[i].real),
                        "quat::geodesic_mean: a motion is not a unit dual quaternion");
            QUAT_ASSERT(!(weight(i) < T(0)), "quat::geodesic_mean: a weight is negative");
        }
    }
    const mean_solution<T> chordal = solve_mean_of<true, T>(
        [motions](std::size_t i) -> const quaternion<T>& { return motions[i].real; }, count,
        weight);
    vec3<T> centroid{T(0), T(0), T(0)};
    T total = T(0);
    for (std::size_t i = 0; i < count; ++i) {
        centroid = centroid + translation_of(motions[i]) * weight(i);
        total = total + weight(i);
    }
    centroid = centroid / (total > T(0) ? total : T(1));
    // The unit for the step's linear part: the largest translation, the scale of its rounding.
    T length = T(0);
    for (std::size_t i = 0; i < count; ++i)
        if (weight(i) > T(0)) length = max(length, norm(translation_of(motions[i])));
    if (!(length > T(0))) length = T(1);
    const dual_quaternion<T> start = to_dual_quaternion(mean_of(chordal), centroid);
    karcher_outcome<dual_quaternion<T>, T> outcome = karcher_iterate<T>(
        start,
        [&](const dual_quaternion<T>& mean) {
            return mean_twist(mean, motions, count, weight, length);
        },
        [](const dual_quaternion<T>& mean, const se3::twist<T>& delta) {
            const dual_quaternion<T> moved = normalize(mean * se3::exp(delta));
            return moved.real.w < T(0) ? -moved : moved;
        });
    outcome.converged = outcome.converged && chordal.valid;
    // A NaN or infinite translation leaves the rotations' mean finite; a finite rotation beside a
    // NaN translation would pass for half a result, so the whole mean is NaN, as documented.
    if (!is_finite(outcome.mean.real) || !is_finite(outcome.mean.dual)) {
        outcome.mean = {nan_quaternion<T>(), nan_quaternion<T>()};
        outcome.converged = false;
    }
    outcome.spread = rotation_spread(
        outcome.mean.real, [motions](std::size_t i) { return motions[i].real; }, count, weight);
    return outcome;
}

}  // namespace detail

/// The geodesic (Karcher, L2 intrinsic) mean of unit quaternions (a contiguous container with
/// data() and size(), or a C array): the rotation M minimizing the sum of squared rotation angles
/// |log(M^-1 R_i)|^2, by the Karcher iteration M <- M exp(mean of log(M^-1 R_i)) from the chordal
/// mean. It stops when the step's angle is below 8 eps or stops halving below sqrt(eps) (rounding),
/// or after 100 steps. Insensitive to the inputs' signs; the result has w >= 0. The minimizer is
/// unique when the rotations lie within a ball of radius pi/2 (90 degrees of rotation); when they
/// spread wider (over more than a hemisphere of directions, say) it may not be, and the result is
/// where the iteration stopped: a local minimum or a saddle, try_geodesic_mean says so. NaN for an
/// empty container or a NaN or infinite component. Precondition: unit quaternions (QUAT_ASSERT).
template <class Rotations, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr quaternion<T> geodesic_mean(const Rotations& rotations) noexcept {
    return detail::solve_geodesic_mean<false>(detail::data_of(rotations),
                                              detail::size_of(rotations),
                                              [](std::size_t) { return T(1); })
        .mean;
}

/// The weighted geodesic mean: M minimizing the sum of weights[i] |log(M^-1 R_i)|^2, as
/// geodesic_mean(rotations). weights: scalars convertible to T, as many as rotations (QUAT_ASSERT;
/// unchecked, other lengths give NaN); a zero weight drops that rotation. Precondition: weights >=
/// 0 (QUAT_ASSERT); NaN when no weight is positive or a weight is negative, NaN or infinite.
template <class Rotations, class Weights, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr quaternion<T> geodesic_mean(const Rotations& rotations,
                                                    const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(rotations, weights),
                "quat::geodesic_mean: weights and rotations differ in size");
    const auto* w = detail::data_of(weights);
    // Unpaired containers are averaged as an empty one: NaN, nothing read.
    return detail::solve_geodesic_mean<false>(
               detail::data_of(rotations),
               detail::same_size(rotations, weights) ? detail::size_of(rotations) : 0,
               [w](std::size_t i) { return static_cast<T>(w[i]); })
        .mean;
}

/// geodesic_mean(rotations), or std::nullopt when it is not the unique mean: an empty container, a
/// NaN or infinite component, a rotation that is not a unit quaternion (|q|^2 not within 1/4096
/// of 1), an iteration that did not converge, or a rotation pi/2 or more from the mean (outside the
/// ball where the mean is known to be unique). Never asserts.
template <class Rotations, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_geodesic_mean(
    const Rotations& rotations) noexcept {
    return detail::unique_karcher_mean(detail::solve_geodesic_mean<true>(
        detail::data_of(rotations), detail::size_of(rotations), [](std::size_t) { return T(1); }));
}

/// geodesic_mean(rotations, weights), or std::nullopt as try_geodesic_mean(rotations) and also
/// when weights and rotations differ in size, no weight is positive, or a weight is negative, NaN
/// or infinite. Never asserts.
template <class Rotations, class Weights, class T = detail::element_scalar_t<quaternion, Rotations>>
[[nodiscard]] constexpr std::optional<quaternion<T>> try_geodesic_mean(
    const Rotations& rotations, const Weights& weights) noexcept {
    if (!detail::same_size(rotations, weights)) return std::nullopt;
    const auto* w = detail::data_of(weights);
    return detail::unique_karcher_mean(
        detail::solve_geodesic_mean<true>(detail::data_of(rotations), detail::size_of(rotations),
                                          [w](std::size_t i) { return static_cast<T>(w[i]); }));
}
/// The bi-invariant mean of unit dual quaternions (rigid motions; a contiguous container with
/// data() and size(), or a C array): the motion M with sum log(M^-1 X_i) = 0 (the exponential
/// barycenter of SE(3): V. Arsigny, X. Pennec, N. Ayache, "Bi-invariant means in Lie groups",
/// 2006; Sophus's average). The same for g X_i and X_i g as for X_i; its rotation is the
/// geodesic_mean of the rotations. Iterates M <- M exp(mean of log(M^-1 X_i)) from the chordal mean
/// rotation and the mean translation, stopping as the rotations' iteration does, the step measured
/// as max(|omega|, |rho| / largest |translation|). Unique where the rotations lie within
/// pi/2 of the mean (try_geodesic_mean checks it); otherwise where the iteration stopped. The
/// result has real.w >= 0. NaN for an empty container or a NaN or infinite component.
/// Precondition: unit dual quaternions (QUAT_ASSERT on the real parts).
template <class Motions, class T = detail::element_scalar_t<dual_quaternion, Motions>>
[[nodiscard]] constexpr dual_quaternion<T> geodesic_mean(const Motions& motions) noexcept {
    return detail::solve_rigid_geodesic_mean<false>(
               detail::data_of(motions), detail::size_of(motions), [](std::size_t) { return T(1); })
        .mean;
}

/// The weighted bi-invariant mean: sum weights[i] log(M^-1 X_i) = 0, as geodesic_mean(motions).
/// weights: scalars convertible to T, as many as motions (QUAT_ASSERT; unchecked, other lengths
/// give NaN), >= 0 (QUAT_ASSERT); NaN when no weight is positive or a weight is negative, NaN or
/// infinite.
template <class Motions, class Weights,
          class T = detail::element_scalar_t<dual_quaternion, Motions>>
[[nodiscard]] constexpr dual_quaternion<T> geodesic_mean(const Motions& motions,
                                                         const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(motions, weights),
                "quat::geodesic_mean: weights and motions differ in size");
    const auto* w = detail::data_of(weights);
    return detail::solve_rigid_geodesic_mean<false>(
               detail::data_of(motions),
               detail::same_size(motions, weights) ? detail::size_of(motions) : 0,
               [w](std::size_t i) { return static_cast<T>(w[i]); })
        .mean;
}

/// geodesic_mean(motions), or std::nullopt as try_geodesic_mean of rotations: empty, NaN or
/// infinite, not unit (|real|^2 not within 1/4096 of 1), not converged, or a rotation pi/2 or more
/// from the mean's. Never asserts.
template <class Motions, class T = detail::element_scalar_t<dual_quaternion, Motions>>
[[nodiscard]] constexpr std::optional<dual_quaternion<T>> try_geodesic_mean(
    const Motions& motions) noexcept {
    return detail::unique_karcher_mean(detail::solve_rigid_geodesic_mean<true>(
        detail::data_of(motions), detail::size_of(motions), [](std::size_t) { return T(1); }));
}

/// geodesic_mean(motions, weights), or std::nullopt as try_geodesic_mean(motions) and also when the
/// sizes differ or a weight is negative, NaN or infinite, or none is positive. Never asserts.
template <class Motions, class Weights,
          class T = detail::element_scalar_t<dual_quaternion, Motions>>
[[nodiscard]] constexpr std::optional<dual_quaternion<T>> try_geodesic_mean(
    const Motions& motions, const Weights& weights) noexcept {
    if (!detail::same_size(motions, weights)) return std::nullopt;
    const auto* w = detail::data_of(weights);
    return detail::unique_karcher_mean(detail::solve_rigid_geodesic_mean<true>(
        detail::data_of(motions), detail::size_of(motions),
        [w](std::size_t i) { return static_cast<T>(w[i]); }));
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_LIE_GEODESIC_MEAN_HPP_INCLUDED
