// A C2 path of a rigid body through (time, pose) keyframes, orientation and position interpolated
// separately: the rotation spline for the orientation, a cubic spline for the position.
#ifndef QUAT_TRAJECTORY_SPLIT_KEYFRAME_PATH_HPP_INCLUDED
#define QUAT_TRAJECTORY_SPLIT_KEYFRAME_PATH_HPP_INCLUDED

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../paths/detail/segments.hpp"
#include "../paths/rotation_spline.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../vec3.hpp"
#include "detail/hermite_cubic.hpp"
#include "detail/keyframe_poses.hpp"
#include "keyframe_path_state.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// A path through (time, pose) keyframes in R^3 x SO(3): the orientation is rotation_spline's
/// (C2, body angular velocity at the first and last keyframes that of the end segments' slerps)
/// and the position of the body's origin, in world coordinates, is the C2 cubic spline through
/// the keyframes' positions whose velocities at the first and last keyframes are those of the end
/// segments' straight lines: the same end condition, each end moving as its segment's constant-rate
/// interpolation would. Two keyframes give slerp and lerp. Position and velocity are continuous
/// at every keyframe; so are the accelerations, linear and angular, wherever rotation_spline's
/// solve converged (try_make says so). The position is independent of the rotation, so a screw
/// motion (turning about an axis while moving along it, or a body swinging on an arm) is cut
/// short: its position is a cubic in time, not a helix; se3_keyframe_path follows screws
/// exactly, and its doc says when to choose which. Before the first and after the last keyframe
/// the end cubics continue. Building allocates (the keyframes, the rotation spline and 3 (N - 1)
/// vectors of cubic coefficients); evaluation allocates nothing.
template <class T>
class split_keyframe_path {
public:
    /// The path through `poses` (unit dual quaternions: body to world; others are normalized
    /// here, dq and -dq alike) at finite, strictly increasing `times` (any arithmetic type,
    /// converted to T), containers with data() and size() or C arrays, of equal size >= 2. Debug
    /// builds check the sizes and times; a release build given fewer than two keyframes or sizes
    /// that differ makes a path that evaluates to NaN, and unsorted, repeated or non-finite times
    /// or NaN poses a meaningless (often non-finite) one, never undefined behaviour. try_make
    /// checks all of it.
    template <class Times, class Poses>
    split_keyframe_path(const Times& times, const Poses& poses)
        : split_keyframe_path(unpacked(times, poses)) {}

    /// The path, or std::nullopt when there are fewer than two keyframes, the sizes differ, a
    /// time or a pose component is not finite (also after conversion to T), the times do not
    /// strictly increase, a pose has a zero real part, rotation_spline::try_make is empty for the
    /// rotations (its solve did not converge, or a value would overflow T), or a position, velocity
    /// or acceleration between the first and last keyframes would overflow T. Never asserts.
    template <class Times, class Poses>
    [[nodiscard]] static std::optional<split_keyframe_path> try_make(const Times& times,
                                                                     const Poses& poses) {
        std::optional<detail::keyframes<T>> k = detail::try_unpack_keyframe_poses<T>(times, poses);
        if (!k) return std::nullopt;
        std::optional<rotation_spline<T>> rotation =
            rotation_spline<T>::try_make(k->times, k->rotations);
        if (!rotation) return std::nullopt;
        split_keyframe_path path(std::move(k->times), std::move(k->positions),
                                 std::move(*rotation));
        for (std::size_t j = 0; j + 1 < path.times_.size(); ++j) {
            const detail::cubic_bounds<T> b =
                detail::cubic_bounds_of(path.cubics_[j], path.times_[j + 1] - path.times_[j]);
            if (!detail::is_finite(b.value + detail::largest_magnitude(path.positions_[j])) ||
                !detail::is_finite(b.rate) || !detail::is_finite(b.second))
                return std::nullopt;
        }
        return path;
    }

    /// The pose at time t (body to world): at a keyframe's time its normalized pose, to a few eps.
    /// A NaN t, or a path without keyframes (moved from, or built from bad input in a release
    /// build), gives NaN.
    [[nodiscard]] dual_quaternion<T> operator()(T t) const noexcept {
        const std::size_t i = segment_of(t);
        return to_dual_quaternion(rotation_(t), position_at(t, i));
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
                    "quat::split_keyframe_path::evaluate: ts and out differ in size");
        detail::evaluate_keyframe_path(
            times_, ts, out,
            [this](T t, std::size_t i) {
                return to_dual_quaternion(rotation_(t), position_at(t, i));
            },
            [this](T t, std::size_t i) { return state_at(t, i); });
    }

    /// The keyframe times, converted to T.
    [[nodiscard]] const std::vector<T>& times() const noexcept { return times_; }
    /// The orientation: the rotation spline through the keyframes' rotations.
    [[nodiscard]] const rotation_spline<T>& orientation() const noexcept { return rotation_; }

private:
    template <class Times, class Poses>
    static detail::keyframes<T> unpacked(const Times& times, const Poses& poses) {
        const std::size_t count = detail::size_of(times);
        QUAT_ASSERT(count >= 2 && detail::size_of(poses) == count,
                    "quat::split_keyframe_path: fewer than two keyframes, or times and poses "
                    "differ in size");
        if (count < 2 || detail::size_of(poses) != count) return {};
        QUAT_ASSERT(detail::are_keyframe_times<T>(detail::data_of(times), count),
                    "quat::split_keyframe_path: times are not strictly increasing, or not finite");
        return detail::unpack_keyframe_poses<T>(times, poses, count);
    }

    explicit split_keyframe_path(detail::keyframes<T>&& k)
        : split_keyframe_path(std::move(k.times), std::move(k.positions),
                              rotation_spline<T>(k.times, k.rotations)) {}

    split_keyframe_path(std::vector<T>&& times, std::vector<vec3<T>>&& positions,
                        rotation_spline<T>&& rotation)
        : times_(std::move(times)),
          positions_(std::move(positions)),
          rotation_(std::move(rotation)) {
        if (times_.size() >= 2)
            detail::clamped_cubic_spline(times_.data(), positions_.data(), times_.size(), cubics_);
    }

    // False for a path without segments: moved from, or built from bad input in a release build.
    [[nodiscard]] bool has_segments() const noexcept {
        return !cubics_.empty() && times_.size() == cubics_.size() + 1 &&
               positions_.size() == times_.size();
    }

    [[nodiscard]] std::size_t segment_of(T t, std::size_t hint = 0) const noexcept {
        return detail::segment_of(times_.data(), times_.size(), t, hint);
    }

    [[nodiscard]] vec3<T> position_at(T t, std::size_t i) const noexcept {
        if (!has_segments()) {
            const T nan = detail::quiet_nan<T>();
            return {nan, nan, nan};
        }
        if (t == times_[i + 1]) return positions_[i + 1];
        const T duration = times_[i + 1] - times_[i], u = (t - times_[i]) / duration;
        return positions_[i] + detail::cubic_motion_at(cubics_[i], u, duration).value;
    }

    [[nodiscard]] keyframe_path_state<T> state_at(T t, std::size_t i) const noexcept {
        if (!has_segments()) return detail::nan_keyframe_path_state<T>();
        const T duration = times_[i + 1] - times_[i], u = (t - times_[i]) / duration;
        const detail::cubic_motion<T> m = detail::cubic_motion_at(cubics_[i], u, duration);
        const vec3<T> position = t == times_[i + 1] ? positions_[i + 1] : positions_[i] + m.value;
        return detail::make_keyframe_path_state(rotation_(t), position, m.rate, m.second,
                                                rotation_.angular_velocity(t),
                                                rotation_.angular_acceleration(t));
    }

    std::vector<T> times_;
    std::vector<vec3<T>> positions_;
    std::vector<detail::hermite_cubic<T>> cubics_;
    rotation_spline<T> rotation_;
};

/// split_keyframe_path(times, poses) takes its scalar from the poses: dual_quaternion<T> gives T.
template <class Times, class Poses>
split_keyframe_path(const Times&, const Poses&)
    -> split_keyframe_path<detail::element_scalar_t<dual_quaternion, Poses>>;

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_SPLIT_KEYFRAME_PATH_HPP_INCLUDED
