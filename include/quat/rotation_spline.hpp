// A C2-continuous rotation spline through keyframes: scipy's RotationSpline, solved to convergence.
#ifndef QUAT_ROTATION_SPLINE_HPP_INCLUDED
#define QUAT_ROTATION_SPLINE_HPP_INCLUDED

#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "config.hpp"
#include "conversions.hpp"
#include "detail/block_tridiagonal.hpp"
#include "detail/containers.hpp"
#include "detail/math.hpp"
#include "detail/rotation_vector_jacobian.hpp"
#include "detail/segments.hpp"
#include "kinematics.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

namespace detail {

/// The derivative of right_jacobian_rate(r, v) with respect to v (r held fixed).
template <class T>
[[nodiscard]] constexpr matrix3<T> right_jacobian_rate_derivative(const vec3<T>& r,
                                                                  const vec3<T>& v) noexcept {
    const T n = norm(r), d = dot(r, v);
    const T k3 = n_minus_sin_over_cube(n), k4 = quartic_coefficient(n), k5 = quintic_coefficient(n);
    const vec3<T> c = cross(r, v);
    // d/dv of (r.v)(k4 r x v + k5 r x (r x v)) and of k3 v x (r x v) = k3 (r (v.v) - v (v.r)).
    return skew_polynomial(r, -k3 * d, k4 * d, k5 * d) +
           outer(c * k4 + cross(r, c) * k5 - v * k3, r) + outer(r, v) * (T(2) * k3);
}

}  // namespace detail

/// A rotation spline through keyframes with continuous angular velocity and angular acceleration
/// (C2), scipy's RotationSpline: on segment i, R(t) = R_i exp(r_i(t - t_i)) with r_i a cubic in
/// the local rotation vector, r_i(0) = 0 and r_i(t_(i+1) - t_i) = log(R_i^T R_(i+1)) (the
/// shorter way), the angular velocities at the first and last keyframes those of the first and
/// last segments' slerps, and the angular velocities at the inner keyframes solved from the
/// condition that the angular acceleration is continuous there (the notes "Smooth attitude
/// interpolation" that scipy's documentation cites, github.com/scipy/scipy/files/2932755). That
/// condition is non-linear in the velocities; scipy stops its fixed-point iteration after 10
/// steps, which on some keyframe sets leaves its spline 0.02 rad from the C2 one, while quat solves
/// it by Newton's method to rounding level (the two agree to 1e-9 wherever scipy's iteration has
/// converged; docs/keyframes.md).
/// Before the first and after the last keyframe the end cubics continue, as in scipy.
///
/// Building allocates: the spline keeps N times, N quaternions and N - 1 cubics (17 N - 9
/// scalars), and solving uses a temporary array of N - 1 records of 40 scalars, freed before the
/// constructor returns. Evaluation allocates nothing.
template <class T>
class rotation_spline {
public:
    /// The spline through `rotations` (non-zero quaternions, normalized here; q and -q are the same
    /// keyframe) at strictly increasing `times`: containers with data() and size(), or C arrays,
    /// of equal size >= 2. Debug builds check these preconditions; a release build given fewer
    /// than two keyframes or sizes that differ makes a spline that evaluates to NaN, and unsorted
    /// or non-finite input a meaningless (often non-finite) one, never undefined behaviour.
    /// try_make checks the input instead.
    template <class Times, class Rotations>
    rotation_spline(const Times& times, const Rotations& rotations) {
        const std::size_t count = detail::size_of(times);
        QUAT_ASSERT(count >= 2 && detail::size_of(rotations) == count,
                    "quat::rotation_spline: fewer than two keyframes, or times and rotations "
                    "differ in size");
        if (count < 2 || detail::size_of(rotations) != count) return;
        const auto* time = detail::data_of(times);
        const quaternion<T>* rotation = detail::data_of(rotations);
        for (std::size_t i = 1; i < count; ++i)
            QUAT_ASSERT(static_cast<T>(time[i - 1]) < static_cast<T>(time[i]),
                        "quat::rotation_spline: times are not strictly increasing");
        times_.resize(count);
        rotations_.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            times_[i] = static_cast<T>(time[i]);
            rotations_[i] = normalize(rotation[i]);
        }
        converged_ = build();
    }

    /// The spline, or std::nullopt when there are fewer than two keyframes, the sizes differ, a
    /// time or a component is NaN or infinite, times do not strictly increase, a quaternion is
    /// zero, or the solve for the angular velocities does not converge (no such keyframe set is
    /// known; the tests look for one among thousands of random sets).
    template <class Times, class Rotations>
    [[nodiscard]] static std::optional<rotation_spline> try_make(const Times& times,
                                                                 const Rotations& rotations) {
        const std::size_t count = detail::size_of(times);
        if (count < 2 || detail::size_of(rotations) != count) return std::nullopt;
        const auto* time = detail::data_of(times);
        const quaternion<T>* rotation = detail::data_of(rotations);
        for (std::size_t i = 0; i < count; ++i) {
            const T t = static_cast<T>(time[i]);
            const quaternion<T>& q = rotation[i];
            if (!detail::is_finite(t) || (i > 0 && !(static_cast<T>(time[i - 1]) < t)) ||
                !detail::is_finite(q.w) || !detail::is_finite(q.x) || !detail::is_finite(q.y) ||
                !detail::is_finite(q.z) || squared_norm(q) == T(0))
                return std::nullopt;
        }
        rotation_spline spline(times, rotations);
        if (!spline.converged_) return std::nullopt;
        return spline;
    }

    /// The rotation at time t (scipy's spline(t)): at a keyframe's time exactly its (normalized)
    /// rotation. A NaN t gives NaN.
    [[nodiscard]] quaternion<T> operator()(T t) const noexcept { return at(t, segment_of(t)); }

    /// The body-frame angular velocity at time t, radians per unit of time (scipy's spline(t, 1)):
    /// integrate_body of it over a short dt follows the spline. A NaN t gives NaN.
    [[nodiscard]] vec3<T> angular_velocity(T t) const noexcept {
        const local_motion m = local(t);
        return detail::right_jacobian(m.r, m.rate);
    }

    /// The body-frame angular acceleration at time t, radians per unit of time squared (scipy's
    /// spline(t, 2)): continuous, piecewise smooth. A NaN t gives NaN.
    [[nodiscard]] vec3<T> angular_acceleration(T t) const noexcept {
        const local_motion m = local(t);
        return detail::right_jacobian(m.r, m.second) + detail::right_jacobian_rate(m.r, m.rate);
    }

    /// out[k] = (*this)(ts[k]) for containers (data() and size(), or C arrays) of equal size
    /// (QUAT_ASSERT); times in increasing order find their segments in constant time each, others
    /// by binary search.
    template <class Times, class Output>
    void evaluate(const Times& ts, Output& out) const noexcept {
        const std::size_t count = detail::size_of(ts);
        QUAT_ASSERT(detail::size_of(out) == count,
                    "quat::rotation_spline::evaluate: ts and out differ in size");
        const auto* t = detail::data_of(ts);
        quaternion<T>* result = detail::data_of(out);
        std::size_t segment = 0;
        for (std::size_t k = 0; k < count; ++k) {
            const T time = static_cast<T>(t[k]);
            segment = segment_of(time, segment);
            result[k] = at(time, segment);
        }
    }

    /// The keyframe times and rotations (normalized), as given.
    /// @{
    [[nodiscard]] const std::vector<T>& times() const noexcept { return times_; }
    [[nodiscard]] const std::vector<quaternion<T>>& rotations() const noexcept {
        return rotations_;
    }
    /// @}

private:
    // r(s) = ((a s + b) s + c) s, s = t - t_i: the rotation vector from keyframe i; c is the
    // angular velocity at keyframe i.
    struct cubic {
        vec3<T> a, b, c;
    };

    // The rotation vector from the keyframe before t and its first and second derivatives.
    struct local_motion {
        vec3<T> r, rate, second;
    };

    [[nodiscard]] local_motion local(T t) const noexcept {
        if (cubics_.empty()) {
            const T nan = std::numeric_limits<T>::quiet_NaN();
            return {{nan, nan, nan}, {nan, nan, nan}, {nan, nan, nan}};
        }
        const std::size_t i = segment_of(t);
        const T s = t - times_[i];
        const cubic& c = cubics_[i];
        return {((c.a * s + c.b) * s + c.c) * s, (c.a * (T(3) * s) + c.b * T(2)) * s + c.c,
                c.a * (T(6) * s) + c.b * T(2)};
    }

    template <class U>
    [[nodiscard]] static U largest_component(const vec3<U>& v) noexcept {
        return detail::max(detail::abs(v.x), detail::max(detail::abs(v.y), detail::abs(v.z)));
    }

    [[nodiscard]] std::size_t segment_of(T t, std::size_t hint = 0) const noexcept {
        return detail::segment_of(times_.data(), times_.size(), t, hint);
    }

    [[nodiscard]] quaternion<T> at(T t, std::size_t i) const noexcept {
        if (cubics_.empty()) {
            const T nan = std::numeric_limits<T>::quiet_NaN();
            return {nan, nan, nan, nan};
        }
        // The last keyframe is the end of the last segment, where the cubic rounds to ~20 eps.
        if (t == times_[i + 1]) return rotations_[i + 1];
        const T s = t - times_[i];
        const cubic& c = cubics_[i];
        return rotations_[i] * from_rotation_vector(((c.a * s + c.b) * s + c.c) * s);
    }

    // Fills cubics_ from times_ and rotations_; false when Newton's method did not converge.
    bool build();

    std::vector<T> times_;
    std::vector<quaternion<T>> rotations_;
    std::vector<cubic> cubics_;
    bool converged_ = false;
};

/// rotation_spline(times, rotations) takes its scalar from the rotations: quaternion<T> gives T.
template <class Times, class Rotations>
rotation_spline(const Times&, const Rotations&)
    -> rotation_spline<detail::quaternion_scalar_t<Rotations>>;

template <class T>
bool rotation_spline<T>::build() {
    // float splines are solved in double: near half turns the solve loses digits (measured: up to
    // 1.3e-3 rad solved in float, 2e-6 in double and rounded to float).
    using S = std::conditional_t<std::is_same_v<T, float>, double, T>;
    const std::size_t count = times_.size(), segments = count - 1;
    // One temporary record per segment j: its duration, rotation vector r_j, J(r_j) (angular
    // velocity from the rotation vector's rate), J(r_j)^-1, the angular velocity at keyframe j,
    // and, for the inner keyframe j + 1, the jump of its angular acceleration, the block of the
    // Newton system on the diagonal, the step and the velocity before it.
    struct record {
        S dt;
        vec3<S> r;
        detail::matrix3<S> to_velocity, from_velocity, diagonal;
        vec3<S> start, jump, step, saved;
    };
    std::vector<record> work(segments);
    for (std::size_t j = 0; j < segments; ++j) {
        record& w = work[j];
        w.dt = static_cast<S>(times_[j + 1]) - static_cast<S>(times_[j]);
        w.r = to_rotation_vector(detail::relative_rotation<true>(quaternion<S>(rotations_[j]),
                                                                 quaternion<S>(rotations_[j + 1])));
        const S n = norm(w.r);
        w.to_velocity = detail::skew_polynomial(w.r, S(1), -detail::one_minus_cos_over_square(n),
                                                detail::n_minus_sin_over_cube(n));
        w.from_velocity =
            detail::skew_polynomial(w.r, S(1), S(0.5), detail::inverse_jacobian_coefficient(n));
        w.start = w.r / w.dt;  // the slerp's velocity, to start with
    }
    // The velocity at keyframe k; the last keyframe's is its segment's slerp velocity, as scipy's.
    const vec3<S> last = work[segments - 1].r / work[segments - 1].dt;
    const auto velocity = [&](std::size_t k) -> const vec3<S>& {
        return k < segments ? work[k].start : last;
    };
    const std::size_t inner = count - 2;
    const auto jumps = [&]() {
        S sum = S(0);
        for (std::size_t k = 1; k <= inner; ++k) {
            record& p = work[k - 1];
            const record& s = work[k];
            const vec3<S> end_rate = p.from_velocity * velocity(k);
            const S both = S(4) / p.dt + S(4) / s.dt;
            p.jump = p.to_velocity * velocity(k - 1) * (S(2) / p.dt) + velocity(k) * both +
                     s.from_velocity * velocity(k + 1) * (S(2) / s.dt) +
                     detail::right_jacobian_rate(p.r, end_rate) - p.r * (S(6) / (p.dt * p.dt)) -
                     s.r * (S(6) / (s.dt * s.dt));
            p.diagonal = detail::skew_polynomial(p.r, both, S(0), S(0)) +
                         detail::right_jacobian_rate_derivative(p.r, end_rate) * p.from_velocity;
            sum += dot(p.jump, p.jump);
        }
        return sum;
    };
    // Newton's method, its step halved until the squared jumps decrease (far from the solution,
    // with steps between keyframes near half turns and durations unequal by 1000 times, full
    // steps can wander). The Newton system is block tridiagonal with 3 x 3 blocks.
    const auto solve = [&]() {
        S squared_jumps = inner > 0 ? jumps() : S(0);
        if (!detail::is_finite(squared_jumps)) return false;
        const S tolerance = detail::sqrt(std::numeric_limits<S>::epsilon());
        bool close = false;
        for (int iteration = 0; squared_jumps > S(0) && iteration < 100; ++iteration) {
            for (std::size_t m = 0; m < inner; ++m) {
                work[m].step = -work[m].jump;
                work[m].saved = work[m + 1].start;
            }
            // Unknown m is the velocity at keyframe m + 1: the blocks beside the diagonal come
            // from segments m (before it) and m + 1 (after it).
            detail::solve_block_tridiagonal(
                inner, [&](std::size_t m) { return work[m].to_velocity * (S(2) / work[m].dt); },
                [&](std::size_t m) -> detail::matrix3<S>& { return work[m].diagonal; },
                [&](std::size_t m) { return work[m + 1].from_velocity * (S(2) / work[m + 1].dt); },
                [&](std::size_t m) -> vec3<S>& { return work[m].step; });
            S largest_step = S(0), largest_velocity = S(0);
            for (std::size_t m = 0; m < inner; ++m) {
                largest_step = detail::max(largest_step, largest_component(work[m].step));
                largest_velocity = detail::max(largest_velocity, largest_component(work[m].saved));
            }
            const bool small = largest_step <= tolerance * largest_velocity;
            S fraction = S(1);
            for (int halving = 0;; ++halving) {
                for (std::size_t m = 0; m < inner; ++m)
                    work[m + 1].start = work[m].saved + work[m].step * fraction;
                const S trial = jumps();
                if (trial < squared_jumps) {  // false for NaN
                    squared_jumps = trial;
                    break;
                }
                if (halving == 40 || small) {  // no decrease: at rounding level, or stuck
                    for (std::size_t m = 0; m < inner; ++m) work[m + 1].start = work[m].saved;
                    return small;
                }
                fraction = fraction / S(2);
            }
            if (close) return true;  // one full step after reaching sqrt(epsilon)
            close = small && fraction == S(1);
        }
        return squared_jumps == S(0);
    };
    const bool converged = solve();
    cubics_.resize(segments);
    for (std::size_t j = 0; j < segments; ++j) {
        const record& w = work[j];
        const vec3<S> start = w.start, end = w.from_velocity * velocity(j + 1);
        // Two keyframes: the slerp, whose cubic terms are zero but would round to tiny values.
        const vec3<S> a =
            count == 2 ? vec3<S>{} : (w.r * S(-2) + (start + end) * w.dt) / (w.dt * w.dt * w.dt);
        const vec3<S> b =
            count == 2 ? vec3<S>{} : (w.r * S(3) - (start * S(2) + end) * w.dt) / (w.dt * w.dt);
        cubics_[j] = {vec3<T>(a), vec3<T>(b), vec3<T>(start)};
    }
    return converged;
}

}  // namespace quat

#endif  // QUAT_ROTATION_SPLINE_HPP_INCLUDED
