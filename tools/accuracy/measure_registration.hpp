// Registration rows of the main table: align_points and align_points_with_scale against
// Eigen::umeyama on the same point sets, and hand_eye (both methods; no GLM or Eigen counterpart).
// align_points' reference is the least-squares solution of the rounded sets computed here in
// `real`, with no quat code in its path: centroids in two passes, B = sum (t - ct)(s - cs)^T, the
// rotation as B's orthogonal polar factor by Newton's iteration (a different method from quat's
// q-method), the translation ct - c R cs and Umeyama's scale c = trace(R^T B) / sum |s - cs|^2.
// hand_eye's reference is the mount the exact motions were made from.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>
#include <quat/registration/hand_eye.hpp>

#include "measure.hpp"

namespace accuracy {
namespace registration {

// ---- targets, in eps of the row's type: about twice the maximum of the full run (g++ 12 -O3) ----
// Rotation: angle (rad); translation: |t - t_ref| / the largest |point| of the two sets; scale:
// relative. Before quat polished its eigenvector with one Newton step from B, the rotation's and
// translation's maxima came from the few sets of 4 to 7 points that are nearly planar or collinear
// (sigma1 / (sigma2 + sigma3) of B between 5 and 20, which --worst prints): 15 eps (float) and 19
// (double) against Eigen's 10 and 9. The scale's come from the longest sets (the rounding of the
// sums).
constexpr double target_rotation = 12;    // (a), (c): max 5.8 (float, scaled noisy sets)
constexpr double target_translation = 8;  // (a), (c): max 2.8
constexpr double target_scale = 12;       // all families: max 6.7 (double, far sets)
// (b), the sets far from the origin: rotation and translation, max 29.5 (double); with the scale,
// max 111 (double, rotation).
constexpr double target_far = 64;
constexpr double target_far_scaled = 256;
constexpr double target_hand_eye = 32;  // max 15.0 (float, daniilidis)

// ---- high-precision 3 x 3 matrices (rows)
// --------------------------------------------------------

using hm = std::array<hv, 3>;

inline real det3(const hm& a) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
}
/// The cofactor matrix: a^-T = cofactor(a) / det(a).
inline hm cofactor(const hm& a) {
    hm c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[i][j] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];
        }
    return c;
}
inline hm transposed(const hm& a) {
    hm t{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t[i][j] = a[j][i];
    return t;
}
inline hm product(const hm& a, const hm& b) {
    hm p{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            p[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return p;
}
inline hv matrix_times(const hm& a, const hv& v) {
    return {a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
            a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
            a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2]};
}
inline real frobenius(const hm& a) {
    real s = 0;
    for (const hv& row : a) s += row[0] * row[0] + row[1] * row[1] + row[2] * row[2];
    return r_sqrt(s);
}

/// The orthogonal factor U of b = U P (det b != 0; det U has det b's sign) by Newton's iteration
/// X <- (g X + X^-T / g) / 2 (Higham, "Computing the polar decomposition, with applications",
/// SIAM J. Sci. Stat. Comput. 7(4), 1986), scaled by g = sqrt(|X^-1| / |X|) (Frobenius) while the
/// steps are large and unscaled after, where it converges quadratically; three steps below 1e-15
/// leave it at real's precision.
inline hm polar_factor(hm x) {
    bool scaled = true;
    int small = 0;
    for (int iteration = 0; iteration < 200 && small < 3; ++iteration) {
        hm inverse_t = cofactor(x);
        const real d = det3(x);
        for (hv& row : inverse_t)
            for (real& e : row) e /= d;
        const real g = scaled ? r_sqrt(frobenius(inverse_t) / frobenius(x)) : real(1);
        real change = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const real next = (g * x[i][j] + inverse_t[i][j] / g) / 2;
                change = r_abs(next - x[i][j]) > change ? r_abs(next - x[i][j]) : change;
                x[i][j] = next;
            }
        scaled = change > real(1e-3);
        if (change < real(1e-15)) ++small;
    }
    return x;
}

/// Unit eigenvector of the symmetric m's eigenvalue of largest magnitude: the largest column of
/// m^(2^64), rescaled at each of the 64 squarings, so that nearly equal eigenvalues still separate.
inline hv dominant_direction(hm m) {
    for (int i = 0; i < 64; ++i) {
        m = product(m, m);
        const real size = frobenius(m);
        for (hv& row : m)
            for (real& e : row) e /= size;
    }
    hv best{0, 0, 0};
    for (int j = 0; j < 3; ++j) {
        const hv c{m[0][j], m[1][j], m[2][j]};
        if (norm(c) > norm(best)) best = c;
    }
    const real n = norm(best);
    return {best[0] / n, best[1] / n, best[2] / n};
}

/// The proper rotation R maximizing trace(R^T b) (Kabsch; Umeyama 1991): b's polar factor U when
/// det b > 0; otherwise U with the direction v of P = U^T b's smallest eigenvalue reversed,
/// R = U (I - 2 v v^T), v the dominant direction of adj(P) (P is symmetric positive definite).
inline hm best_rotation(const hm& b) {
    const hm u = polar_factor(b);
    if (det3(b) > 0) return u;
    const hv v = dominant_direction(cofactor(product(transposed(u), b)));
    hm flip{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) flip[i][j] = (i == j ? real(1) : real(0)) - 2 * v[i] * v[j];
    return product(u, flip);
}

/// Rotation matrix of q / |q|.
inline hm to_matrix(const hq& q_in) {
    const hq q = normalized(q_in);
    const real w = q[0], x = q[1], y = q[2], z = q[3];
    return {hv{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            hv{2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            hv{2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
}

/// Angle (rad) of the rotation a^T b, from its antisymmetric part (sin) and trace (cos): a b that
/// is orthogonal only to rounding (Eigen's matrix) is charged for its rotation, not its distortion.
inline real angle_between(const hm& a, const hm& b) {
    const hm m = product(transposed(a), b);
    const hv axis{m[2][1] - m[1][2], m[0][2] - m[2][0], m[1][0] - m[0][1]};
    return r_atan2(norm(axis) / 2, (m[0][0] + m[1][1] + m[2][2] - 1) / 2);
}

inline hv difference(const hv& a, const hv& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// ---- point sets and the reference fit
// ------------------------------------------------------------

template <class T>
struct point_set {
    std::vector<v3<T>> sources, targets;
    std::string what;  // for --worst
};

/// Centroid in two passes (the mean, then the mean of the points less it), so that long double
/// keeps the spread of points far from the origin.
template <class T>
hv centroid(const std::vector<v3<T>>& points) {
    hv c{0, 0, 0};
    const real n = real(points.size());
    for (int pass = 0; pass < 2; ++pass) {
        hv sum{0, 0, 0};
        for (const v3<T>& p : points)
            for (int k = 0; k < 3; ++k) sum[k] += real(p[k]) - c[k];
        for (int k = 0; k < 3; ++k) c[k] += sum[k] / n;
    }
    return c;
}

struct fit {
    hm rotation;
    hv translation;
    real scale;
    // sigma1 / (sigma2 + sigma3) from B's singular values (the third with det B's sign): the
    // rotation's sensitivity to rounding, for --worst.
    real conditioning;
};

/// The least-squares rigid motion (scaled = false) or similarity of the rounded set.
template <class T>
fit reference_fit(const point_set<T>& set, bool scaled) {
    const hv cs = centroid(set.sources), ct = centroid(set.targets);
    hm b{};
    real spread = 0;  // sum |s - cs|^2
    for (std::size_t i = 0; i < set.sources.size(); ++i) {
        const hv s = difference(widen(set.sources[i]), cs);
        const hv t = difference(widen(set.targets[i]), ct);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) b[r][c] += t[r] * s[c];
        spread += s[0] * s[0] + s[1] * s[1] + s[2] * s[2];
    }
    const hm rotation = best_rotation(b);
    real trace = 0;  // trace(R^T B)
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) trace += rotation[r][c] * b[r][c];
    const real scale = scaled ? trace / spread : real(1);
    const hv turned = matrix_times(rotation, cs);
    const hm p = product(transposed(rotation), b);  // symmetric at the optimum: eigenvalues sigma
    const hv v = dominant_direction(p);
    const hv pv = matrix_times(p, v);
    const real top = v[0] * pv[0] + v[1] * pv[1] + v[2] * pv[2];
    return {rotation,
            hv{ct[0] - scale * turned[0], ct[1] - scale * turned[1], ct[2] - scale * turned[2]},
            scale, top / (trace - top)};
}

/// The largest |p| over both sets: what the translation error is divided by (the translation of
/// sets far from the origin is as long as their offset, and T holds it only to eps times that).
template <class T>
real largest_point(const point_set<T>& set) {
    real m = 0;
    for (const auto* points : {&set.sources, &set.targets})
        for (const v3<T>& p : *points) m = norm(widen(p)) > m ? norm(widen(p)) : m;
    return m;
}

inline double gaussian(rng& g) {
    const double u1 = 1.0 - g.uniform();  // (0, 1]
    const double u2 = g.uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * 3.141592653589793 * u2);
}
inline hv gaussian_vector(rng& g, double scale) {
    return {real(scale * gaussian(g)), real(scale * gaussian(g)), real(scale * gaussian(g))};
}

/// A set of n (uniform in 4..64) sources o + N(0, 1) rounded to T and their targets
/// o + c R (s - o) + t + N(0, noise^2) computed in real from the rounded sources and rounded to T:
/// R uniform, t N(0, 1), c = 10^u with u uniform in [-0.3, 0.3] when scaled (else 1), o at
/// distance `offset` in a uniform direction.
template <class T>
point_set<T> make_set(rng& g, double offset, double noise, bool scaled) {
    const int n = 4 + int(g.uniform() * 61);
    const hm r = to_matrix(widen(g.unit_quaternion()));
    const hv t = gaussian_vector(g, 1);
    const real c = scaled ? real(std::pow(10.0, g.uniform(-0.3, 0.3))) : real(1);
    const v3<double> direction = g.unit_vector();
    const hv o{real(offset * direction[0]), real(offset * direction[1]),
               real(offset * direction[2])};
    point_set<T> set;
    for (int i = 0; i < n; ++i) {
        const hv p = gaussian_vector(g, 1);
        const v3<T> s{T(o[0] + p[0]), T(o[1] + p[1]), T(o[2] + p[2])};
        const hv image = matrix_times(r, difference(widen(s), o));
        const hv e = gaussian_vector(g, noise);
        set.sources.push_back(s);
        set.targets.push_back(v3<T>{T(o[0] + c * image[0] + t[0] + e[0]),
                                    T(o[1] + c * image[1] + t[1] + e[1]),
                                    T(o[2] + c * image[2] + t[2] + e[2])});
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "n = %d, scale %.6g", n, double(c));
    set.what = buf;
    return set;
}

// ---- the libraries' answers
// ----------------------------------------------------------------------

template <class T>
struct answer {
    hm rotation;
    hv translation;
    real scale;
};

template <class T>
answer<T> quat_answer(const point_set<T>& set, bool scaled) {
    std::vector<quat::vec3<T>> sources, targets;
    for (const v3<T>& p : set.sources) sources.push_back({p[0], p[1], p[2]});
    for (const v3<T>& p : set.targets) targets.push_back({p[0], p[1], p[2]});
    const quat::similarity_alignment<T> a =
        scaled ? quat::align_points_with_scale(targets, sources)
               : quat::similarity_alignment<T>{quat::align_points(targets, sources), T(1)};
    // The translation as a user reads it, translation_of's rounding included.
    const quat::vec3<T> t = quat::translation_of(a.motion);
    const quat::quaternion<T>& q = a.motion.real;
    return {to_matrix(hq{real(q.w), real(q.x), real(q.y), real(q.z)}), widen(v3<T>{t.x, t.y, t.z}),
            real(a.scale)};
}

/// Eigen::umeyama: the 4 x 4 [c R, t]; c from the columns' Frobenius norm, R = (c R) / c.
template <class T>
answer<T> eigen_answer(const point_set<T>& set, bool scaled) {
    const Eigen::Index n = Eigen::Index(set.sources.size());
    Eigen::Matrix<T, 3, Eigen::Dynamic> src(3, n), dst(3, n);
    for (Eigen::Index i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            src(k, i) = set.sources[std::size_t(i)][std::size_t(k)];
            dst(k, i) = set.targets[std::size_t(i)][std::size_t(k)];
        }
    const Eigen::Matrix<T, 4, 4> m = Eigen::umeyama(src, dst, scaled);
    hm cr{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) cr[i][j] = real(m(i, j));
    const real c = scaled ? frobenius(cr) / r_sqrt(real(3)) : real(1);
    for (hv& row : cr)
        for (real& e : row) e /= c;
    return {cr, hv{real(m(0, 3)), real(m(1, 3)), real(m(2, 3))}, c};
}

struct set_errors {
    error_stats rotation, translation, scale;
};

template <class T>
void add_errors(set_errors& e, const answer<T>& got, const fit& ref, const point_set<T>& set,
                const std::string& what) {
    if (e.rotation.add(in_eps<T>(angle_between(ref.rotation, got.rotation))))
        e.rotation.worst_case = what;
    const real size = largest_point(set);
    if (e.translation.add(in_eps<T>(norm(difference(got.translation, ref.translation)) / size)))
        e.translation.worst_case = what;
    if (e.scale.add(in_eps<T>(r_abs(got.scale - ref.scale) / ref.scale))) e.scale.worst_case = what;
}

// ---- hand_eye
// --------------------------------------------------------------------------------------

struct motion {
    hq rotation;  // unit
    hv translation;
};

/// The motion a dual quaternion of T stands for: real / |real|, 2 dual real* / |real|^2.
template <class T>
motion motion_of(const quat::dual_quaternion<T>& dq) {
    const hq r{real(dq.real.w), real(dq.real.x), real(dq.real.y), real(dq.real.z)};
    const hq d{real(dq.dual.w), real(dq.dual.x), real(dq.dual.y), real(dq.dual.z)};
    const hq p = mul(d, conj(r));
    const real k = 2 / dot4(r, r);
    return {normalized(r), hv{k * p[1], k * p[2], k * p[3]}};
}

/// The motion (q, t) as a dual quaternion (q, (0, t) q / 2) rounded once to T.
template <class T>
quat::dual_quaternion<T> rounded(const motion& m) {
    const hq d = mul(hq{0, m.translation[0], m.translation[1], m.translation[2]}, m.rotation);
    return {{T(m.rotation[0]), T(m.rotation[1]), T(m.rotation[2]), T(m.rotation[3])},
            {T(d[0] / 2), T(d[1] / 2), T(d[2] / 2), T(d[3] / 2)}};
}

inline hv rotated(const hq& q, const hv& v) {
    const hq image = mul(mul(q, hq{0, v[0], v[1], v[2]}), conj(q));
    return {image[1], image[2], image[3]};
}

/// Exact motions for a random mount X (rotation uniform, translation N(0, 0.1^2)): 3..16 hand
/// motions A (rotation uniform, translation N(0, 1)) rounded once to T, and B = X^-1 A X computed
/// in real from the rounded A and X and rounded once; the rotation-angle error of hand_eye's mount
/// against X, in eps.
template <class T>
error_stats measure_hand_eye(rng& g, int sets, quat::hand_eye_method method) {
    error_stats s;
    for (int k = 0; k < sets; ++k) {
        const motion x =
            motion_of(rounded<T>(motion{widen(g.unit_quaternion()), gaussian_vector(g, 0.1)}));
        const int count = 3 + int(g.uniform() * 14);
        std::vector<quat::dual_quaternion<T>> a, b;
        for (int i = 0; i < count; ++i) {
            a.push_back(rounded<T>(motion{widen(g.unit_quaternion()), gaussian_vector(g, 1)}));
            const motion ma = motion_of(a.back());
            // X^-1 A X: rotation qx* qa qx, translation Rx^T (Ra tx + ta - tx).
            const hq qb = mul(mul(conj(x.rotation), ma.rotation), x.rotation);
            const hv ra_tx = rotated(ma.rotation, x.translation);
            const hv tb =
                rotated(conj(x.rotation), hv{ra_tx[0] + ma.translation[0] - x.translation[0],
                                             ra_tx[1] + ma.translation[1] - x.translation[1],
                                             ra_tx[2] + ma.translation[2] - x.translation[2]});
            b.push_back(rounded<T>(motion{normalized(qb), tb}));
        }
        const quat::hand_eye_calibration<T> c = quat::hand_eye(a, b, method);
        const quat::quaternion<T>& q = c.mount.real;
        const real angle =
            rotation_angle_between(hq{real(q.w), real(q.x), real(q.y), real(q.z)}, x.rotation);
        if (s.add(in_eps<T>(angle))) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "set %d: %d motions", k, count);
            s.worst_case = buf;
        }
    }
    return s;
}

// ---- rows --------------------------------------------------------------------------------------

template <class T>
const char* scalar_name() {
    return sizeof(T) == sizeof(float) ? "float" : "double";
}

/// The registration rows in T: align_points and align_points_with_scale (quat and Eigen) on the
/// three families, then hand_eye. Sets per family: 3000 (--quick: 200); hand_eye 2000 (200).
template <class T>
void add_rows(std::vector<row>& rows, bool quick, std::uint64_t seed) {
    const int sets = quick ? 200 : 3000;
    const bool is_float = sizeof(T) == sizeof(float);
    // The offset D of (b): Eigen's one-pass means are off by about eps D, which shifts every
    // centred point alike and moves B by n (eps D)^2, a relative eps (D / spread)^2. Its rotation
    // error reaches 27 eps (RMS 3.9) at 1e4 in float and 346 (RMS 44) at 1e9 in double; at 1e3 and
    // 1e6 neither library lost anything.
    const double far = is_float ? 1e4 : 1e9;
    struct family {
        std::string name;
        double offset, noise;
    };
    const family families[3] = {
        {"4 … 64 points of spread 1, t ~ 1, noise 1e-3", 0, 1e-3},
        {std::string("the same moved ") + (is_float ? "1e4" : "1e9") + " from the origin", far,
         1e-3},
        {"4 … 64 points of spread 1, t ~ 1, exact (noise 0)", 0, 0},
    };
    const char* rotation_unit = "eps (rotation angle, rad)";
    const char* translation_unit = "eps (\\|Δt\\| / largest \\|p\\|)";
    const char* scale_unit = "eps (relative)";
    const auto make = [&](const std::string& op, const std::string& inputs, const char* unit,
                          double target) {
        return row{op,     inputs,       scalar_name<T>(), unit,
                   target, std::nullopt, std::nullopt,     std::nullopt};
    };
    for (const bool scaled : {false, true}) {
        const std::string op = scaled ? "align_points_with_scale" : "align_points";
        for (int f = 0; f < 3; ++f) {
            const family& fam = families[f];
            rng g{seed * 7919 + 40 + std::uint64_t(f) + (scaled ? 10 : 0)};
            set_errors quat_errors, eigen_errors;
            for (int k = 0; k < sets; ++k) {
                const point_set<T> set = make_set<T>(g, fam.offset, fam.noise, scaled);
                const fit ref = reference_fit(set, scaled);
                char conditioning[48];
                std::snprintf(conditioning, sizeof conditioning, ", σ1 / (σ2 + σ3) = %.3g",
                              double(ref.conditioning));
                const std::string what =
                    "set " + std::to_string(k) + ": " + set.what + conditioning;
                add_errors(quat_errors, quat_answer(set, scaled), ref, set, what);
                add_errors(eigen_errors, eigen_answer(set, scaled), ref, set, what);
            }
            const std::string inputs = fam.name + (scaled ? ", scale 0.5 … 2" : "");
            const double far_target = scaled ? target_far_scaled : target_far;
            const double rotation_target = fam.offset > 0 ? far_target : target_rotation;
            const double translation_target = fam.offset > 0 ? far_target : target_translation;
            row r = make(op + ": rotation", inputs, rotation_unit, rotation_target);
            r.quat = quat_errors.rotation;
            r.eigen = eigen_errors.rotation;
            rows.push_back(r);
            r = make(op + ": translation", inputs, translation_unit, translation_target);
            r.quat = quat_errors.translation;
            r.eigen = eigen_errors.translation;
            rows.push_back(r);
            if (scaled) {
                r = make(op + ": scale", inputs, scale_unit, target_scale);
                r.quat = quat_errors.scale;
                r.eigen = eigen_errors.scale;
                rows.push_back(r);
            }
        }
    }
    const int motions = quick ? 200 : 2000;
    for (const auto method :
         {quat::hand_eye_method::daniilidis, quat::hand_eye_method::rotation_first}) {
        const bool first = method == quat::hand_eye_method::rotation_first;
        rng g{seed * 7919 + 60};  // the same motions for both methods
        row r = make(first ? "hand_eye (rotation_first): mount rotation"
                           : "hand_eye (daniilidis): mount rotation",
                     "3 … 16 exact random motions, mount translation ~ 0.1", rotation_unit,
                     target_hand_eye);
        r.quat = measure_hand_eye<T>(g, motions, method);
        rows.push_back(r);
    }
}

}  // namespace registration
}  // namespace accuracy
