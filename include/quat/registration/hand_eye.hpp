// Hand-eye calibration: the fixed rigid motion X between a robot's hand (gripper, rig) and a sensor
// mounted on it (the eye: camera, IMU) from motions measured by both, A_i X = X B_i, by
// Daniilidis's dual-quaternion method ("Hand-eye calibration using dual quaternions", The
// International Journal of Robotics Research 18(3), 1999): rotation and translation together, from
// the null space of one stacked matrix.
#ifndef QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED
#define QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../detail/power_of_two.hpp"
#include "../fitting/detail/symmetric_eigen.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"

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

#include "../detail/isa_namespace.inc"
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

/// The normal matrix sum R_i^T R_i of the rotation rows (daniilidis_block of the real parts),
/// decomposed; its eigenvalues in the matrix's own units (not scaled).
template <class T, class A, class B>
[[nodiscard]] constexpr symmetric_eigen4<T> rotation_rows_eigen(const A* a_motions,
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
    const T largest = scale_to_unit(m);
    symmetric_eigen4<T> eigen = symmetric_eigen(m);
    if (largest > T(0))
        for (T& value : eigen.values) value = value * largest;
    return eigen;
}

/// The spread of one side's turning axes: sqrt(floor / (e2 + e3)), at most 1, for e1 >= e2 >= e3
/// the eigenvalues of W = sum v_i v_i^T over its rotations' vector parts v_i = sin(angle_i / 2)
/// axis_i. e2 + e3 is what the turns about axes other than the main one add; the floor is the
/// rounding of the v_i (a few epsilon each, absolute, whatever the angle) and of forming and
/// decomposing W. So exact motions about one axis give 1 however small their turns, where the
/// axes' own directions are as uncertain as epsilon / angle. turns: e1 above the floor.
template <class T>
struct axis_spread {
    T ratio;
    bool turns;
};

template <class T>
[[nodiscard]] constexpr axis_spread<T> spread_of(T (&w)[3][3], T motions) noexcept {
    const T largest = scale_to_unit(w);
    const symmetric_eigen_n<3, T> e = jacobi_eigen<3>(w);
    const T eps = epsilon<T>();
    const T first = e.values[0] * largest, rest = (e.values[1] + e.values[2]) * largest;
    const T floor = T(16) * eps * first + T(64) * motions * eps * eps;
    return {sqrt(floor / max(rest, floor)), first > floor};
}

/// hand_eye_calibration::ambiguity, and how many directions of X's rotation the rotation rows
/// fix (3 where X is unique). Of the rows: sqrt(noise / second-smallest eigenvalue), the noise
/// their smallest eigenvalue or a floor of rounding (forming and decomposing the matrix, and the
/// motions' components themselves); the fixed directions are the eigenvectors whose eigenvalues
/// exceed noise / limit^4: the free solution inverts the rows there, and a direction only a few
/// times above the noise would carry that noise into X's translation. Then at least the spread
/// of either side's axes: where one side turns about one axis exactly, noise on the other can
/// make the rows look determined.
template <class T>
struct rotation_fit {
    T ambiguity;
    std::size_t fixed;
};

/// hand_eye_calibration::unique's threshold on the ambiguity.
template <class T>
[[nodiscard]] constexpr T ambiguity_limit() noexcept {
    return T(1) / T(4);
}

template <class T>
[[nodiscard]] constexpr rotation_fit<T> fit_of(const symmetric_eigen4<T>& rows,
                                               const axis_spread<T>& a, const axis_spread<T>& b,
                                               T motions) noexcept {
    const T eps = epsilon<T>();
    const T floor = T(16) * eps * rows.values[0] + T(64) * motions * eps * eps;
    const T noise = max(rows.values[3], floor);
    const T limit = ambiguity_limit<T>();
    rotation_fit<T> fit{max(sqrt(noise / max(rows.values[2], floor)), max(a.ratio, b.ratio)), 0};
    while (fit.fixed < 3 && rows.values[fit.fixed] * limit * limit * limit * limit > noise)
        ++fit.fixed;
    if (!(fit.ambiguity < limit) && fit.fixed > 2) fit.fixed = 2;
    // A side that does not turn leaves the rotation to the translations, t_Ai = R_X t_Bi.
    if (!a.turns || !b.turns) fit.fixed = 0;
    return fit;
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

/// The rotation first, from the rotation rows alone (rows: rotation_rows_eigen; the eigenvector
/// of its smallest eigenvalue), then the translation t of X by linear least squares given it:
/// (R_Ai - I) t = R_X t_Bi - t_Ai for every i (Tsai and Lenz's second step, IEEE Trans. Robotics
/// and Automation 5(3), 1989), solved through the eigen-decomposition of the 3 x 3 normal matrix,
/// its eigenvalues below 64 epsilon of the largest left out (rounding where the axes are nearly
/// parallel). Translations divided by p; for motions that determine X.
template <class T, class A, class B>
[[nodiscard]] constexpr dual_quaternion<T> rotation_first_mount(
    const A* a_motions, const B* b_motions, std::size_t count, T p,
    const symmetric_eigen4<T>& rows) noexcept {
    const quaternion<T> q = normalize(rows.vectors[3]);
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

/// X where the rotation rows leave its rotation free in 4 - fixed directions (the eigenvectors of
/// rows' smallest eigenvalues, the space N): from Daniilidis's full system T (q, q') = 0, q' is
/// eliminated by least squares over the directions the rotation rows fix, q' = -M^+ G q with
/// M = sum R_i^T R_i inverted there only and G = sum R_i^T D_i; then q in N is the unit vector of
/// least remaining residual q^T (H - G^T M^+ G) q, H = sum D_i^T D_i. So the translations settle
/// the rotation about a common axis where they can (pure translations: t_Ai = R_X t_Bi, the
/// whole rotation), and q', having no part in N, holds the least translation: none along the
/// common axis, none at all without turns. Translations divided by p.
template <class T, class A, class B>
[[nodiscard]] constexpr dual_quaternion<T> free_mount(const A* a_motions, const B* b_motions,
                                                      std::size_t count, T p,
                                                      const symmetric_eigen4<T>& rows,
                                                      std::size_t fixed) noexcept {
    T g[4][4] = {}, h[4][4] = {};
    for (std::size_t i = 0; i < count; ++i) {
        const motion_pair<T> pair = matched_pair(a_motions[i], b_motions[i], p);
        T r[3][4] = {}, d[3][4] = {};
        daniilidis_block(pair.a.real, pair.b.real, r);
        daniilidis_block(pair.a.dual, pair.b.dual, d);
        for (int x = 0; x < 4; ++x)
            for (int y = 0; y < 4; ++y)
                for (int k = 0; k < 3; ++k) {
                    g[x][y] += r[k][x] * d[k][y];
                    h[x][y] += d[k][x] * d[k][y];
                }
    }
    // w_k = G^T v_k over the fixed directions v_k, so that G^T M^+ G = sum w_k w_k^T / lambda_k.
    quaternion<T> w[3] = {};
    for (std::size_t k = 0; k < fixed; ++k) {
        const quaternion<T>& u = rows.vectors[k];
        const T v[4] = {u.w, u.x, u.y, u.z};
        T column[4] = {};
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) column[y] += g[x][y] * v[x];
        w[k] = {column[0], column[1], column[2], column[3]};
    }
    const auto reduced = [&](const quaternion<T>& u, const quaternion<T>& v) {
        const T uu[4] = {u.w, u.x, u.y, u.z}, vv[4] = {v.w, v.x, v.y, v.z};
        T sum(0);
        for (int x = 0; x < 4; ++x)
            for (int y = 0; y < 4; ++y) sum += uu[x] * h[x][y] * vv[y];
        for (std::size_t k = 0; k < fixed; ++k) sum -= dot(w[k], u) * dot(w[k], v) / rows.values[k];
        return sum;
    };
    // The reduced matrix in N's coordinates; the unused coordinates get an eigenvalue above any
    // of N's, so that the smallest eigenvector lies in N.
    const std::size_t free = 4 - fixed;
    T c[4][4] = {};
    for (std::size_t x = 0; x < free; ++x)
        for (std::size_t y = 0; y < free; ++y)
            c[x][y] = reduced(rows.vectors[fixed + x], rows.vectors[fixed + y]);
    scale_to_unit(c);
    for (std::size_t x = free; x < 4; ++x) c[x][x] = T(8);
    const symmetric_eigen_n<4, T> e = jacobi_eigen<4>(c);
    quaternion<T> q{T(0), T(0), T(0), T(0)};
    for (std::size_t x = 0; x < free; ++x) q += rows.vectors[fixed + x] * e.vectors[3][x];
    q = normalize(q);
    quaternion<T> dual{T(0), T(0), T(0), T(0)};
    for (std::size_t k = 0; k < fixed; ++k)
        dual -= rows.vectors[k] * (dot(w[k], q) / rows.values[k]);
    return {q, dual};
}

/// The documented NaN result: NaN in the mount, the residuals and the ambiguity; not unique.
template <class T>
[[nodiscard]] constexpr hand_eye_calibration<T> nan_calibration() noexcept {
    const T nan = quiet_nan<T>();
    return {{nan_quaternion<T>(), nan_quaternion<T>()}, nan, nan, false, nan};
}

template <class T, class A, class B>
[[nodiscard]] constexpr hand_eye_calibration<T> solve_hand_eye(const A* a_motions,
                                                               const B* b_motions,
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
    return {best, sqrt(angles / n), sqrt(offsets / n) * p, unique, fit.ambiguity};
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
/// solved here.
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
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_REGISTRATION_HAND_EYE_HPP_INCLUDED
