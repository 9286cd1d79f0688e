// A C2-continuous rotation spline through keyframes: scipy's RotationSpline, solved to convergence.
#ifndef QUAT_PATHS_ROTATION_SPLINE_HPP_INCLUDED
#define QUAT_PATHS_ROTATION_SPLINE_HPP_INCLUDED

#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../detail/relative_rotation.hpp"
#include "../lie/detail/rotation_vector_jacobian.hpp"
#include "../quaternion.hpp"
#include "../vec3.hpp"
#include "detail/block_tridiagonal.hpp"
#include "detail/segment_cubic.hpp"
#include "detail/segments.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// The derivative of right_jacobian_rate(r, v) with respect to v (r held fixed), with k the
/// coefficients at |r|.
template <class T>
[[nodiscard]] constexpr matrix3<T> right_jacobian_rate_derivative(
    const vec3<T>& r, const vec3<T>& v, const jacobian_rate_coefficients<T>& k) noexcept {
    const T d = dot(r, v);
    const vec3<T> c = cross(r, v);
    // d/dv of (r.v)(k4 r x v + k5 r x (r x v)) and of k3 v x (r x v) = k3 (r (v.v) - v (v.r)).
    return skew_polynomial(r, -k.cubic * d, k.quartic * d, k.quintic * d) +
           outer(c * k.quartic + cross(r, c) * k.quintic - v * k.cubic, r) +
           outer(r, v) * (T(2) * k.cubic);
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
/// converged; docs/keyframes.md). The solve works in a unit of time set by the durations, so
/// times scaled by any factor give the same curve (to rounding) at any magnitude.
/// Before the first and after the last keyframe the end cubics continue, as in scipy.
///
/// Building allocates: the spline keeps N times, N quaternions and N - 1 cubics (14 N - 9
/// scalars), and solving uses a temporary array of N - 1 records of 46 scalars, freed before the
/// constructor returns. The solve takes at most 100 Newton steps and 300 evaluations of the
/// equations: at most 400 passes over the keyframes (measured, -O2: 0.3 to 0.8 s for 10,000
/// keyframes that do not converge). Evaluation allocates nothing.
template <class T>
class rotation_spline {
public:
    /// The spline through `rotations` (non-zero quaternions, normalized here; q and -q are the same
    /// keyframe) at finite, strictly increasing `times` (of any arithmetic type, converted to T):
    /// containers with data() and size(), or C arrays, of equal size >= 2. Debug builds check
    /// these preconditions; a release build given fewer than two keyframes or sizes that differ
    /// makes a spline that evaluates to NaN, and unsorted or non-finite input a meaningless (often
    /// non-finite) one, never undefined behaviour. try_make checks the input instead. Where
    /// try_make is empty for valid input (the solve did not converge, or a value would overflow T)
    /// the constructor keeps the velocities with the smallest jumps: through every keyframe with
    /// continuous angular velocity, the acceleration jumping at inner keyframes, and the values
    /// that overflow infinite or NaN. Durations unequal by many orders of magnitude are valid and
    /// give rates of the short segments' size on the long ones: that is the C2 spline.
    template <class Times, class Rotations>
    rotation_spline(const Times& times, const Rotations& rotations) {
        const std::size_t count = detail::size_of(times);
        QUAT_ASSERT(count >= 2 && detail::size_of(rotations) == count,
                    "quat::rotation_spline: fewer than two keyframes, or times and rotations "
                    "differ in size");
        if (count < 2 || detail::size_of(rotations) != count) return;
        const auto* time = detail::data_of(times);
        const quaternion<T>* rotation = detail::data_of(rotations);
        QUAT_ASSERT(detail::are_keyframe_times<T>(time, count),
                    "quat::rotation_spline: times are not strictly increasing, or not finite");
        times_.resize(count);
        rotations_.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            times_[i] = detail::to_scalar<T>(time[i]);
            rotations_[i] = normalize(rotation[i]);
        }
        solved_ = build();
    }

    /// The spline, or std::nullopt when there are fewer than two keyframes, the sizes differ, a
    /// time or a component is NaN or infinite (also after conversion to T), times do not strictly
    /// increase, a quaternion is zero, the solve for the angular velocities does not converge
    /// within its bound of work (see the class comment; measured on random sets,
    /// docs/keyframes.md), or a value of the spline between its first and last keyframes would
    /// overflow T.
    template <class Times, class Rotations>
    [[nodiscard]] static std::optional<rotation_spline> try_make(const Times& times,
                                                                 const Rotations& rotations) {
        const std::size_t count = detail::size_of(times);
        if (count < 2 || detail::size_of(rotations) != count) return std::nullopt;
        const auto* time = detail::data_of(times);
        const quaternion<T>* rotation = detail::data_of(rotations);
        for (std::size_t i = 0; i < count; ++i) {
            const T t = detail::to_scalar<T>(time[i]);
            const quaternion<T>& q = rotation[i];
            // Zero, not |q|^2 == 0: normalize scales subnormal keyframes up first.
            if (!detail::is_finite(t) || (i > 0 && !(detail::to_scalar<T>(time[i - 1]) < t)) ||
                !detail::is_finite(q) || (q.w == T(0) && q.x == T(0) && q.y == T(0) && q.z == T(0)))
                return std::nullopt;
        }
        rotation_spline spline(times, rotations);
        if (!spline.solved_) return std::nullopt;
        return spline;
    }

    /// The rotation at time t (scipy's spline(t)): at a keyframe's time exactly its (normalized)
    /// rotation. A NaN t, or a spline without keyframes (moved from, or built from bad input in a
    /// release build), gives NaN.
    [[nodiscard]] quaternion<T> operator()(T t) const noexcept { return at(t, segment_of(t)); }

    /// The body-frame angular velocity at time t, radians per unit of time (scipy's spline(t, 1)):
    /// integrate_body of it over a short dt follows the spline. NaN as for operator().
    [[nodiscard]] vec3<T> angular_velocity(T t) const noexcept {
        const local_motion m = local(t);
        return detail::right_jacobian(m.r, m.rate);
    }

    /// The body-frame angular acceleration at time t, radians per unit of time squared (scipy's
    /// spline(t, 2)): continuous, piecewise smooth. NaN as for operator().
    [[nodiscard]] vec3<T> angular_acceleration(T t) const noexcept {
        const local_motion m = local(t);
        // A slerp segment (two keyframes) turns at a constant rate: zero (NaN for a NaN t), where
        // the formula would leave rounding noise times the velocity squared.
        if (m.constant_rate) return m.second;
        return detail::right_jacobian(m.r, m.second) + detail::right_jacobian_rate(m.r, m.rate);
    }

    /// out[k] = (*this)(ts[k]) for containers (data() and size(), or C arrays) of equal size
    /// (QUAT_ASSERT; a release build fills the shorter length); ts of any arithmetic type. Times
    /// in increasing order find their segments in constant time each, others by binary search.
    template <class Times, class Output>
    void evaluate(const Times& ts, Output& out) const noexcept {
        const std::size_t count = detail::size_of(ts);
        QUAT_ASSERT(detail::size_of(out) == count,
                    "quat::rotation_spline::evaluate: ts and out differ in size");
        const std::size_t filled = detail::size_of(out) < count ? detail::size_of(out) : count;
        const auto* t = detail::data_of(ts);
        quaternion<T>* result = detail::data_of(out);
        std::size_t segment = 0;
        for (std::size_t k = 0; k < filled; ++k) {
            const T time = detail::to_scalar<T>(t[k]);
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
    // r(u) = ((a u + b) u + c) u, u = (t - t_i) / (t_(i+1) - t_i): the rotation vector from
    // keyframe i in the segment's own time, so that its coefficients are angles (c is the
    // angular velocity at keyframe i times the duration) whatever the unit of time.
    using cubic = detail::hermite_cubic<T>;

    // The rotation vector from the keyframe before t and its first and second derivatives in t.
    struct local_motion {
        vec3<T> r, rate, second;
        bool constant_rate;
    };

    // False for a spline without segments: moved from, or built from too few keyframes or
    // unequal sizes in a release build.
    [[nodiscard]] bool has_segments() const noexcept {
        return !cubics_.empty() && times_.size() == cubics_.size() + 1 &&
               rotations_.size() == times_.size();
    }

    [[nodiscard]] local_motion local(T t) const noexcept {
        if (!has_segments()) {
            const T nan = detail::quiet_nan<T>();
            return {{nan, nan, nan}, {nan, nan, nan}, {nan, nan, nan}, false};
        }
        const std::size_t i = segment_of(t);
        const T s = t - times_[i], duration = times_[i + 1] - times_[i], u = s / duration;
        const cubic& c = cubics_[i];
        // The linear term as velocity times s, as the velocity itself is, so that on a slerp
        // segment r and its rate are parallel to rounding. Divided by the duration twice, not by
        // its square, which over- or underflows first.
        const vec3<T> velocity = c.c / duration, zero{};
        return {((c.a * u + c.b) * u) * u + velocity * s,
                (c.a * (T(3) * u) + c.b * T(2)) * u / duration + velocity,
                (c.a * (T(6) * u) + c.b * T(2)) / duration / duration, c.a == zero && c.b == zero};
    }

    template <class U>
    [[nodiscard]] static U largest_component(const vec3<U>& v) noexcept {
        return detail::max(detail::abs(v.x), detail::max(detail::abs(v.y), detail::abs(v.z)));
    }

    [[nodiscard]] std::size_t segment_of(T t, std::size_t hint = 0) const noexcept {
        return detail::segment_of(times_.data(), times_.size(), t, hint);
    }

    [[nodiscard]] quaternion<T> at(T t, std::size_t i) const noexcept {
        if (!has_segments()) {
            const T nan = detail::quiet_nan<T>();
            return {nan, nan, nan, nan};
        }
        // The last keyframe is the end of the last segment, where the cubic rounds to ~20 eps.
        if (t == times_[i + 1]) return rotations_[i + 1];
        const T u = (t - times_[i]) / (times_[i + 1] - times_[i]);
        const cubic& c = cubics_[i];
        return rotations_[i] * from_rotation_vector(((c.a * u + c.b) * u + c.c) * u);
    }

    // True when no value of segment i's rotation vector, rate, second derivative or angular
    // acceleration (whose terms grow as the rate squared times up to |r|^2) between its keyframes
    // can overflow T: bounds from the coefficients' magnitudes for u in [0, 1] (|J(r)| <= 1).
    [[nodiscard]] bool is_bounded(std::size_t i) const noexcept {
        const T duration = times_[i + 1] - times_[i];
        const detail::cubic_bounds<T> b = detail::cubic_bounds_of(cubics_[i], duration);
        return duration > T(0) && detail::is_finite(duration) && detail::is_finite(b.value) &&
               detail::is_finite(b.rate) &&
               detail::is_finite(b.second +
                                 b.rate * b.rate * ((T(1) + b.value) * (T(1) + b.value)));
    }

    // Fills cubics_ from times_ and rotations_; false when Newton's method did not converge within
    // its bound of work or a value would overflow T.
    bool build();

    std::vector<T> times_;
    std::vector<quaternion<T>> rotations_;
    std::vector<cubic> cubics_;
    bool solved_ = false;
};

/// rotation_spline(times, rotations) takes its scalar from the rotations: quaternion<T> gives T.
template <class Times, class Rotations>
rotation_spline(const Times&, const Rotations&)
    -> rotation_spline<detail::element_scalar_t<quaternion, Rotations>>;

template <class T>
bool rotation_spline<T>::build() {
    // float splines are solved in double: near half turns the solve loses digits (measured: up to
    // 1.3e-3 rad solved in float, 2e-6 in double and rounded to float).
    using S = std::conditional_t<std::is_same_v<T, float>, double, T>;
    const std::size_t count = times_.size(), segments = count - 1;
    // One temporary record per segment j: its duration, rotation vector r_j, the coefficients of
    // J's rate at r_j, J(r_j) (angular velocity from the rotation vector's rate), J(r_j)^-1, the
    // angular velocity at keyframe j, and, for the inner keyframe j + 1, the jump of its angular
    // acceleration, the block of the Newton system on the diagonal, the step and the velocity
    // before it.
    struct record {
        S dt;
        vec3<S> r;
        detail::jacobian_rate_coefficients<S> k;
        matrix3<S> to_velocity, from_velocity, diagonal;
        vec3<S> start, jump, step, saved;
    };
    std::vector<record> work(segments);
    // The equations hold in any unit of time and their solution scales with it, but in the
    // caller's unit the jumps (angle / time^2), squared, underflow to zero at durations of 1e100
    // (the first guess then passes for the solution) and overflow at 1e-100. So the solve runs in
    // the geometric mean of the shortest and longest durations, and measures the jumps in the
    // largest step's angle (tiny steps would underflow them the same way).
    S shortest = detail::infinity<S>(), longest = S(0), largest_step = S(0);
    for (std::size_t j = 0; j < segments; ++j) {
        record& w = work[j];
        w.dt = static_cast<S>(times_[j + 1]) - static_cast<S>(times_[j]);
        shortest = w.dt < shortest ? w.dt : shortest;
        longest = w.dt > longest ? w.dt : longest;
        w.r = to_rotation_vector(detail::relative_rotation<true>(quaternion<S>(rotations_[j]),
                                                                 quaternion<S>(rotations_[j + 1])));
        largest_step = detail::max(largest_step, largest_component(w.r));
    }
    const S unit_of_time = detail::sqrt(shortest) * detail::sqrt(longest);
    const S unit_of_angle = largest_step > S(0) ? largest_step : S(1);
    for (std::size_t j = 0; j < segments; ++j) {
        record& w = work[j];
        w.dt = w.dt / unit_of_time;
        const S n = norm(w.r);
        w.k = detail::jacobian_rate_coefficients_of(n);
        w.to_velocity =
            detail::skew_polynomial(w.r, S(1), -detail::one_minus_cos_over_square(n), w.k.cubic);
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
    // The bound of work: Newton steps, step halvings within one step (a step that must be
    // shorter than 2^-20 of Newton's is stuck; converging sets measured at most 16), and
    // evaluations of the jumps in all. Measured on random sets of 3 to 60 keyframes with durations
    // unequal by up to 1000 times: 99.9 % of those that converge take at most 107 evaluations, and
    // this bound turns 1 set in 9000 (one that took 881) into a failure.
    constexpr int most_steps = 100, most_halvings = 20, most_evaluations = 300;
    int evaluations = 0;
    const auto jumps = [&]() {
        ++evaluations;
        S sum = S(0);
        for (std::size_t k = 1; k <= inner; ++k) {
            record& p = work[k - 1];
            const record& s = work[k];
            const vec3<S> end_rate = p.from_velocity * velocity(k);
            const S both = S(4) / p.dt + S(4) / s.dt;
            p.jump = p.to_velocity * velocity(k - 1) * (S(2) / p.dt) + velocity(k) * both +
                     s.from_velocity * velocity(k + 1) * (S(2) / s.dt) +
                     detail::right_jacobian_rate(p.r, end_rate, p.k) -
                     p.r * (S(6) / (p.dt * p.dt)) - s.r * (S(6) / (s.dt * s.dt));
            p.diagonal =
                detail::skew_polynomial(p.r, both, S(0), S(0)) +
                detail::right_jacobian_rate_derivative(p.r, end_rate, p.k) * p.from_velocity;
            const vec3<S> measured = p.jump / unit_of_angle;
            sum += dot(measured, measured);
        }
        return sum;
    };
    // Newton's method, its step halved until the squared jumps decrease (far from the solution,
    // with steps between keyframes near half turns and durations unequal by 1000 times, full
    // steps can wander). The Newton system is block tridiagonal with 3 x 3 blocks.
    const auto solve = [&]() {
        S squared_jumps = inner > 0 ? jumps() : S(0);
        if (!detail::is_finite(squared_jumps)) return false;
        const S tolerance = detail::sqrt(detail::epsilon<S>());
        bool close = false;
        for (int iteration = 0; squared_jumps > S(0) && iteration < most_steps; ++iteration) {
            for (std::size_t m = 0; m < inner; ++m) {
                work[m].step = -work[m].jump;
                work[m].saved = work[m + 1].start;
            }
            // Unknown m is the velocity at keyframe m + 1: the blocks beside the diagonal come
            // from segments m (before it) and m + 1 (after it).
            detail::solve_block_tridiagonal(
                inner, [&](std::size_t m) { return work[m].to_velocity * (S(2) / work[m].dt); },
                [&](std::size_t m) -> matrix3<S>& { return work[m].diagonal; },
                [&](std::size_t m) { return work[m + 1].from_velocity * (S(2) / work[m + 1].dt); },
                [&](std::size_t m) -> vec3<S>& { return work[m].step; });
            S longest_step = S(0), largest_velocity = S(0);
            for (std::size_t m = 0; m < inner; ++m) {
                longest_step = detail::max(longest_step, largest_component(work[m].step));
                largest_velocity = detail::max(largest_velocity, largest_component(work[m].saved));
            }
            const bool small = longest_step <= tolerance * largest_velocity;
            S fraction = S(1);
            for (int halving = 0;; ++halving) {
                for (std::size_t m = 0; m < inner; ++m)
                    work[m + 1].start = work[m].saved + work[m].step * fraction;
                const S trial = jumps();
                if (trial < squared_jumps) {  // false for NaN
                    squared_jumps = trial;
                    break;
                }
                // No decrease: at rounding level, stuck, or out of work.
                if (small || halving == most_halvings || evaluations >= most_evaluations) {
                    for (std::size_t m = 0; m < inner; ++m) work[m + 1].start = work[m].saved;
                    return small;
                }
                fraction = fraction / S(2);
            }
            if (close) return true;  // one full step after reaching sqrt(epsilon)
            close = small && fraction == S(1);
            if (evaluations >= most_evaluations) return false;
        }
        return squared_jumps == S(0);
    };
    const bool converged = solve();
    // The cubics in each segment's own time u: velocities (per unit_of_time) times the duration.
    // Values beyond float's range (only from a failed solve) become NaN, not an undefined cast.
    const auto narrow = [](const vec3<S>& v) {
        if constexpr (!std::is_same_v<S, T>) {
            const S largest = static_cast<S>(detail::largest<T>());
            if (!(largest_component(v) <= largest)) {
                const T nan = detail::quiet_nan<T>();
                return vec3<T>{nan, nan, nan};
            }
        }
        return vec3<T>(v);
    };
    cubics_.resize(segments);
    bool bounded = true;
    for (std::size_t j = 0; j < segments; ++j) {
        const record& w = work[j];
        const vec3<S> start = w.start * w.dt, end = (w.from_velocity * velocity(j + 1)) * w.dt;
        // Two keyframes: the slerp, whose cubic terms are zero but would round to tiny values.
        const vec3<S> a = count == 2 ? vec3<S>{} : w.r * S(-2) + start + end;
        const vec3<S> b = count == 2 ? vec3<S>{} : w.r * S(3) - start * S(2) - end;
        cubics_[j] = {narrow(a), narrow(b), narrow(count == 2 ? w.r : start)};
        bounded = bounded && is_bounded(j);
    }
    return converged && bounded;
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_PATHS_ROTATION_SPLINE_HPP_INCLUDED
