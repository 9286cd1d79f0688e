// Hand-eye calibration: the fixed rigid motion X between a robot's hand (gripper, rig) and a sensor
// mounted on it (the eye: camera, IMU) from motions measured by both, A_i X = X B_i, by
// Daniilidis's dual-quaternion method ("Hand-eye calibration using dual quaternions", The
// International Journal of Robotics Research 18(3), 1999): rotation and translation together, from
// the null space of one stacked matrix.
#ifndef QUAT_HAND_EYE_HPP_INCLUDED
#define QUAT_HAND_EYE_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "config.hpp"
#include "detail/containers.hpp"
#include "detail/math.hpp"
#include "detail/power_of_two.hpp"
#include "detail/symmetric_eigen.hpp"
#include "dual_quaternion.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

/// The mount X found by hand_eye, and how well the motions agree with it.
template <class T>
struct hand_eye_calibration {
    /// Unit dual quaternion of X: the sensor's frame in the hand's, x_hand = X x_sensor.
    dual_quaternion<T> mount;
    /// sqrt(mean angle(A_i X, X B_i)^2): the rotations' disagreement, radians.
    T rotation_rms;
    /// sqrt(mean |translation(A_i X) - translation(X B_i)|^2): the translations' disagreement, in
    /// the motions' unit of length.
    T translation_rms;
    /// False when the motions do not determine X: fewer than two turn (angle above 64 epsilon), or
    /// all turn about parallel axes (within 64 epsilon radians). X's rotation about that axis is
    /// then free, and so is its translation along it.
    bool unique;
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

#include "detail/isa_namespace.inc"
namespace detail {

/// The rows of Daniilidis's equation for one motion pair, a q = q b with equal scalar parts:
/// (a - b) q0 + [a + b]x q_vec = 0 for the vector parts a, b; row r of the 3 x 4 block.
template <class T>
constexpr void daniilidis_block(const quaternion<T>& a, const quaternion<T>& b,
                                T (&m)[3][4]) noexcept {
    const vec3<T> d{a.x - b.x, a.y - b.y, a.z - b.z}, s{a.x + b.x, a.y + b.y, a.z + b.z};
    const T rows[3][4] = {{d.x, T(0), -s.z, s.y}, {d.y, s.z, T(0), -s.x}, {d.z, -s.y, s.x, T(0)}};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) m[r][c] = rows[r][c];
}

/// True when every component of dq is finite and its real part is a unit quaternion to within
/// 1/4096 (the library's debug check).
template <class T>
[[nodiscard]] constexpr bool is_valid_motion(const dual_quaternion<T>& dq) noexcept {
    return is_finite(dq.real) && is_finite(dq.dual) && is_near_unit(dq.real);
}

/// Whether the motions' rotation axes determine X: at least two turn (angle above 64 epsilon), not
/// all about parallel axes (within 64 epsilon radians).
template <class T>
struct turning_axes {
    std::size_t turning = 0;
    vec3<T> longest{T(0), T(0), T(0)};  // the unit axis of the largest sin(angle / 2) so far
    T longest_size = T(0);
    bool parallel = true;

    constexpr void add(const quaternion<T>& rotation) noexcept {
        const vec3<T> axis{rotation.x, rotation.y, rotation.z};
        const T size = norm(axis);
        if (!(size > T(64) * epsilon<T>())) return;
        ++turning;
        const vec3<T> unit = axis / size;
        if (longest_size > T(0) && norm(cross(unit, longest)) > T(64) * epsilon<T>())
            parallel = false;
        if (size > longest_size) {
            longest = unit;
            longest_size = size;
        }
    }
    [[nodiscard]] constexpr bool determine() const noexcept { return turning >= 2 && !parallel; }
};

/// Motion i's pair as both methods take it: b's sign chosen so that its screw parameters equal a's
/// (a.real.w = b.real.w, the angle, and a.dual.w = b.dual.w, the slide), which Daniilidis's
/// equations assume; the dual parts (the translations) divided by p.
template <class T>
struct motion_pair {
    dual_quaternion<T> a, b;
};

template <class T, class A, class B>
[[nodiscard]] constexpr motion_pair<T> matched_pair(const A& a_motion, const B& b_motion,
                                                    T p) noexcept {
    const dual_quaternion<T> a(a_motion);
    dual_quaternion<T> b(b_motion);
    motion_pair<T> pair{{a.real, a.dual / p}, {b.real, b.dual / p}};
    const T same = abs(a.real.w - b.real.w) + abs(pair.a.dual.w - pair.b.dual.w);
    const T flipped = abs(a.real.w + b.real.w) + abs(pair.a.dual.w + pair.b.dual.w);
    if (flipped < same) pair.b = -pair.b;
    return pair;
}

/// m divided by its largest |element| (unchanged when that is 0): what jacobi_eigen expects.
/// Returns that element.
template <std::size_t N, class T>
constexpr T scale_to_unit(T (&m)[N][N]) noexcept {
    T largest(0);
    for (std::size_t x = 0; x < N; ++x)
        for (std::size_t y = 0; y < N; ++y) largest = max(largest, abs(m[x][y]));
    if (largest > T(0))
        for (std::size_t x = 0; x < N; ++x)
            for (std::size_t y = 0; y < N; ++y) m[x][y] = m[x][y] / largest;
    return largest;
}

/// Daniilidis's joint solution, with translations divided by p. M = sum T_i^T T_i for the 6 x 8
/// T_i = [[R_i, 0], [D_i, R_i]] acting on (q, q'), where R_i and D_i are daniilidis_block of the
/// real and the dual parts.
template <class T, class A, class B>
[[nodiscard]] constexpr dual_quaternion<T> daniilidis_mount(const A* a_motions, const B* b_motions,
                                                            std::size_t count, T p) noexcept {
    T m[8][8] = {};
    for (std::size_t i = 0; i < count; ++i) {
        const motion_pair<T> pair = matched_pair(a_motions[i], b_motions[i], p);
        T r[3][4] = {}, d[3][4] = {};
        daniilidis_block(pair.a.real, pair.b.real, r);
        daniilidis_block(pair.a.dual, pair.b.dual, d);
        T rows[6][8] = {};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 4; ++c) {
                rows[k][c] = r[k][c];
                rows[3 + k][c] = d[k][c];
                rows[3 + k][4 + c] = r[k][c];
            }
        for (int x = 0; x < 8; ++x)
            for (int y = x; y < 8; ++y) {
                T sum(0);
                for (int k = 0; k < 6; ++k) sum += rows[k][x] * rows[k][y];
                m[x][y] += sum;
            }
    }
    for (int x = 0; x < 8; ++x)
        for (int y = x + 1; y < 8; ++y) m[y][x] = m[x][y];
    scale_to_unit(m);
    const symmetric_eigen_n<8, T> eigen = jacobi_eigen<8>(m);

    // X = l1 v7 + l2 v8 over the two smallest eigenvectors, v = (u, w) with u the real and w the
    // dual half, under X's constraints |q| = 1 and q . q' = 0. With (l1, l2) = (cos f, sin f) the
    // second reads A cos 2f + B sin 2f + C = 0, A = (u1.w1 - u2.w2) / 2, B = (u1.w2 + u2.w1) / 2,
    // C = (u1.w1 + u2.w2) / 2: two solutions; the one with the larger |q| is X, scaled to |q| = 1.
    const T(&v7)[8] = eigen.vectors[6];
    const T(&v8)[8] = eigen.vectors[7];
    const quaternion<T> u1{v7[0], v7[1], v7[2], v7[3]}, w1{v7[4], v7[5], v7[6], v7[7]};
    const quaternion<T> u2{v8[0], v8[1], v8[2], v8[3]}, w2{v8[4], v8[5], v8[6], v8[7]};
    const T ca = (dot(u1, w1) - dot(u2, w2)) / T(2), cb = (dot(u1, w2) + dot(u2, w1)) / T(2),
            cc = (dot(u1, w1) + dot(u2, w2)) / T(2);
    const T amplitude = sqrt(ca * ca + cb * cb);
    const T phase = atan2(cb, ca);
    // Noise can push |C| / amplitude past 1: the nearest point, where the constraint is met best.
    T ratio = amplitude > T(0) ? -cc / amplitude : T(1);
    ratio = ratio > T(1) ? T(1) : (ratio < T(-1) ? T(-1) : ratio);
    const T spread = atan2(sqrt((T(1) - ratio) * (T(1) + ratio)), ratio);
    dual_quaternion<T> best{{T(0), T(0), T(0), T(0)}, {T(0), T(0), T(0), T(0)}};
    T best_size(-1);
    for (int sign = -1; sign <= 1; sign += 2) {
        const T f = (phase + T(sign) * spread) / T(2);
        const T c = cos(f), s = sin(f);
        const quaternion<T> q = u1 * c + u2 * s;
        const T size = norm(q);
        if (size > best_size) {
            best_size = size;
            best = {q / size, (w1 * c + w2 * s) / size};
        }
    }
    // The constraint q . q' = 0, met to rounding: remove what noise left along q.
    best.dual = best.dual - best.real * dot(best.real, best.dual);
    return best;
}

/// The rotation first, from the rotation rows alone (the eigenvector of the smallest eigenvalue of
/// sum R_i^T R_i), then the translation t of X by linear least squares given it:
/// (R_Ai - I) t = R_X t_Bi - t_Ai for every i (Tsai and Lenz's second step, IEEE Trans. Robotics
/// and Automation 5(3), 1989), solved through the eigen-decomposition of the 3 x 3 normal matrix,
/// its eigenvalues below 64 epsilon of the largest left out (rounding where the axes are nearly
/// parallel). Translations divided by p; for motions that determine X.
template <class T, class A, class B>
[[nodiscard]] constexpr dual_quaternion<T> rotation_first_mount(const A* a_motions,
                                                                const B* b_motions,
                                                                std::size_t count, T p) noexcept {
    T m[4][4] = {};
    for (std::size_t i = 0; i < count; ++i) {
        const motion_pair<T> pair = matched_pair(a_motions[i], b_motions[i], p);
        T r[3][4] = {};
        daniilidis_block(pair.a.real, pair.b.real, r);
        for (int x = 0; x < 4; ++x)
            for (int y = 0; y < 4; ++y)
                for (int k = 0; k < 3; ++k) m[x][y] += r[k][x] * r[k][y];
    }
    scale_to_unit(m);
    const symmetric_eigen4<T> eigen = symmetric_eigen(m);
    const quaternion<T> q = normalize(eigen.vectors[3]);
    const rotation_matrix<T> x_rotation = to_matrix(q);

    T normal[3][3] = {}, rhs[3] = {};
    for (std::size_t i = 0; i < count; ++i) {
        const motion_pair<T> pair = matched_pair(a_motions[i], b_motions[i], p);
        rotation_matrix<T> c = to_matrix(pair.a.real);  // R_A - I
        for (int k = 0; k < 3; ++k) c(k, k) -= T(1);
        const vec3<T> g = rotate(x_rotation, translation_of(pair.b)) - translation_of(pair.a);
        for (int x = 0; x < 3; ++x) {
            rhs[x] += dot(column(c, x), g);
            for (int y = 0; y < 3; ++y) normal[x][y] += dot(column(c, x), column(c, y));
        }
    }
    const T largest = scale_to_unit(normal);
    vec3<T> t{T(0), T(0), T(0)};
    if (largest > T(0)) {
        for (int x = 0; x < 3; ++x) rhs[x] = rhs[x] / largest;
        const symmetric_eigen_n<3, T> e = jacobi_eigen<3>(normal);
        for (std::size_t k = 0; k < 3; ++k) {
            if (!(e.values[k] > T(64) * epsilon<T>() * e.values[0])) continue;
            const vec3<T> v{e.vectors[k][0], e.vectors[k][1], e.vectors[k][2]};
            t += v * ((v.x * rhs[0] + v.y * rhs[1] + v.z * rhs[2]) / e.values[k]);
        }
    }
    return to_dual_quaternion(q, t);
}

template <class T, class A, class B>
[[nodiscard]] constexpr hand_eye_calibration<T> solve_hand_eye(const A* a_motions,
                                                               const B* b_motions,
                                                               std::size_t count,
                                                               hand_eye_method method) noexcept {
    const T nan = quiet_nan<T>();
    const quaternion<T> nan_q{nan, nan, nan, nan};
    if (count == 0) return {dual_quaternion<T>::identity(), T(0), T(0), false};
    // The translations are divided by the power of two of the longest, so that the dual rows
    // weigh like the rotation rows (Daniilidis's matrix mixes both) and nothing overflows.
    T longest(0);
    turning_axes<T> axes;
    for (std::size_t i = 0; i < count; ++i) {
        const dual_quaternion<T> a(a_motions[i]), b(b_motions[i]);
        if (!is_finite(a.real) || !is_finite(a.dual) || !is_finite(b.real) || !is_finite(b.dual))
            return {{nan_q, nan_q}, nan, nan, false};
        longest = max(longest, max(largest_magnitude(a.dual), largest_magnitude(b.dual)));
        axes.add(a.real);
    }
    const T p = binade_or_one(longest);
    // Where the motions leave X free, the rotation rows alone would pick any rotation about the
    // common axis, which the translations may not accept: Daniilidis's solution meets both.
    dual_quaternion<T> best = method == hand_eye_method::rotation_first && axes.determine()
                                  ? rotation_first_mount(a_motions, b_motions, count, p)
                                  : daniilidis_mount(a_motions, b_motions, count, p);
    best.dual = best.dual * p;
    if (best.real.w < T(0)) best = -best;

    T angles(0), offsets(0), n(0);
    for (std::size_t i = 0; i < count; ++i) {
        n += T(1);
        const dual_quaternion<T> a(a_motions[i]), b(b_motions[i]);
        const dual_quaternion<T> left = a * best, right = best * b;
        const T angle = angle_between(left.real, right.real);
        // Divided by p before squaring, so that huge translations cannot overflow the sum.
        const vec3<T> offset = (translation_of(left) - translation_of(right)) / p;
        angles += angle * angle;
        offsets += dot(offset, offset);
    }
    return {best, sqrt(angles / n), sqrt(offsets / n) * p, axes.determine()};
}

}  // namespace detail

/// The mount X with A_i X = X B_i for every i, in the least-squares sense of the chosen method
/// (Daniilidis's by default; hand_eye_method::rotation_first for the more accurate rotation):
/// eye-in-hand calibration. motions_a holds the hand's motions and motions_b the sensor's, as unit
/// dual quaternions (containers of dual_quaternion<T> with data() and size(), equally long, or C
/// arrays). From absolute poses, the hand's H_j (hand in the robot's base) and the sensor's S_j
/// (a fixed target in the sensor's frame), pair j -> k gives A = H_k^-1 H_j and B = S_k S_j^-1;
/// X then maps sensor coordinates into hand coordinates. The sign of each B is chosen to match its
/// A's screw (equal scalar parts), so either sign may be given. The robot-world form AX = YB is not
/// solved here. unique is false when fewer than two motions turn or all turn about parallel axes
/// (then X's rotation about that axis and its translation along it are undetermined, and one of the
/// solutions is returned). No motions: the identity, residuals 0, not unique. A NaN or infinite
/// component gives NaN in every component; try_hand_eye checks instead. Precondition: unit real
/// parts (QUAT_ASSERT).
template <class MotionsA, class MotionsB,
          class T = detail::element_scalar_t<dual_quaternion, MotionsA>>
[[nodiscard]] constexpr hand_eye_calibration<T> hand_eye(
    const MotionsA& motions_a, const MotionsB& motions_b,
    hand_eye_method method = hand_eye_method::daniilidis) noexcept {
    QUAT_ASSERT(detail::size_of(motions_a) == detail::size_of(motions_b),
                "quat::hand_eye: the two lists of motions differ in size");
    const auto* a = detail::data_of(motions_a);
    const auto* b = detail::data_of(motions_b);
    const std::size_t count = detail::size_of(motions_a) < detail::size_of(motions_b)
                                  ? detail::size_of(motions_a)
                                  : detail::size_of(motions_b);
    for (std::size_t i = 0; i < count; ++i)  // an empty loop where QUAT_ASSERT compiles to nothing
        QUAT_ASSERT(detail::is_near_unit(dual_quaternion<T>(a[i]).real) &&
                        detail::is_near_unit(dual_quaternion<T>(b[i]).real),
                    "quat::hand_eye: a motion's real part is not a unit quaternion");
    return detail::solve_hand_eye<T>(a, b, count, method);
}

/// hand_eye(motions_a, motions_b, method), or std::nullopt for motions it cannot calibrate from: lists of
/// different sizes, fewer than two motions, a NaN or infinite component, or a real part that is not
/// a unit quaternion (|q|^2 not within 1/4096 of 1). Motions that leave X undetermined are not bad
/// input: they give unique = false. Never asserts.
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
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_HAND_EYE_HPP_INCLUDED
