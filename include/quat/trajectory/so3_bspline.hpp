// Cumulative B-splines on SO(3) with uniform knots: a smooth rotation through (near) control
// rotations, with its body-frame angular velocity, acceleration and jerk, and their analytic
// Jacobians with respect to the control points, in O(K) per evaluation (C. Sommer, V. Usenko,
// D. Schubert, N. Demmel, D. Cremers, "Efficient Derivative Computation for Cumulative B-Splines on
// Lie Groups", CVPR 2020; trajectory/detail/lie_bspline.hpp derives the recurrences).
#ifndef QUAT_TRAJECTORY_SO3_BSPLINE_HPP_INCLUDED
#define QUAT_TRAJECTORY_SO3_BSPLINE_HPP_INCLUDED

#include <array>
#include <cstddef>
#include <initializer_list>
#include <optional>

#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "detail/lie_bspline.hpp"
#include "detail/spline_view.hpp"
#include "detail/uniform_basis.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// A rotation and the derivatives of its body-frame angular velocity at one time, and which K
/// control points it depends on: points first .. first + K - 1 (Jacobian block m is point first + m).
template <class T>
struct so3_bspline_sample {
    std::size_t first;             ///< the first control point of the segment
    quaternion<T> rotation;        ///< R(t), a unit quaternion
    vec3<T> angular_velocity;      ///< omega = (R^T R')^v, body frame, radians per unit of time
    vec3<T> angular_acceleration;  ///< omega', body frame (the derivative of the vector above)
    vec3<T> angular_jerk;          ///< omega'', body frame; for K = 4 it jumps at knots
};

/// The cumulative B-spline of order K (degree K - 1; K = 4 is cubic) on SO(3) with uniform knots:
/// on [t0 + i dt, t0 + (i + 1) dt], with u = (t - t0) / dt - i and d_j = log(q_(i+j-1)^-1
/// q_(i+j)) (the shorter way, so q and -q are the same control point),
///     R(t) = q_i exp(b~_1(u) d_1) ... exp(b~_(K-1)(u) d_(K-1)),
/// b~_j the cumulative basis of the uniform B-spline. It is C^(K-2) in t, passes near (not
/// through) its control points, and is defined for t in [t0, t0 + (count - K + 1) dt] (the last
/// segment includes its end). Only uniform knots are supported.
///
/// A non-owning view: it keeps a pointer to the caller's `count` unit quaternions (which must
/// outlive it and may change between evaluations), t0 and dt. Every view is valid to evaluate:
/// fewer than K points, dt not positive or not finite, t0 not finite, a null pointer, or t NaN or
/// outside the range give the NaN sample (first = 0, every component and Jacobian entry NaN) from
/// evaluate and operator(), and an empty optional from try_evaluate. Evaluation allocates nothing.
template <class T, std::size_t K>
class so3_bspline {
    static_assert(K >= 2 && K <= 8, "quat::so3_bspline: order K in [2, 8]");

public:
    /// K 3x3 blocks, block m the Jacobian with respect to control point first + m.
    using jacobian_blocks = std::array<matrix3<T>, K>;

    /// The view of `count` control rotations at `points`, knots t0 + m dt.
    constexpr so3_bspline(const quaternion<T>* points, std::size_t count, T t0, T dt) noexcept
        : view_{points, count, t0, dt} {}
    /// The view of a container of quaternions (data() and size(), or a C array), which must
    /// outlive it.
    template <class Points>
    constexpr so3_bspline(const Points& points, T t0, T dt) noexcept
        : so3_bspline(detail::data_of(points), detail::size_of(points), t0, dt) {}
    template <class Points>
    so3_bspline(const Points&& points, T t0, T dt) = delete;  ///< no view of a temporary

    /// True when the view can be evaluated somewhere: count >= K, finite t0, finite dt > 0.
    [[nodiscard]] constexpr bool valid() const noexcept { return view_.template valid<K>(); }
    /// t0, the start of the range of evaluation.
    [[nodiscard]] constexpr T start_time() const noexcept { return view_.t0; }
    /// t0 + (count - K + 1) dt, the end of the range; NaN when not valid().
    [[nodiscard]] constexpr T end_time() const noexcept { return view_.template end_time<K>(); }
    /// The segment that holds t (its first control point, and t's offset into it), the numbers
    /// the residuals of interop/ceres_trajectory.hpp take; std::nullopt outside the domain (see
    /// the class comment). The control points are not read.
    [[nodiscard]] constexpr std::optional<bspline_segment<T>> segment_at(T t) const noexcept {
        return view_.template segment_at<K>(t);
    }
    /// dt, the knot spacing.
    [[nodiscard]] constexpr T knot_spacing() const noexcept { return view_.dt; }
    /// The number of control points.
    [[nodiscard]] constexpr std::size_t size() const noexcept { return view_.count; }
    /// The control points viewed.
    [[nodiscard]] constexpr const quaternion<T>* points() const noexcept { return view_.points; }

    /// R(t) alone (no derivatives): NaN outside the domain (see the class comment).
    [[nodiscard]] constexpr quaternion<T> operator()(T t) const noexcept {
        const detail::knot_position<T> at = view_.template locate<K>(t);
        if (!at.valid) return detail::nan_quaternion<T>();
        return detail::evaluate_lie_bspline<group, T, K>(
                   view_.points + at.segment, detail::cumulative_weights_at<T, K>(at.u, view_.dt),
                   0, nullptr, nullptr, nullptr, nullptr)
            .value;
    }

    /// R(t) with its body-frame angular velocity, acceleration and jerk; each Jacobian pointer that
    /// is not null receives the K blocks of that output with respect to the segment's control
    /// points, in the right convention of lie/so3.hpp (q_m <- q_m exp(delta), the rotation's change
    /// as log(R^-1 R'), the velocities' as a difference). Precondition: unit control points. The
    /// NaN sample, and NaN in every requested block, outside the domain.
    [[nodiscard]] constexpr so3_bspline_sample<T> evaluate(
        T t, jacobian_blocks* J_q_points = nullptr, jacobian_blocks* J_w_points = nullptr,
        jacobian_blocks* J_a_points = nullptr,
        jacobian_blocks* J_j_points = nullptr) const noexcept {
        const detail::knot_position<T> at = view_.template locate<K>(t);
        if (!at.valid) {
            for (jacobian_blocks* J :
                 std::array<jacobian_blocks*, 4>{J_q_points, J_w_points, J_a_points, J_j_points})
                if (J != nullptr) detail::fill_nan(*J);
            const T nan = detail::quiet_nan<T>();
            return {
                0, detail::nan_quaternion<T>(), {nan, nan, nan}, {nan, nan, nan}, {nan, nan, nan}};
        }
        const auto s = detail::evaluate_lie_bspline<group, T, K>(
            view_.points + at.segment, detail::cumulative_weights_at<T, K>(at.u, view_.dt), 3,
            J_q_points, J_w_points, J_a_points, J_j_points);
        return {at.segment, s.value, s.velocity, s.acceleration, s.jerk};
    }

    /// evaluate(t, ...), or std::nullopt outside the domain or when one of the segment's K control
    /// points is not finite or not a unit quaternion (|q|^2 within 1/4096 of 1, QUAT_ASSERT's
    /// tolerance), or when an output or a requested Jacobian overflows (a very short knot
    /// spacing); never asserts. The Jacobians are written only with a value.
    [[nodiscard]] constexpr std::optional<so3_bspline_sample<T>> try_evaluate(
        T t, jacobian_blocks* J_q_points = nullptr, jacobian_blocks* J_w_points = nullptr,
        jacobian_blocks* J_a_points = nullptr,
        jacobian_blocks* J_j_points = nullptr) const noexcept {
        const detail::knot_position<T> at = view_.template locate<K>(t);
        if (!at.valid || !view_.template usable_points<K>(at.segment)) return std::nullopt;
        return detail::finite_or_empty<so3_bspline_sample<T>>(
            [&](auto*... J) { return evaluate(t, J...); },
            [](const so3_bspline_sample<T>& s) {
                return detail::is_finite(s.rotation) && detail::is_finite(s.angular_velocity) &&
                       detail::is_finite(s.angular_acceleration) &&
                       detail::is_finite(s.angular_jerk);
            },
            J_q_points, J_w_points, J_a_points, J_j_points);
    }

private:
    using group = detail::so3_spline_group<T>;
    detail::spline_view<T, quaternion<T>> view_;
};

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_SO3_BSPLINE_HPP_INCLUDED
