// The closed-form hand-eye solvers behind registration/hand_eye.hpp: Daniilidis's joint
// dual-quaternion solution, the rotation-first solution, the free solution where the motions leave
// X undetermined, and the measures of how well the motions fix X. Each takes the motions as two
// indexable sequences (pointers, or the pose views of registration/detail/hand_eye_poses.hpp) of
// values convertible to dual_quaternion<T>.
#ifndef QUAT_REGISTRATION_DETAIL_HAND_EYE_SOLVERS_HPP_INCLUDED
#define QUAT_REGISTRATION_DETAIL_HAND_EYE_SOLVERS_HPP_INCLUDED

#include <cstddef>

#include "../../config.hpp"
#include "../../detail/math.hpp"
#include "../../fitting/detail/symmetric_eigen.hpp"
#include "../../quaternion.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../../rotation_matrix.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
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
[[nodiscard]] constexpr symmetric_eigen4<T> rotation_rows_eigen(const A& a_motions,
                                                                const B& b_motions,
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
[[nodiscard]] constexpr dual_quaternion<T> daniilidis_mount(const A& a_motions, const B& b_motions,
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
    const A& a_motions, const B& b_motions, std::size_t count, T p,
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
[[nodiscard]] constexpr dual_quaternion<T> free_mount(const A& a_motions, const B& b_motions,
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

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_REGISTRATION_DETAIL_HAND_EYE_SOLVERS_HPP_INCLUDED
