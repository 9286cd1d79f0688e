// Hand-eye calibration: the fixed rigid motion X between a robot's hand (gripper, rig) and a sensor
// mounted on it (the eye: camera, IMU) from motions measured by both, A_i X = X B_i, by
// Daniilidis's dual-quaternion method ("Hand-eye calibration using dual quaternions", The
// International Journal of Robotics Research 18(3), 1999): rotation and translation together, from
// the null space of one stacked matrix; or rotation first (the closed forms:
// registration/detail/hand_eye_solvers.hpp). From the absolute poses, hand_eye_from_poses refines
// the closed form by fitting the mount and the target's pose to the poses
// (registration/detail/hand_eye_poses.hpp).
#ifndef QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED
#define QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../detail/power_of_two.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "detail/hand_eye_poses.hpp"
#include "detail/hand_eye_solvers.hpp"

namespace quat {

/// The mount X found by hand_eye, and how well the motions agree with it and determine it.
template <class T>
struct hand_eye_calibration {
    /// Unit dual quaternion of X: the sensor's frame in the hand's, x_hand = X x_sensor.
    dual_quaternion<T> mount;
    /// sqrt(mean angle(A_i X, X B_i)^2): the rotations' disagreement, radians.
    T rotation_rms;
    /// sqrt(mean |translation(A_i X) - translation(X B_i)|^2): the translations' disagreement, in
    /// the motions' unit of length.
    T translation_rms;
    /// ambiguity < 1/4: the motions turn about axes that spread beyond their noise, which fixes
    /// X. Otherwise (one turning axis, no turns, or axes that differ only by noise) X's slide along
    /// the common axis is free, and so is its turn about it unless the translations fix it;
    /// hand_eye says which solution it returns then.
    bool unique;
    /// How nearly the motions leave X's rotation free, in (0, 1]: the largest of
    /// - sqrt(smallest / second-smallest eigenvalue) of the rotation equations' 4 x 4 normal
    ///   matrix (both raised to a floor of rounding): the noise of the motions' rotations against
    ///   the spread of their axes, weighted by sin^2 of the half-angles, which more motions do not
    ///   change;
    /// - for the hand's motions and for the sensor's: sqrt(rounding floor / (e2 + e3)), at most 1,
    ///   for e1 >= e2 >= e3 the eigenvalues of sum sin^2(angle_i / 2) axis_i axis_i^T, so that
    ///   one side turning about one axis gives 1 whatever noise the other side's motions carry.
    /// Exact motions about several axes sit at rounding's floor, about 4 sqrt(epsilon) / spread
    /// (median 1.1e-7 in double and 2.5e-3 in float for turns of 0.1 to 2 rad about random axes);
    /// noisy ones near the noise (a median of 0.7 times the angle noise of each measured pose for
    /// those turns); one axis or none: 1. unique is ambiguity < 1/4. Treat values approaching 1/4
    /// as ill-conditioned: the axes then spread hardly beyond the noise, and the rotation about the
    /// least determined axis is the first to go wrong. NaN where the result is NaN; NaN too when
    /// not given in a hand-written hand_eye_calibration.
    T ambiguity = detail::quiet_nan<T>();
};

/// How hand_eye solves A_i X = X B_i.
enum class hand_eye_method {
    /// Daniilidis 1999: rotation and translation together, from one 8 x 8 eigen-solve. Translation
    /// noise reaches the rotation.
    daniilidis,
    /// The rotation from the rotation rows alone, then the translation by linear least squares
    /// given it: about twice as accurate in rotation at the same data (docs/rigid-motions.md).
    rotation_first
};

/// hand_eye_from_poses's result: the mount as hand_eye reports it, and the target's pose.
template <class T>
struct hand_eye_with_target {
    /// The mount X, and rotation_rms, translation_rms, unique and ambiguity as hand_eye gives them
    /// for the motions between consecutive poses (A = H_(j+1)^-1 H_j, B = S_(j+1) S_j^-1).
    hand_eye_calibration<T> calibration;
    /// W, the target in the robot's base (x_base = W x_target): H_j X S_j = W for exact poses.
    dual_quaternion<T> target;
    /// True where the refinement on the poses replaced the closed form; false where the
    /// poses do not fix X (calibration.unique false), for bad input, or where it did not lower
    /// the cost.
    bool refined;
};

#include "../detail/isa_namespace.inc"
namespace detail {

/// The documented NaN result: NaN in the mount, the residuals and the ambiguity; not unique.
template <class T>
[[nodiscard]] constexpr hand_eye_calibration<T> nan_calibration() noexcept {
    const T nan = quiet_nan<T>();
    return {{nan_quaternion<T>(), nan_quaternion<T>()}, nan, nan, false, nan};
}

/// c.mount with a non-negative scalar part, and c's rotation_rms and translation_rms for it over
/// count >= 1 motions, p the power of two the translations are divided by.
template <class T, class A, class B>
constexpr void set_residuals(hand_eye_calibration<T>& c, const A& a_motions, const B& b_motions,
                             std::size_t count, T p) noexcept {
    if (c.mount.real.w < T(0)) c.mount = -c.mount;
    T angles(0), offsets(0), n(0);
    for (std::size_t i = 0; i < count; ++i) {
        n += T(1);
        const dual_quaternion<T> a(a_motions[i]), b(b_motions[i]);
        const dual_quaternion<T> left = a * c.mount, right = c.mount * b;
        const T angle = angle_between(left.real, right.real);
        // Divided by p before squaring, so that huge translations cannot overflow the sum.
        const vec3<T> offset = (translation_of(left) - translation_of(right)) / p;
        angles += angle * angle;
        offsets += dot(offset, offset);
    }
    c.rotation_rms = sqrt(angles / n);
    c.translation_rms = sqrt(offsets / n) * p;
}

template <class T, class A, class B>
[[nodiscard]] constexpr hand_eye_calibration<T> solve_hand_eye(const A& a_motions,
                                                               const B& b_motions,
                                                               std::size_t count,
                                                               hand_eye_method method) noexcept {
    if (count == 0) return {dual_quaternion<T>::identity(), T(0), T(0), false, T(1)};
    // The translations are divided by the power of two of the longest, so that the dual rows
    // weigh like the rotation rows (Daniilidis's matrix mixes both) and nothing overflows.
    T longest(0), motions(0), wa[3][3] = {}, wb[3][3] = {};
    for (std::size_t i = 0; i < count; ++i) {
        const dual_quaternion<T> a(a_motions[i]), b(b_motions[i]);
        if (!is_finite(a.real) || !is_finite(a.dual) || !is_finite(b.real) || !is_finite(b.dual))
            return nan_calibration<T>();
        longest = max(longest, max(largest_magnitude(a.dual), largest_magnitude(b.dual)));
        motions += T(1);
        const T va[3] = {a.real.x, a.real.y, a.real.z}, vb[3] = {b.real.x, b.real.y, b.real.z};
        for (int x = 0; x < 3; ++x)
            for (int y = 0; y < 3; ++y) {
                wa[x][y] += va[x] * va[y];
                wb[x][y] += vb[x] * vb[y];
            }
    }
    const T p = binade_or_one(longest);
    const symmetric_eigen4<T> rows = rotation_rows_eigen(a_motions, b_motions, count, p);
    const rotation_fit<T> fit =
        fit_of(rows, spread_of(wa, motions), spread_of(wb, motions), motions);
    const bool unique = fit.ambiguity < ambiguity_limit<T>();
    dual_quaternion<T> best = !unique ? free_mount(a_motions, b_motions, count, p, rows, fit.fixed)
                              : method == hand_eye_method::rotation_first
                                  ? rotation_first_mount(a_motions, b_motions, count, p, rows)
                                  : daniilidis_mount(a_motions, b_motions, count, p);
    // Daniilidis's two smallest eigenvectors hold no rotation only where rounding hides a third
    // null direction; the free solution is then the one left.
    if (!(squared_norm(best.real) > T(0)))
        best = free_mount(a_motions, b_motions, count, p, rows, fit.fixed);
    best.dual = best.dual * p;
    hand_eye_calibration<T> result{best, T(0), T(0), unique, fit.ambiguity};
    set_residuals(result, a_motions, b_motions, count, p);
    return result;
}

template <class T, class H, class S>
[[nodiscard]] constexpr hand_eye_with_target<T> solve_hand_eye_from_poses(
    const H* hands, const S* targets, std::size_t count) noexcept {
    T longest(0);
    for (std::size_t j = 0; j < count; ++j) {
        const dual_quaternion<T> h(hands[j]), s(targets[j]);
        if (!is_finite(h.real) || !is_finite(h.dual) || !is_finite(s.real) || !is_finite(s.dual))
            return {nan_calibration<T>(), nan_calibration<T>().mount, false};
        longest = max(longest, max(largest_magnitude(h.dual), largest_magnitude(s.dual)));
    }
    const dual_quaternion<T> identity = dual_quaternion<T>::identity();
    if (count < 2)
        return {{identity, T(0), T(0), false, T(1)},
                count == 1
                    ? normalize(dual_quaternion<T>(hands[0]) * dual_quaternion<T>(targets[0]))
                    : identity,
                false};
    const T p = binade_or_one(longest);
    const hand_motion_view<T, H> a{hands, false};
    const target_motion_view<T, S> b{targets, false};
    const std::size_t motions = pair_count(count, false);
    hand_eye_calibration<T> c = solve_hand_eye<T>(a, b, motions, hand_eye_method::rotation_first);
    const pose_refinement<T> r = refine_hand_eye(hands, targets, count, c.mount, p, c.unique);
    c.mount = r.mount;
    set_residuals(c, a, b, motions, p);
    return {c, r.target, r.refined};
}

}  // namespace detail

/// The mount X with A_i X = X B_i for every i, in the least-squares sense of the chosen method
/// (Daniilidis's by default; hand_eye_method::rotation_first for the more accurate rotation):
/// eye-in-hand calibration. motions_a holds the hand's motions and motions_b the sensor's, as unit
/// dual quaternions (containers of dual_quaternion<T> with data() and size(), equally long, or C
/// arrays). From absolute poses, the hand's H_j (hand in the robot's base) and the sensor's S_j
/// (a fixed target in the sensor's frame), pair j -> k gives A = H_k^-1 H_j and B = S_k S_j^-1;
/// X then maps sensor coordinates into hand coordinates (hand_eye_from_poses takes the poses
/// themselves, and is more accurate under measurement noise). The sign of each B is chosen to
/// match its A's screw (equal scalar parts), so either sign may be given. The robot-world form
/// AX = YB is not solved here.
///
/// unique is false where the motions do not fix X (hand_eye_calibration::ambiguity, reported, at
/// 1/4 or more): the hand turning about one axis, or not at all, or about axes that differ only by
/// noise. Then both methods return the same solution: among the rotations the rotation equations
/// leave free (a turn about the common axis; any rotation where nothing turns), the one that fits
/// the translations best (for pure translations, t_Ai = R_X t_Bi), and of the translations that
/// fit it, the least: no slide along the common axis, and none at all without turns. Exact
/// motions about one axis give that solution to rounding. Noise on the hand's motions as well can,
/// with few motions, spread one axis into axes that look determined: use more motions, and turns
/// well above the noise.
///
/// No motions: the identity, residuals 0, ambiguity 1, not unique. Lists of different sizes (a
/// precondition, QUAT_ASSERT) or a NaN or infinite component give NaN in every component,
/// residuals and ambiguity, and unique false; try_hand_eye checks instead. Finite motions never
/// give NaN. Precondition: unit real parts (QUAT_ASSERT).
template <class MotionsA, class MotionsB,
          class T = detail::element_scalar_t<dual_quaternion, MotionsA>>
[[nodiscard]] constexpr hand_eye_calibration<T> hand_eye(
    const MotionsA& motions_a, const MotionsB& motions_b,
    hand_eye_method method = hand_eye_method::daniilidis) noexcept {
    QUAT_ASSERT(detail::same_size(motions_a, motions_b),
                "quat::hand_eye: the two lists of motions differ in size");
    if (!detail::same_size(motions_a, motions_b)) return detail::nan_calibration<T>();
    const auto* a = detail::data_of(motions_a);
    const auto* b = detail::data_of(motions_b);
    const std::size_t count = detail::size_of(motions_a);
    for (std::size_t i = 0; i < count; ++i)  // an empty loop where QUAT_ASSERT compiles to nothing
        QUAT_ASSERT(detail::is_near_unit(dual_quaternion<T>(a[i]).real) &&
                        detail::is_near_unit(dual_quaternion<T>(b[i]).real),
                    "quat::hand_eye: a motion's real part is not a unit quaternion");
    return detail::solve_hand_eye<T>(a, b, count, method);
}

/// hand_eye(motions_a, motions_b, method), or std::nullopt for motions it cannot calibrate from:
/// lists of different sizes, fewer than two motions, a NaN or infinite component, or a real part
/// that is not a unit quaternion (|q|^2 not within 1/4096 of 1). Motions that leave X undetermined
/// (pure translations, one turning axis) are not bad input: they give hand_eye's solution with
/// unique = false. Never asserts.
template <class MotionsA, class MotionsB,
          class T = detail::element_scalar_t<dual_quaternion, MotionsA>>
[[nodiscard]] constexpr std::optional<hand_eye_calibration<T>> try_hand_eye(
    const MotionsA& motions_a, const MotionsB& motions_b,
    hand_eye_method method = hand_eye_method::daniilidis) noexcept {
    const std::size_t count = detail::size_of(motions_a);
    if (count < 2 || detail::size_of(motions_b) != count) return std::nullopt;
    const auto* a = detail::data_of(motions_a);
    const auto* b = detail::data_of(motions_b);
    for (std::size_t i = 0; i < count; ++i)
        if (!detail::is_valid_motion(dual_quaternion<T>(a[i])) ||
            !detail::is_valid_motion(dual_quaternion<T>(b[i])))
            return std::nullopt;
    const hand_eye_calibration<T> result = detail::solve_hand_eye<T>(a, b, count, method);
    if (!detail::is_finite(result.mount.real) || !detail::is_finite(result.mount.dual) ||
        !detail::is_finite(result.rotation_rms) || !detail::is_finite(result.translation_rms))
        return std::nullopt;
    return result;
}

/// The mount X and the target's pose W from absolute poses, eye-in-hand: hand_poses[j] is the
/// hand in the robot's base (H_j), target_poses[j] a fixed target in the sensor's frame (S_j, e.g.
/// from a camera's pose estimate), so that H_j X S_j = W for every j. hand_eye's rotation_first
/// solution from the motions between consecutive poses, then X and W fitted to the poses for exact
/// hand poses and target poses measured with isotropic rotation and translation noise of unknown
/// variances: weighted least squares, the weights from the data's residuals in two rounds (the
/// maximum of the likelihood where there are many poses; registration/detail/hand_eye_poses.hpp,
/// docs/rigid-motions.md). The answer does not depend on the unit of length. Where the poses do
/// not fix X (calibration.unique false) the closed form stays, as hand_eye gives it.
///
/// Unit dual quaternions, in containers with data() and size(), equally long, or C arrays. No
/// poses: X and W the identity; one: X the identity and W = H_0 S_0; both with residuals 0,
/// ambiguity 1, not unique. Lists of different sizes (a precondition, QUAT_ASSERT) or a NaN or
/// infinite component give NaN in every component of X and W, the residuals and the ambiguity;
/// try_hand_eye_from_poses checks instead. Precondition: unit real parts (QUAT_ASSERT).
template <class HandPoses, class TargetPoses,
          class T = detail::element_scalar_t<dual_quaternion, HandPoses>>
[[nodiscard]] constexpr hand_eye_with_target<T> hand_eye_from_poses(
    const HandPoses& hand_poses, const TargetPoses& target_poses) noexcept {
    QUAT_ASSERT(detail::same_size(hand_poses, target_poses),
                "quat::hand_eye_from_poses: the two lists of poses differ in size");
    if (!detail::same_size(hand_poses, target_poses))
        return {detail::nan_calibration<T>(), detail::nan_calibration<T>().mount, false};
    const auto* h = detail::data_of(hand_poses);
    const auto* s = detail::data_of(target_poses);
    const std::size_t count = detail::size_of(hand_poses);
    for (std::size_t j = 0; j < count; ++j)  // an empty loop where QUAT_ASSERT compiles to nothing
        QUAT_ASSERT(detail::is_near_unit(dual_quaternion<T>(h[j]).real) &&
                        detail::is_near_unit(dual_quaternion<T>(s[j]).real),
                    "quat::hand_eye_from_poses: a pose's real part is not a unit quaternion");
    return detail::solve_hand_eye_from_poses<T>(h, s, count);
}

/// hand_eye_from_poses(hand_poses, target_poses), or std::nullopt for poses it cannot calibrate
/// from: lists of different sizes, fewer than three poses, a NaN or infinite component, or a real
/// part that is not a unit quaternion (|q|^2 not within 1/4096 of 1). Poses that leave X
/// undetermined give the closed form with calibration.unique = false. Never asserts.
template <class HandPoses, class TargetPoses,
          class T = detail::element_scalar_t<dual_quaternion, HandPoses>>
[[nodiscard]] constexpr std::optional<hand_eye_with_target<T>> try_hand_eye_from_poses(
    const HandPoses& hand_poses, const TargetPoses& target_poses) noexcept {
    const std::size_t count = detail::size_of(hand_poses);
    if (count < 3 || detail::size_of(target_poses) != count) return std::nullopt;
    const auto* h = detail::data_of(hand_poses);
    const auto* s = detail::data_of(target_poses);
    for (std::size_t j = 0; j < count; ++j)
        if (!detail::is_valid_motion(dual_quaternion<T>(h[j])) ||
            !detail::is_valid_motion(dual_quaternion<T>(s[j])))
            return std::nullopt;
    const hand_eye_with_target<T> result = detail::solve_hand_eye_from_poses<T>(h, s, count);
    const hand_eye_calibration<T>& c = result.calibration;
    if (!detail::is_finite(c.mount.real) || !detail::is_finite(c.mount.dual) ||
        !detail::is_finite(result.target.real) || !detail::is_finite(result.target.dual) ||
        !detail::is_finite(c.rotation_rms) || !detail::is_finite(c.translation_rms))
        return std::nullopt;
    return result;
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED
