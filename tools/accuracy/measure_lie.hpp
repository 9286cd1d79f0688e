// Lie-group rows of the main table: so3 and se3 exp -> log round
// trips, so3::exp's value, and the Jacobians of lie/so3.hpp and lie/se3.hpp, quat only (GLM has
// none; Eigen
// has AngleAxis, measured beside the so3 round trip). Every reference is computed here in `real`
// with no quat code in its path: exp from the cosine and sine of the half angle, Jr = I - a W + b
// W^2
// with a = 2 sin^2(n/2) / n^2 (no cancellation) and b = (n - sin n) / n^3 summed from its Taylor
// series below n = 1, inverses by cofactors, SE(3)'s Q block by Barfoot's formula with the matrix
// products as written (T. Barfoot, "State Estimation for Robotics", 2017, eq. 7.86), and SE(3)'s
// log as rho = Jl(omega)^-1 t.
//
// Within a few eps of the angle pi the rotation vectors w and w - 2 pi w/|w| are the same rotation,
// and which one a log returns is decided by the rounding of a cosine near zero; there (pi - |w|
// below 64 eps of T) an answer is compared with both and the nearer counts.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>

#include "measure.hpp"

namespace accuracy {
namespace lie {

// ---- targets, in eps of the row's type, from the full run (g++ 12 -O2, 20000 inputs a family)
// ----
// Round trips: so3 max 1.84 (float and double, random w), se3 max 4.53 (double, tiny w, where the
// error is that of the translation's roundings relative to |xi| = |rho|).
constexpr double target_round_trip = 4;
constexpr double target_se3_round_trip = 8;
// so3::exp's value: the target of main.cpp's exp row (max 1.40, near pi).
constexpr double target_exp_value = 2;
// so3 Jacobians: the largest error is in float, near pi, where exp's Jacobian is formed from the
// rounded quaternion's half-angle sine; se3 Jacobians: in float, right_jacobian_inverse of random
// twists (docs/accuracy.md has the measured maxima).
constexpr double target_jacobian = 8;
constexpr double target_se3_jacobian = 12;

template <class T>
const char* lie_scalar_name() {
    return sizeof(T) == sizeof(float) ? "float" : "double";
}

// ---- high-precision 3 x 3 and 6 x 6 matrices
// -----------------------------------------------------

template <int N>
using hmat = std::array<std::array<real, N>, N>;
using hm3 = hmat<3>;
using hm6 = hmat<6>;

template <int N>
hmat<N> identity() {
    hmat<N> m{};
    for (int i = 0; i < N; ++i) m[i][i] = 1;
    return m;
}
inline hm3 skew(const hv& v) { return {{{0, -v[2], v[1]}, {v[2], 0, -v[0]}, {-v[1], v[0], 0}}}; }
inline hm3 operator*(const hm3& a, const hm3& b) {
    hm3 p{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            p[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    return p;
}
inline hm3 operator+(const hm3& a, const hm3& b) {
    hm3 s{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s[i][j] = a[i][j] + b[i][j];
    return s;
}
inline hm3 operator*(real k, const hm3& a) {
    hm3 s{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s[i][j] = k * a[i][j];
    return s;
}
inline hv operator*(const hm3& a, const hv& v) {
    return {a[0][0] * v[0] + a[0][1] * v[1] + a[0][2] * v[2],
            a[1][0] * v[0] + a[1][1] * v[1] + a[1][2] * v[2],
            a[2][0] * v[0] + a[2][1] * v[1] + a[2][2] * v[2]};
}
/// a^-1 = adjugate / det.
inline hm3 inverse(const hm3& a) {
    hm3 c{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            c[j][i] = a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1];  // transposed cofactor
        }
    const real det = a[0][0] * c[0][0] + a[0][1] * c[1][0] + a[0][2] * c[2][0];
    return (1 / det) * c;
}
/// [[a, b], [0, a]].
inline hm6 block_triangular(const hm3& a, const hm3& b) {
    hm6 m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            m[i][j] = a[i][j];
            m[i][j + 3] = b[i][j];
            m[i + 3][j + 3] = a[i][j];
        }
    return m;
}
inline hv negate(const hv& v) { return {-v[0], -v[1], -v[2]}; }
inline hv sum(const hv& a, const hv& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline hv difference(const hv& a, const hv& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

// ---- SO(3) and SE(3) in real --------------------------------------------------------------------

/// sum_k (-1)^k weight(k) n^(2k) / (2k + m)!, 30 terms: below n = 1 the terms fall faster than
/// 1/(2k)!, far past real's precision.
template <class Weight>
real series(real n, int m, Weight weight) {
    real factorial = 1;
    for (int i = 2; i <= m; ++i) factorial *= i;
    real power = 1, total = 0;
    for (int k = 0; k < 30; ++k) {
        total += weight(k) * power / factorial;
        power *= -n * n;
        factorial *= real(2 * k + m + 1) * real(2 * k + m + 2);
    }
    return total;
}
/// (1 - cos n) / n^2 = 2 sin^2(n/2) / n^2: no cancellation.
inline real coefficient_a(real n) {
    if (n == 0) return real(0.5);
    const real s = r_sin(n / 2);
    return 2 * s * s / (n * n);
}
/// (n - sin n) / n^3.
inline real coefficient_b(real n) {
    if (n < 1) return series(n, 3, [](int) { return real(1); });
    return (n - r_sin(n)) / (n * n * n);
}
/// Barfoot's (n^2 + 2 cos n - 2) / (2 n^4).
inline real coefficient_c2(real n) {
    if (n < 1) return series(n, 4, [](int) { return real(1); });
    return (n * n + 2 * r_cos(n) - 2) / (2 * n * n * n * n);
}
/// Barfoot's (2n - 3 sin n + n cos n) / (2 n^5).
inline real coefficient_c3(real n) {
    if (n < 1) return series(n, 5, [](int k) { return real(k + 1); });
    return (2 * n - 3 * r_sin(n) + n * r_cos(n)) / (2 * n * n * n * n * n);
}

/// SO(3)'s right Jacobian I - a W + b W^2 (left: I + a W + b W^2).
inline hm3 jacobian3(const hv& w, bool left) {
    const real n = norm(w);
    const hm3 W = skew(w);
    const real a = coefficient_a(n);
    return identity<3>() + (left ? a : -a) * W + coefficient_b(n) * (W * W);
}
/// Barfoot's Q(rho, omega), eq. 7.86, products as written.
inline hm3 barfoot_q(const hv& rho, const hv& omega) {
    const real n = norm(omega);
    const hm3 P = skew(rho), W = skew(omega);
    const hm3 WP = W * P, PW = P * W, WPW = W * P * W, WW = W * W;
    return real(0.5) * P + coefficient_b(n) * (WP + PW + WPW) +
           coefficient_c2(n) * (WW * P + P * WW + real(-3) * WPW) +
           coefficient_c3(n) * (WPW * W + W * WPW);
}
/// SE(3)'s right Jacobian Jl(-xi) = [[Jr(omega), Q(-rho, -omega)], [0, Jr(omega)]].
inline hm6 jacobian6(const hv& rho, const hv& omega) {
    return block_triangular(jacobian3(omega, false), barfoot_q(negate(rho), negate(omega)));
}
/// Its inverse [[A, -A B A], [0, A]], A = Jr(omega)^-1 by cofactors.
inline hm6 jacobian6_inverse(const hv& rho, const hv& omega) {
    const hm3 a = inverse(jacobian3(omega, false));
    return block_triangular(a, real(-1) * (a * barfoot_q(negate(rho), negate(omega)) * a));
}

/// The other rotation vector of the same rotation, w - 2 pi w/|w|.
inline hv other_branch(const hv& w) {
    const real n = norm(w), k = (n - 2 * r_pi()) / n;
    return {k * w[0], k * w[1], k * w[2]};
}
/// Within 64 eps of T of the angle pi (either side), where the branch of log is rounding's choice.
template <class T>
bool near_cut(const hv& w) {
    return r_abs(r_pi() - norm(w)) < 64 * real(std::numeric_limits<T>::epsilon());
}

/// exp(rho, omega) in real: rotation exp(omega), translation t = Jl(omega) rho, dual part t q / 2.
inline std::array<hq, 2> se3_exp(const hv& rho, const hv& omega) {
    const hq q = exp_map(omega);
    const hv t = jacobian3(omega, true) * rho;
    const hq d = mul(hq{0, t[0] / 2, t[1] / 2, t[2] / 2}, q);
    return {q, d};
}
/// log of a (near-)unit dual quaternion in real: omega = log of the rotation, t = 2 d r* / |r|^2
/// (either sign of the pair), rho = Jl(omega)^-1 t.
inline std::array<hv, 2> se3_log(const hq& r, const hq& d) {
    const hv omega = log_map(r);
    const hq p = mul(d, conj(r));
    const real n2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3];
    const hv t{2 * p[1] / n2, 2 * p[2] / n2, 2 * p[3] / n2};
    return {inverse(jacobian3(omega, true)) * t, omega};
}

// ---- quat's types to and from the tool's
// ---------------------------------------------------------

template <class T>
quat::vec3<T> to_quat(const v3<T>& v) {
    return {v[0], v[1], v[2]};
}
template <class T>
hv widen_vec(const quat::vec3<T>& v) {
    return {real(v.x), real(v.y), real(v.z)};
}
template <class T>
hq widen_quat(const quat::quaternion<T>& q) {
    return {real(q.w), real(q.x), real(q.y), real(q.z)};
}
/// max |got - ref| / max |ref|, over the elements.
template <class T, int N, class Reference>
real matrix_error(const quat::matrix<T, N, N>& got, const Reference& ref) {
    real difference = 0, size = 0;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            const real d = r_abs(real(got(i, j)) - ref[i][j]);
            difference = d > difference ? d : difference;
            size = r_abs(ref[i][j]) > size ? r_abs(ref[i][j]) : size;
        }
    return difference / size;
}
inline real smaller(real a, real b) { return a < b ? a : b; }

// ---- input families
// -------------------------------------------------------------------------------

struct family {
    const char* name;
    int kind;  // 0 random angle in [0, pi), 1 tiny, 2 near pi
};
constexpr family families[3] = {{"random w, \\|w\\| ∈ [0, π)", 0},
                                {"tiny w, \\|w\\| 1e-12 … 1e-6", 1},
                                {"near π, \\|w\\| π − 1e-3 … π − 1e-8", 2}};

/// Rotation vectors of the family, random axes, rounded to T.
template <class T>
std::vector<v3<T>> rotation_vectors_of(rng& g, int kind, int n) {
    const double pi = 3.141592653589793;
    std::vector<v3<T>> out;
    for (int i = 0; i < n; ++i) {
        const double angle = kind == 0   ? g.uniform(0, pi)
                             : kind == 1 ? std::pow(10.0, g.uniform(-12, -6))
                                         : pi - std::pow(10.0, g.uniform(-8, -3));
        const v3<double> a = g.unit_vector();
        out.push_back(narrow<T>(v3<double>{angle * a[0], angle * a[1], angle * a[2]}));
    }
    return out;
}

/// Eigen's rotation-vector round trip: AngleAxis(|w|, w/|w|) -> Quaternion -> AngleAxis.
template <class T>
hv eigen_round_trip(const v3<T>& w) {
    const Eigen::Matrix<T, 3, 1> v(w[0], w[1], w[2]);
    const T n = v.norm();
    const Eigen::Quaternion<T> q(Eigen::AngleAxis<T>(n, v / n));
    const Eigen::AngleAxis<T> back(q);
    const Eigen::Matrix<T, 3, 1> r = back.angle() * back.axis();
    return {real(r[0]), real(r[1]), real(r[2])};
}

/// |got - w| / |w|, or to the other branch where that is rounding's choice.
template <class T>
real round_trip_error(const hv& got, const hv& w) {
    real e = norm(difference(got, w)) / norm(w);
    if (near_cut<T>(w)) e = smaller(e, norm(difference(got, other_branch(w))) / norm(w));
    return e;
}

/// A row of quat's figures only (GLM and Eigen have no Lie-group Jacobians).
template <class T>
row lie_row(const std::string& op, const std::string& inputs, const char* unit, double target) {
    return {op,     inputs,       lie_scalar_name<T>(), unit,
            target, std::nullopt, std::nullopt,         std::nullopt};
}

template <class T>
void add_so3_rows(std::vector<row>& rows, bool quick, std::uint64_t seed) {
    const int count = quick ? 500 : 20000;
    const char* jacobian_unit = "eps (max element error / largest element)";
    const auto make = lie_row<T>;
    for (const family& fam : families) {
        rng g{seed * 7919 + 70 + std::uint64_t(fam.kind)};
        const std::vector<v3<T>> ws = rotation_vectors_of<T>(g, fam.kind, count);
        error_stats round_trip, eigen_trip, value, jr, jr_inverse, exp_jacobian, log_jacobian,
            minus_y, minus_x;
        for (const v3<T>& w_in : ws) {
            const quat::vec3<T> w = to_quat(w_in);
            const hv wide = widen(w_in);
            const std::string what = "w = " + describe(w_in);
            // Round trip and value.
            const quat::quaternion<T> q = quat::so3::exp(w);
            if (round_trip.add(in_eps<T>(round_trip_error<T>(widen_vec(quat::so3::log(q)), wide))))
                round_trip.worst_case = what;
            if (eigen_trip.add(in_eps<T>(round_trip_error<T>(eigen_round_trip(w_in), wide))))
                eigen_trip.worst_case = what;
            const hq ref = exp_map(wide), got = widen_quat(q);
            const real vector_error = norm(hv{got[1] - ref[1], got[2] - ref[2], got[3] - ref[3]}) /
                                      norm(hv{ref[1], ref[2], ref[3]});
            const real scalar_error = r_abs(got[0] - ref[0]);
            if (value.add(in_eps<T>(vector_error > scalar_error ? vector_error : scalar_error)))
                value.worst_case = what;
            // Jacobians at w.
            const hm3 jr_ref = jacobian3(wide, false);
            if (jr.add(in_eps<T>(matrix_error(quat::so3::right_jacobian(w), jr_ref))))
                jr.worst_case = what;
            if (jr_inverse.add(
                    in_eps<T>(matrix_error(quat::so3::right_jacobian_inverse(w), inverse(jr_ref)))))
                jr_inverse.worst_case = what;
            quat::matrix3<T> j{};
            static_cast<void>(quat::so3::exp(w, &j));
            if (exp_jacobian.add(in_eps<T>(matrix_error(j, jr_ref))))
                exp_jacobian.worst_case = what;
            // log's Jacobian at the best T quaternion of exp(w), against Jr^-1 at its exact log.
            const q4<T> rounded = narrow<T>(ref);
            const quat::quaternion<T> qr{rounded[0], rounded[1], rounded[2], rounded[3]};
            static_cast<void>(quat::so3::log(qr, &j));
            const hv log_ref = log_map(widen(rounded));
            real e = matrix_error(j, inverse(jacobian3(log_ref, false)));
            if (near_cut<T>(log_ref))
                e = smaller(e, matrix_error(j, inverse(jacobian3(other_branch(log_ref), false))));
            if (log_jacobian.add(in_eps<T>(e))) log_jacobian.worst_case = describe(rounded);
            // minus(y, x) with y = x exp(w) rounded once; the reference at the exact log(x^-1 y).
            const q4<T> x4 = g.template unit_quaternion<T>();
            const q4<T> y4 = narrow<T>(mul(widen(x4), ref));
            const quat::quaternion<T> x{x4[0], x4[1], x4[2], x4[3]}, y{y4[0], y4[1], y4[2], y4[3]};
            quat::matrix3<T> dy{}, dx{};
            static_cast<void>(quat::so3::minus(y, x, &dy, &dx));
            const hv t = log_map(mul(conj(widen(x4)), widen(y4)));
            real ey = matrix_error(dy, inverse(jacobian3(t, false)));
            real ex = matrix_error(dx, real(-1) * inverse(jacobian3(t, true)));
            if (near_cut<T>(t)) {
                const hv u = other_branch(t);
                ey = smaller(ey, matrix_error(dy, inverse(jacobian3(u, false))));
                ex = smaller(ex, matrix_error(dx, real(-1) * inverse(jacobian3(u, true))));
            }
            const std::string pair = "x = " + describe(x4) + ", y = " + describe(y4);
            if (minus_y.add(in_eps<T>(ey))) minus_y.worst_case = pair;
            if (minus_x.add(in_eps<T>(ex))) minus_x.worst_case = pair;
        }
        const std::string inputs = fam.name;
        const std::string minus_inputs = std::string("y = x exp(w), x random, ") + fam.name;
        row r = make("so3: log(exp(w)) round trip", inputs, "eps (\\|Δw\\| / \\|w\\|)",
                     target_round_trip);
        r.quat = round_trip;
        r.eigen = eigen_trip;
        rows.push_back(r);
        r = make("so3::exp: value", inputs, "eps (w abs., vector rel.)", target_exp_value);
        r.quat = value;
        rows.push_back(r);
        const std::pair<const char*, error_stats*> jacobians[4] = {
            {"so3::right_jacobian", &jr},
            {"so3::right_jacobian_inverse", &jr_inverse},
            {"so3::exp: Jacobian (Jr)", &exp_jacobian},
            {"so3::log: Jacobian (Jr⁻¹)", &log_jacobian}};
        for (const auto& [op, stats] : jacobians) {
            r = make(op, inputs, jacobian_unit, target_jacobian);
            r.quat = *stats;
            rows.push_back(r);
        }
        r = make("so3::minus(y, x): d/dy (Jr⁻¹)", minus_inputs, jacobian_unit, target_jacobian);
        r.quat = minus_y;
        rows.push_back(r);
        r = make("so3::minus(y, x): d/dx (−Jl⁻¹)", minus_inputs, jacobian_unit, target_jacobian);
        r.quat = minus_x;
        rows.push_back(r);
    }
}

template <class T>
void add_se3_rows(std::vector<row>& rows, bool quick, std::uint64_t seed) {
    const int count = quick ? 500 : 20000;
    const char* jacobian_unit = "eps (max element error / largest element)";
    const auto make = lie_row<T>;
    for (const family& fam : families) {
        rng g{seed * 7919 + 80 + std::uint64_t(fam.kind)};
        const std::vector<v3<T>> ws = rotation_vectors_of<T>(g, fam.kind, count);
        error_stats round_trip, jr, jr_inverse, exp_jacobian, log_jacobian;
        for (const v3<T>& w_in : ws) {
            const v3<double> direction = g.unit_vector();
            const double length = g.uniform(0.5, 2);
            const v3<T> rho_in = narrow<T>(
                v3<double>{length * direction[0], length * direction[1], length * direction[2]});
            const quat::se3::twist<T> xi{to_quat(rho_in), to_quat(w_in)};
            const hv rho = widen(rho_in), omega = widen(w_in);
            const std::string what = "rho = " + describe(rho_in) + ", omega = " + describe(w_in);
            // Round trip: |log(exp(xi)) - xi| / |xi| (6-vector norms); near the cut also against
            // the other branch, (Jl(omega')^-1 Jl(omega) rho, omega').
            const quat::se3::twist<T> back = quat::se3::log(quat::se3::exp(xi));
            const hv back_rho = widen_vec(back.linear), back_omega = widen_vec(back.angular);
            const real size = r_sqrt(norm(rho) * norm(rho) + norm(omega) * norm(omega));
            const auto twist_error = [&](const hv& r, const hv& o) {
                const real a = norm(difference(back_rho, r)), b = norm(difference(back_omega, o));
                return r_sqrt(a * a + b * b) / size;
            };
            real e = twist_error(rho, omega);
            if (near_cut<T>(omega)) {
                const hv other = other_branch(omega);
                const hv other_rho =
                    inverse(jacobian3(other, true)) * (jacobian3(omega, true) * rho);
                e = smaller(e, twist_error(other_rho, other));
            }
            if (round_trip.add(in_eps<T>(e))) round_trip.worst_case = what;
            // Jacobians at xi.
            const hm6 jr_ref = jacobian6(rho, omega);
            if (jr.add(in_eps<T>(matrix_error(quat::se3::right_jacobian(xi), jr_ref))))
                jr.worst_case = what;
            if (jr_inverse.add(in_eps<T>(matrix_error(quat::se3::right_jacobian_inverse(xi),
                                                      jacobian6_inverse(rho, omega)))))
                jr_inverse.worst_case = what;
            quat::matrix6<T> j{};
            static_cast<void>(quat::se3::exp(xi, &j));
            if (exp_jacobian.add(in_eps<T>(matrix_error(j, jr_ref))))
                exp_jacobian.worst_case = what;
            // log's Jacobian at the best T dual quaternion of exp(xi), against Jr^-1 at its exact
            // log.
            const std::array<hq, 2> motion = se3_exp(rho, omega);
            const q4<T> r4 = narrow<T>(motion[0]), d4 = narrow<T>(motion[1]);
            const quat::dual_quaternion<T> x{{r4[0], r4[1], r4[2], r4[3]},
                                             {d4[0], d4[1], d4[2], d4[3]}};
            static_cast<void>(quat::se3::log(x, &j));
            const std::array<hv, 2> log_ref = se3_log(widen(r4), widen(d4));
            e = matrix_error(j, jacobian6_inverse(log_ref[0], log_ref[1]));
            if (near_cut<T>(log_ref[1])) {
                const hv other = other_branch(log_ref[1]);
                const hv other_rho =
                    inverse(jacobian3(other, true)) * (jacobian3(log_ref[1], true) * log_ref[0]);
                e = smaller(e, matrix_error(j, jacobian6_inverse(other_rho, other)));
            }
            if (log_jacobian.add(in_eps<T>(e)))
                log_jacobian.worst_case = "real " + describe(r4) + ", dual " + describe(d4);
        }
        const std::string inputs = std::string(fam.name) + ", \\|ρ\\| 0.5 … 2";
        row r = make("se3: log(exp(ξ)) round trip", inputs, "eps (\\|Δξ\\| / \\|ξ\\|)",
                     target_se3_round_trip);
        r.quat = round_trip;
        rows.push_back(r);
        const std::pair<const char*, error_stats*> jacobians[4] = {
            {"se3::right_jacobian", &jr},
            {"se3::right_jacobian_inverse", &jr_inverse},
            {"se3::exp: Jacobian (Jr)", &exp_jacobian},
            {"se3::log: Jacobian (Jr⁻¹)", &log_jacobian}};
        for (const auto& [op, stats] : jacobians) {
            r = make(op, inputs, jacobian_unit, target_se3_jacobian);
            r.quat = *stats;
            rows.push_back(r);
        }
    }
}

/// The so3 rows, then the se3 rows, of one scalar type.
template <class T>
void add_rows(std::vector<row>& rows, bool quick, std::uint64_t seed) {
    add_so3_rows<T>(rows, quick, seed);
    add_se3_rows<T>(rows, quick, seed);
}

}  // namespace lie
}  // namespace accuracy
