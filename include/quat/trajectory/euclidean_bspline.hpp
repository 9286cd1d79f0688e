// Cumulative B-splines in R^3 with uniform knots: a smooth point path (the position half of
// split_bspline), its velocity, acceleration and jerk, and their (scalar) Jacobians with respect to
// the control points.
#ifndef QUAT_TRAJECTORY_EUCLIDEAN_BSPLINE_HPP_INCLUDED
#define QUAT_TRAJECTORY_EUCLIDEAN_BSPLINE_HPP_INCLUDED

#include <array>
#include <cstddef>
#include <optional>

#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../vec3.hpp"
#include "detail/spline_view.hpp"
#include "detail/uniform_basis.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// A point of the path and its time derivatives at one time, and which K control points it depends
/// on: points first .. first + K - 1 (Jacobian weight m is point first + m).
template <class T>
struct euclidean_bspline_sample {
    std::size_t first;     ///< the first control point of the segment
    vec3<T> position;      ///< p(t)
    vec3<T> velocity;      ///< p'(t)
    vec3<T> acceleration;  ///< p''(t)
    vec3<T> jerk;          ///< p'''(t); for K = 4 it jumps at knots
};

/// The uniform B-spline of order K (degree K - 1) in R^3, in cumulative form (the same curve as the
/// plain form): on [t0 + i dt, t0 + (i + 1) dt], u = (t - t0) / dt - i,
///     p(t) = p_i + b~_1(u) (p_(i+1) - p_i) + ... + b~_(K-1)(u) (p_(i+K-1) - p_(i+K-2)).
/// Uniform knots only; the domain, the NaN sample (first = 0) and the view are those of
/// so3_bspline: `count` points that the caller keeps alive, t in [t0, t0 + (count - K + 1) dt].
/// Evaluation allocates nothing.
template <class T, std::size_t K>
class euclidean_bspline {
    static_assert(K >= 2 && K <= 8, "quat::euclidean_bspline: order K in [2, 8]");

public:
    /// K weights: the Jacobian of an output with respect to point first + m is weight m times the
    /// 3x3 identity (the path is linear in its points).
    using jacobian_weights = std::array<T, K>;

    /// The view of `count` control points at `points`, knots t0 + m dt.
    constexpr euclidean_bspline(const vec3<T>* points, std::size_t count, T t0, T dt) noexcept
        : view_{points, count, t0, dt} {}
    /// The view of a container of points (data() and size(), or a C array), which must outlive it.
    template <class Points>
    constexpr euclidean_bspline(const Points& points, T t0, T dt) noexcept
        : euclidean_bspline(detail::data_of(points), detail::size_of(points), t0, dt) {}
    template <class Points>
    euclidean_bspline(const Points&& points, T t0, T dt) = delete;  ///< no view of a temporary

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
    [[nodiscard]] constexpr const vec3<T>* points() const noexcept { return view_.points; }

    /// p(t) alone: NaN outside the domain.
    [[nodiscard]] constexpr vec3<T> operator()(T t) const noexcept { return evaluate(t).position; }

    /// p(t) and its first three time derivatives; each weights pointer that is not null receives
    /// the K weights of that output (see jacobian_weights). The NaN sample, and NaN weights,
    /// outside the domain.
    [[nodiscard]] constexpr euclidean_bspline_sample<T> evaluate(
        T t, jacobian_weights* J_p_points = nullptr, jacobian_weights* J_v_points = nullptr,
        jacobian_weights* J_a_points = nullptr,
        jacobian_weights* J_j_points = nullptr) const noexcept {
        jacobian_weights* J[4] = {J_p_points, J_v_points, J_a_points, J_j_points};
        const detail::knot_position<T> at = view_.template locate<K>(t);
        if (!at.valid) {
            for (jacobian_weights* weights : J)
                if (weights != nullptr) detail::fill_nan(*weights);
            const T nan = detail::quiet_nan<T>();
            const vec3<T> v{nan, nan, nan};
            return {0, v, v, v, v};
        }
        const detail::cumulative_weights<T, K> w =
            detail::cumulative_weights_at<T, K>(at.u, view_.dt);
        const vec3<T>* p = view_.points + at.segment;
        vec3<T> out[4] = {p[0], {T(0), T(0), T(0)}, {T(0), T(0), T(0)}, {T(0), T(0), T(0)}};
        for (std::size_t j = 1; j < K; ++j) {
            const vec3<T> step = p[j] - p[j - 1];
            for (std::size_t d = 0; d < 4; ++d) out[d] = out[d] + step * w.b[d][j];
        }
        // d p / d p_m = b~_m - b~_(m+1) (b~_0 = 1 and b~_K = 0; for derivatives b~_0' = 0).
        for (std::size_t d = 0; d < 4; ++d) {
            if (J[d] == nullptr) continue;
            for (std::size_t m = 0; m < K; ++m)
                (*J[d])[m] = m + 1 < K ? w.b[d][m] - w.b[d][m + 1] : w.b[d][m];
        }
        return {at.segment, out[0], out[1], out[2], out[3]};
    }

    /// evaluate(t, ...), or std::nullopt outside the domain, when one of the segment's K points is
    /// not finite, or when an output or a requested weight overflows; never asserts. The weights
    /// are written only with a value.
    [[nodiscard]] constexpr std::optional<euclidean_bspline_sample<T>> try_evaluate(
        T t, jacobian_weights* J_p_points = nullptr, jacobian_weights* J_v_points = nullptr,
        jacobian_weights* J_a_points = nullptr,
        jacobian_weights* J_j_points = nullptr) const noexcept {
        const detail::knot_position<T> at = view_.template locate<K>(t);
        if (!at.valid || !view_.template usable_points<K>(at.segment)) return std::nullopt;
        return detail::finite_or_empty<euclidean_bspline_sample<T>>(
            [&](auto*... J) { return evaluate(t, J...); },
            [](const euclidean_bspline_sample<T>& s) {
                return detail::is_finite(s.position) && detail::is_finite(s.velocity) &&
                       detail::is_finite(s.acceleration) && detail::is_finite(s.jerk);
            },
            J_p_points, J_v_points, J_a_points, J_j_points);
    }

private:
    detail::spline_view<T, vec3<T>> view_;
};

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_EUCLIDEAN_BSPLINE_HPP_INCLUDED
