// A C2 path of a rigid body through (time, pose) keyframes in SE(3): a cubic twist per segment,
// so that rotation and translation move together, as a screw.
#ifndef QUAT_TRAJECTORY_SE3_KEYFRAME_PATH_HPP_INCLUDED
#define QUAT_TRAJECTORY_SE3_KEYFRAME_PATH_HPP_INCLUDED

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../lie/detail/rotation_vector_jacobian.hpp"
#include "../paths/detail/segments.hpp"
#include "../paths/rotation_spline.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../vec3.hpp"
#include "detail/hermite_cubic.hpp"
#include "detail/keyframe_poses.hpp"
#include "detail/left_jacobian_rates.hpp"
#include "detail/se3_cubics.hpp"
#include "keyframe_path_state.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// A C2 path through (time, pose) keyframes in SE(3): on segment i, X(t) = X_i exp(xi_i(u)),
/// u = (t - t_i) / (t_(i+1) - t_i), with xi_i a cubic twist (rho, omega), xi_i(0) = 0 and
/// xi_i(1) = log(X_i^-1 X_(i+1)) (the shorter rotation), the body twist at the first and last
/// keyframes that of the end segments' constant-twist screws (sclerp), and the body velocities at
/// the inner keyframes solved so that the linear and angular accelerations are continuous.
/// rotation_spline is this construction on SO(3), and the rotation part of a twist cubic moves on
/// its own, so the orientation is rotation_spline's (to rounding) and, given it, the translation
/// is a linear block-tridiagonal solve (derivation in trajectory/detail/se3_cubics.hpp).
///
/// Why a C2 cubic in se(3) rather than Catmull-Rom or Hermite forms in se(3): it reuses
/// rotation_spline's orientation (with its C2 claim, its solve and its end conditions) and adds
/// only a linear solve, where a Catmull-Rom twist path would be C1 with tangents picked by a rule.
///
/// Split (split_keyframe_path) or coupled (this)? Both are invariant to the choice of world frame.
/// This path is also invariant to the choice of body frame: the keyframes X_i H give the path
/// X(t) H for any fixed H, so every point of the body moves the same whichever point is called
/// the origin, and a motion of constant twist (a screw: a camera on a turning arm, a rolling
/// wheel, a body turning about an axis off its origin) is reproduced exactly. Choose it for
/// physical rigid motions and continuous-time estimation. The split path moves the origin on a
/// cubic of its own: the origin's path does not swing when the body turns (a camera dollying in
/// a straight line while it pans stays on the line, which here bends), at the price of depending
/// on which point is the origin. Choose it when the keyframed position is the thing to follow.
/// (A. Haarbach, T. Birdal, S. Ilic, "Survey of higher order rigid body motion interpolation
/// methods for keyframe animation and continuous-time trajectory estimation", 3DV 2018, compares
/// the two families; the tests measure both cases.)
///
/// Before the first and after the last keyframe the end cubics continue. Building allocates (the
/// keyframes, 6 (N - 1) vectors of coefficients, a temporary rotation spline and one record per
/// keyframe); evaluation allocates nothing.
template <class T>
class se3_keyframe_path {
public:
    /// The path through `poses` (unit dual quaternions: body to world; others are normalized
    /// here, dq and -dq alike) at finite, strictly increasing `times` (any arithmetic type,
    /// converted to T), containers with data() and size() or C arrays, of equal size >= 2. Debug
    /// builds check the sizes and times; a release build given fewer than two keyframes or sizes
    /// that differ makes a path that evaluates to NaN, and unsorted, repeated or non-finite times
    /// or NaN poses a meaningless (often non-finite) one, never undefined behaviour. Where the
    /// rotation spline's solve does not converge (try_make is empty) the path is C1.
    template <class Times, class Poses>
    se3_keyframe_path(const Times& times, const Poses& poses)
        : se3_keyframe_path(unpacked(times, poses)) {}

    /// The path, or std::nullopt when there are fewer than two keyframes, the sizes differ, a
    /// time or a pose component is not finite (also after conversion to T), the times do not
    /// strictly increase, a pose has a zero real part, rotation_spline::try_make is empty for the
    /// rotations, or a value of the path between the first and last keyframes would overflow T.
    /// Never asserts.
    template <class Times, class Poses>
    [[nodiscard]] static std::optional<se3_keyframe_path> try_make(const Times& times,
                                                                   const Poses& poses) {
        std::optional<detail::keyframes<T>> k = detail::try_unpack_keyframe_poses<T>(times, poses);
        if (!k) return std::nullopt;
        const std::optional<rotation_spline<T>> rotation =
            rotation_spline<T>::try_make(k->times, k->rotations);
        if (!rotation) return std::nullopt;
        se3_keyframe_path path(std::move(*k), *rotation);
        return path.is_bounded() ? std::optional<se3_keyframe_path>(std::move(path)) : std::nullopt;
    }

    /// The pose at time t (body to world): at a keyframe's time its normalized pose, to a few eps.
    /// A NaN t, or a path without keyframes (moved from, or built from bad input in a release
    /// build), gives NaN.
    [[nodiscard]] dual_quaternion<T> operator()(T t) const noexcept {
        return pose_at(t, segment_of(t));
    }

    /// The pose, velocities and accelerations at time t, linear ones in units of the positions
    /// per unit of time (squared), angular ones in radians; frames as keyframe_path_state says.
    /// NaN as for operator().
    [[nodiscard]] keyframe_path_state<T> state(T t) const noexcept {
        return state_at(t, segment_of(t));
    }

    /// out[k] = (*this)(ts[k]) for an output of dual_quaternion<T>, state(ts[k]) for one of
    /// keyframe_path_state<T>: containers (data() and size(), or C arrays) of equal size
    /// (QUAT_ASSERT; a release build fills the shorter length), ts of any arithmetic type.
    /// Allocates nothing; times in increasing order find their segments in constant time.
    template <class Times, class Output>
    void evaluate(const Times& ts, Output& out) const noexcept {
        QUAT_ASSERT(detail::size_of(out) == detail::size_of(ts),
                    "quat::se3_keyframe_path::evaluate: ts and out differ in size");
        detail::evaluate_keyframe_path(
            times_, ts, out, [this](T t, std::size_t i) { return pose_at(t, i); },
            [this](T t, std::size_t i) { return state_at(t, i); });
    }

    /// The keyframe times, converted to T.
    [[nodiscard]] const std::vector<T>& times() const noexcept { return times_; }

private:
    template <class Times, class Poses>
    static detail::keyframes<T> unpacked(const Times& times, const Poses& poses) {
        const std::size_t count = detail::size_of(times);
        QUAT_ASSERT(count >= 2 && detail::size_of(poses) == count,
                    "quat::se3_keyframe_path: fewer than two keyframes, or times and poses "
                    "differ in size");
        if (count < 2 || detail::size_of(poses) != count) return {};
        QUAT_ASSERT(detail::are_keyframe_times<T>(detail::data_of(times), count),
                    "quat::se3_keyframe_path: times are not strictly increasing, or not finite");
        return detail::unpack_keyframe_poses<T>(times, poses, count);
    }

    explicit se3_keyframe_path(detail::keyframes<T>&& k) {
        if (k.times.size() < 2) return;
        const rotation_spline<T> rotation(k.times, k.rotations);
        *this = se3_keyframe_path(std::move(k), rotation);
    }

    se3_keyframe_path(detail::keyframes<T>&& k, const rotation_spline<T>& rotation)
        : times_(std::move(k.times)),
          rotations_(std::move(k.rotations)),
          positions_(std::move(k.positions)) {
        detail::se3_cubics(times_, rotations_, positions_, rotation, cubics_);
    }

    // False for a path without segments: moved from, or built from bad input in a release build.
    [[nodiscard]] bool has_segments() const noexcept {
        return !cubics_.empty() && times_.size() == cubics_.size() + 1 &&
               rotations_.size() == times_.size() && positions_.size() == times_.size();
    }

    [[nodiscard]] std::size_t segment_of(T t, std::size_t hint = 0) const noexcept {
        return detail::segment_of(times_.data(), times_.size(), t, hint);
    }

    // True when no position, velocity or acceleration between the keyframes can overflow T:
    // bounds from the coefficients' magnitudes for u in [0, 1], with |Jl| and its rates' factors
    // bounded through (1 + angle)^2 (rotation_spline::try_make bounds the angular values).
    [[nodiscard]] bool is_bounded() const noexcept {
        for (std::size_t j = 0; j < cubics_.size(); ++j) {
            const T duration = times_[j + 1] - times_[j];
            const detail::cubic_bounds<T> w = detail::cubic_bounds_of(cubics_[j].angular, duration);
            const detail::cubic_bounds<T> r = detail::cubic_bounds_of(cubics_[j].linear, duration);
            const T growth = (T(1) + w.value) * (T(1) + w.value);
            if (!detail::is_finite(detail::largest_magnitude(positions_[j]) + r.value * growth) ||
                !detail::is_finite((r.rate + r.value * w.rate) * growth) ||
                !detail::is_finite(
                    (r.second + r.rate * w.rate + r.value * (w.second + w.rate * w.rate)) * growth))
                return false;
        }
        return true;
    }

    [[nodiscard]] dual_quaternion<T> pose_at(T t, std::size_t i) const noexcept {
        if (!has_segments()) return detail::nan_keyframe_path_state<T>().pose;
        if (t == times_[i + 1]) return to_dual_quaternion(rotations_[i + 1], positions_[i + 1]);
        const T duration = times_[i + 1] - times_[i], u = (t - times_[i]) / duration;
        const vec3<T> omega = detail::cubic_motion_at(cubics_[i].angular, u, duration).value;
        const vec3<T> rho = detail::cubic_motion_at(cubics_[i].linear, u, duration).value;
        const vec3<T> zero{};
        const vec3<T> p = detail::left_jacobian_rates_of(omega, zero, zero)(rho).value;
        return to_dual_quaternion(rotations_[i] * from_rotation_vector(omega),
                                  positions_[i] + detail::rotate_unchecked(rotations_[i], p));
    }

    [[nodiscard]] keyframe_path_state<T> state_at(T t, std::size_t i) const noexcept {
        if (!has_segments()) return detail::nan_keyframe_path_state<T>();
        const T duration = times_[i + 1] - times_[i], u = (t - times_[i]) / duration;
        const detail::hermite_cubic<T>& turning = cubics_[i].angular;
        const detail::cubic_motion<T> w = detail::cubic_motion_at(turning, u, duration);
        const detail::cubic_motion<T> r = detail::cubic_motion_at(cubics_[i].linear, u, duration);
        const detail::left_jacobian_rates<T> jl =
            detail::left_jacobian_rates_of(w.value, w.rate, w.second);
        const auto at_rho = jl(r.value), at_rate = jl(r.rate);
        const vec3<T> p = at_rho.value;
        const vec3<T> velocity = at_rate.value + at_rho.rate;
        const vec3<T> acceleration = jl(r.second).value + at_rate.rate * T(2) + at_rho.second;
        const quaternion<T>& base = rotations_[i];
        const bool end = t == times_[i + 1];
        // A screw segment (two keyframes) turns at a constant rate: zero angular acceleration,
        // where the formula would leave rounding noise times the velocity squared.
        const vec3<T> zero{};
        const bool constant_rate = turning.a == zero && turning.b == zero;
        return detail::make_keyframe_path_state(
            end ? rotations_[i + 1] : base * from_rotation_vector(w.value),
            end ? positions_[i + 1] : positions_[i] + detail::rotate_unchecked(base, p),
            detail::rotate_unchecked(base, velocity), detail::rotate_unchecked(base, acceleration),
            detail::right_jacobian(w.value, w.rate),
            constant_rate ? w.second
                          : detail::right_jacobian(w.value, w.second) +
                                detail::right_jacobian_rate(w.value, w.rate));
    }

    std::vector<T> times_;
    std::vector<quaternion<T>> rotations_;
    std::vector<vec3<T>> positions_;
    std::vector<detail::se3_cubic<T>> cubics_;
};

/// se3_keyframe_path(times, poses) takes its scalar from the poses: dual_quaternion<T> gives T.
template <class Times, class Poses>
se3_keyframe_path(const Times&, const Poses&)
    -> se3_keyframe_path<detail::element_scalar_t<dual_quaternion, Poses>>;

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_SE3_KEYFRAME_PATH_HPP_INCLUDED
