// The non-owning view every uniform spline of trajectory/ holds: its control points, their count,
// the start time t0 and the knot spacing dt, with the domain checks the splines share.
#ifndef QUAT_TRAJECTORY_DETAIL_SPLINE_VIEW_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_SPLINE_VIEW_HPP_INCLUDED

#include <array>
#include <cstddef>
#include <optional>
#include <tuple>

#include "../../detail/math.hpp"
#include "../../matrix.hpp"
#include "../../quaternion.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../../vec3.hpp"
#include "../bspline_segment.hpp"
#include "uniform_basis.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// True when every component is finite and the rotation (the quaternion, a motion's real part) is
/// a unit quaternion to is_near_unit's tolerance, the one QUAT_ASSERT checks: the points
/// try_evaluate accepts.
template <class T>
[[nodiscard]] constexpr bool is_usable_point(const quaternion<T>& q) noexcept {
    return is_finite(q) && is_near_unit(q);
}
template <class T>
[[nodiscard]] constexpr bool is_usable_point(const dual_quaternion<T>& x) noexcept {
    return is_finite(x.real) && is_finite(x.dual) && is_near_unit(x.real);
}
template <class T>
[[nodiscard]] constexpr bool is_usable_point(const vec3<T>& v) noexcept {
    return is_finite(v);
}

/// Every entry of every block NaN.
template <class T, int R, int C, std::size_t N>
constexpr void fill_nan(std::array<matrix<T, R, C>, N>& blocks) noexcept {
    for (matrix<T, R, C>& m : blocks)
        for (int r = 0; r < R; ++r)
            for (int c = 0; c < C; ++c) m(r, c) = quiet_nan<T>();
}
template <class T, std::size_t N>
constexpr void fill_nan(std::array<T, N>& weights) noexcept {
    for (T& w : weights) w = quiet_nan<T>();
}

/// True when every entry of every block (or every weight) is finite.
template <class T, int R, int C, std::size_t N>
[[nodiscard]] constexpr bool all_finite(const std::array<matrix<T, R, C>, N>& blocks) noexcept {
    for (const matrix<T, R, C>& m : blocks)
        for (int r = 0; r < R; ++r)
            for (int c = 0; c < C; ++c)
                if (!is_finite(m(r, c))) return false;
    return true;
}
template <class T, std::size_t N>
[[nodiscard]] constexpr bool all_finite(const std::array<T, N>& weights) noexcept {
    for (const T& w : weights)
        if (!is_finite(w)) return false;
    return true;
}

/// try_evaluate's rule for what it returns: evaluate(J...) (a callable taking one pointer per
/// Jacobian, null where not requested) into local Jacobians; the sample, with the requested
/// Jacobians copied to the caller's, when finite_sample(sample) holds and each requested Jacobian
/// is finite, and std::nullopt, the caller's Jacobians untouched, when a value overflowed (a knot
/// spacing so short that velocities, their derivatives or their Jacobians exceed T's range).
template <class Sample, class Evaluate, class FiniteSample, class... Blocks>
[[nodiscard]] constexpr std::optional<Sample> finite_or_empty(const Evaluate& evaluate,
                                                              const FiniteSample& finite_sample,
                                                              Blocks*... requested) noexcept {
    std::tuple<Blocks...> local{};
    const Sample sample = std::apply(
        [&](Blocks&... l) { return evaluate((requested != nullptr ? &l : nullptr)...); }, local);
    const bool finite =
        finite_sample(sample) &&
        std::apply(
            [&](const Blocks&... l) { return ((requested == nullptr || all_finite(l)) && ...); },
            local);
    if (!finite) return std::nullopt;
    std::apply(
        [&](const Blocks&... l) { ((requested != nullptr ? void(*requested = l) : void()), ...); },
        local);
    return sample;
}

/// Control points, their count, t0 and dt; see spline_position for the domain.
template <class T, class Point>
struct spline_view {
    const Point* points;
    std::size_t count;
    T t0, dt;

    /// False for a null pointer. Not asked during constant evaluation, where reading a null view
    /// fails to compile anyway and where g++'s -fsanitize=null (it implies
    /// -fno-delete-null-pointer-checks) refuses to compare an object's address with null.
    [[nodiscard]] constexpr bool has_points() const noexcept {
        return constant_evaluated() || points != nullptr;
    }
    template <std::size_t K>
    [[nodiscard]] constexpr bool valid() const noexcept {
        return has_points() && count >= K && dt > T(0) && is_finite(dt) && is_finite(t0);
    }
    template <std::size_t K>
    [[nodiscard]] constexpr T end_time() const noexcept {
        if (!valid<K>()) return quiet_nan<T>();
        return t0 + T(static_cast<double>(count - K + 1)) * dt;
    }
    template <std::size_t K>
    [[nodiscard]] constexpr knot_position<T> locate(const T& t) const noexcept {
        if (!has_points()) return {0, quiet_nan<T>(), false};
        return spline_position<K>(t, t0, dt, count);
    }
    template <std::size_t K>
    [[nodiscard]] constexpr std::optional<bspline_segment<T>> segment_at(
        const T& t) const noexcept {
        const knot_position<T> at = locate<K>(t);
        if (!at.valid) return std::nullopt;
        return bspline_segment<T>{at.segment, at.u * dt};
    }
    /// True when the K points of the segment are usable (is_usable_point).
    template <std::size_t K>
    [[nodiscard]] constexpr bool usable_points(std::size_t segment) const noexcept {
        for (std::size_t m = 0; m < K; ++m)
            if (!is_usable_point(points[segment + m])) return false;
        return true;
    }
};

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_SPLINE_VIEW_HPP_INCLUDED
