// Cumulative B-splines on SO(3) x R^3 with uniform knots: a pose whose rotation is an so3_bspline
// and whose position is a euclidean_bspline of the same order and knots (the split form of a rigid
// trajectory; unlike se3_bspline, the position's path does not depend on the rotations).
#ifndef QUAT_TRAJECTORY_SPLIT_BSPLINE_HPP_INCLUDED
#define QUAT_TRAJECTORY_SPLIT_BSPLINE_HPP_INCLUDED

#include <array>
#include <cstddef>
#include <optional>

#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../lie/se3.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "euclidean_bspline.hpp"
#include "so3_bspline.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// A pose and its derivatives at one time, and which K control points it depends on: rotations
/// and positions first .. first + K - 1.
template <class T>
struct split_bspline_sample {
    std::size_t first;                ///< the first control point of the segment
    quaternion<T> rotation;           ///< R(t)
    vec3<T> position;                 ///< p(t), world frame
    vec3<T> angular_velocity;         ///< omega, body frame (as so3_bspline)
    vec3<T> angular_acceleration;     ///< omega', body frame
    vec3<T> angular_jerk;             ///< omega'', body frame; for K = 4 it jumps at knots
    vec3<T> linear_velocity;          ///< p', world frame
    vec3<T> linear_acceleration;      ///< p'', world frame
    vec3<T> linear_jerk;              ///< p''', world frame; for K = 4 it jumps at knots
    se3::twist<T> body_velocity;      ///< the pose's body twist (R^T p', omega)
    se3::twist<T> body_acceleration;  ///< its derivative (R^T p'' - omega x R^T p', omega')
};

/// The pose (R(t), p(t)) of an so3_bspline<T, K> over `rotations` and a euclidean_bspline<T, K>
/// over `positions`, with the same t0 and dt: a non-owning view of two arrays of `count` elements.
/// Domain and NaN rules as so3_bspline's; containers of different sizes make a view that is not
/// valid (the NaN sample everywhere). Evaluation allocates nothing.
template <class T, std::size_t K>
class split_bspline {
public:
    /// K 3x3 blocks of a rotation output's Jacobian, block m for rotation first + m (so3_bspline).
    using jacobian_blocks = std::array<matrix3<T>, K>;
    /// K weights of a position output's Jacobian, weight m times I for position first + m.
    using jacobian_weights = std::array<T, K>;

    /// The view of `count` rotations and `count` positions, knots t0 + m dt.
    constexpr split_bspline(const quaternion<T>* rotations, const vec3<T>* positions,
                            std::size_t count, T t0, T dt) noexcept
        : rotation_(rotations, count, t0, dt), position_(positions, count, t0, dt) {}
    /// The view of two containers (data() and size(), or C arrays), which must outlive it.
    template <class Rotations, class Positions>
    constexpr split_bspline(const Rotations& rotations, const Positions& positions, T t0,
                            T dt) noexcept
        : rotation_(detail::data_of(rotations), detail::size_of(rotations), t0, dt),
          position_(detail::data_of(positions), detail::size_of(positions), t0, dt) {}
    template <class Rotations, class Positions>
    split_bspline(const Rotations&&, const Positions&, T, T) = delete;  ///< no temporaries
    template <class Rotations, class Positions>
    split_bspline(const Rotations&, const Positions&&, T, T) = delete;  ///< no temporaries

    /// True when both halves are valid and have the same number of points.
    [[nodiscard]] constexpr bool valid() const noexcept {
        return rotation_.valid() && position_.valid() && rotation_.size() == position_.size();
    }
    /// t0, the start of the range of evaluation.
    [[nodiscard]] constexpr T start_time() const noexcept { return rotation_.start_time(); }
    /// t0 + (count - K + 1) dt, the end of the range; NaN when not valid().
    [[nodiscard]] constexpr T end_time() const noexcept {
        return valid() ? rotation_.end_time() : detail::quiet_nan<T>();
    }
    /// The segment that holds t (its first control point, and t's offset into it), the numbers
    /// the residuals of interop/ceres_trajectory.hpp take; std::nullopt outside the domain or when
    /// not valid(). The control points are not read.
    [[nodiscard]] constexpr std::optional<bspline_segment<T>> segment_at(T t) const noexcept {
        if (!valid()) return std::nullopt;
        return rotation_.segment_at(t);
    }
    /// dt, the knot spacing.
    [[nodiscard]] constexpr T knot_spacing() const noexcept { return rotation_.knot_spacing(); }
    /// The number of control points (of the rotations; not valid() when the positions differ).
    [[nodiscard]] constexpr std::size_t size() const noexcept { return rotation_.size(); }
    /// The rotation half, an so3_bspline view.
    [[nodiscard]] constexpr const so3_bspline<T, K>& rotation_spline() const noexcept {
        return rotation_;
    }
    /// The position half, a euclidean_bspline view.
    [[nodiscard]] constexpr const euclidean_bspline<T, K>& position_spline() const noexcept {
        return position_;
    }

    /// (R(t), p(t)) as a unit dual quaternion: the rotation, then the translation. NaN outside
    /// the domain.
    [[nodiscard]] constexpr dual_quaternion<T> operator()(T t) const noexcept {
        if (!valid()) return {detail::nan_quaternion<T>(), detail::nan_quaternion<T>()};
        return to_dual_quaternion(rotation_(t), position_(t));
    }

    /// The pose and its derivatives; the rotation Jacobians are so3_bspline's (right convention),
    /// the position ones euclidean_bspline's weights. The NaN sample, and NaN in every requested
    /// Jacobian, outside the domain. Precondition: unit rotations.
    [[nodiscard]] constexpr split_bspline_sample<T> evaluate(
        T t, jacobian_blocks* J_q_rotations = nullptr, jacobian_blocks* J_w_rotations = nullptr,
        jacobian_blocks* J_a_rotations = nullptr, jacobian_blocks* J_j_rotations = nullptr,
        jacobian_weights* J_p_positions = nullptr, jacobian_weights* J_v_positions = nullptr,
        jacobian_weights* J_dv_positions = nullptr,
        jacobian_weights* J_ddv_positions = nullptr) const noexcept {
        // An invalid view evaluates both halves at NaN: NaN everywhere, as documented.
        const T time = valid() ? t : detail::quiet_nan<T>();
        const so3_bspline_sample<T> r =
            rotation_.evaluate(time, J_q_rotations, J_w_rotations, J_a_rotations, J_j_rotations);
        const euclidean_bspline_sample<T> p =
            position_.evaluate(time, J_p_positions, J_v_positions, J_dv_positions, J_ddv_positions);
        const quaternion<T> inverse = conjugate(r.rotation);
        const vec3<T> body_linear = rotate(inverse, p.velocity);
        const vec3<T> body_linear_rate =
            rotate(inverse, p.acceleration) - cross(r.angular_velocity, body_linear);
        return {r.first,
                r.rotation,
                p.position,
                r.angular_velocity,
                r.angular_acceleration,
                r.angular_jerk,
                p.velocity,
                p.acceleration,
                p.jerk,
                {body_linear, r.angular_velocity},
                {body_linear_rate, r.angular_acceleration}};
    }

    /// evaluate(t, ...), or std::nullopt when the view is not valid, t is outside the domain, or one
    /// of the segment's rotations or positions is not finite or a rotation is not a unit quaternion
    /// (as so3_bspline::try_evaluate), or when an output or a requested Jacobian overflows; never
    /// asserts. The Jacobians are written only with a value.
    [[nodiscard]] constexpr std::optional<split_bspline_sample<T>> try_evaluate(
        T t, jacobian_blocks* J_q_rotations = nullptr, jacobian_blocks* J_w_rotations = nullptr,
        jacobian_blocks* J_a_rotations = nullptr, jacobian_blocks* J_j_rotations = nullptr,
        jacobian_weights* J_p_positions = nullptr, jacobian_weights* J_v_positions = nullptr,
        jacobian_weights* J_dv_positions = nullptr,
        jacobian_weights* J_ddv_positions = nullptr) const noexcept {
        if (!valid() || !rotation_.try_evaluate(t).has_value() ||
            !position_.try_evaluate(t).has_value())
            return std::nullopt;
        return detail::finite_or_empty<split_bspline_sample<T>>(
            [&](auto*... J) { return evaluate(t, J...); },
            [](const split_bspline_sample<T>& s) {
                const auto finite = [](const se3::twist<T>& x) {
                    return detail::is_finite(x.linear) && detail::is_finite(x.angular);
                };
                return detail::is_finite(s.rotation) && detail::is_finite(s.position) &&
                       detail::is_finite(s.angular_velocity) &&
                       detail::is_finite(s.angular_acceleration) &&
                       detail::is_finite(s.angular_jerk) && detail::is_finite(s.linear_velocity) &&
                       detail::is_finite(s.linear_acceleration) &&
                       detail::is_finite(s.linear_jerk) && finite(s.body_velocity) &&
                       finite(s.body_acceleration);
            },
            J_q_rotations, J_w_rotations, J_a_rotations, J_j_rotations, J_p_positions,
            J_v_positions, J_dv_positions, J_ddv_positions);
    }

private:
    so3_bspline<T, K> rotation_;
    euclidean_bspline<T, K> position_;
};

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_SPLIT_BSPLINE_HPP_INCLUDED
