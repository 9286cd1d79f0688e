// `quat_accuracy --rigid`: the error of quat's rigid motions (rigid/dual_quaternion.hpp,
// rigid/homogeneous_matrix.hpp, rigid/sclerp.hpp, rigid/blend.hpp, batch/rigid_motions.hpp) in
// float and double against long
// double references, in units of the type's eps, on random inputs (fixed seed) and edge-case
// families; then the constant speed of sclerp against dual-quaternion linear blending (quat's
// blend, GLM's lerp + normalize), in radians. Motions are compared through their 4x4 matrices as
// tests/support/rigid_reference.hpp builds them in long double from a dual quaternion's components
// (the rotation of real / |real|, the translation 2 dual real* / |real|^2), so the reference is
// the motion the rounded inputs and outputs stand for, with no quat code in its path (blend is
// compared component by component with its definition evaluated in the tool's high precision).
// Samples (--quick in brackets): 20000 [1000] per sclerp family (the long double logm is the slow
// part), 1000 [20] compose chains, 10000 [200] speed pairs at 65 values of t, 100000 [2000] for
// the rest. Exit status 1 when a row's maximum exceeds its bound.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#ifndef GLM_ENABLE_EXPERIMENTAL
#define GLM_ENABLE_EXPERIMENTAL
#endif
#include <glm/gtx/dual_quaternion.hpp>

#include <quat/quat.hpp>

#include "measure.hpp"
#include "support/rigid_reference.hpp"

namespace accuracy {
namespace rigid {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::matrix4;
using quat::test::max_abs;
using quat::test::max_difference;
using quat::test::reference_matrix;

template <class T>
constexpr long double eps = static_cast<long double>(std::numeric_limits<T>::epsilon());

// ---- bounds, in eps of the row's type: about twice the maximum of the full run (g++ 12 -O3) -----

// The error is relative to max(1, max |entry|) of a, b and the result: the computation passes
// through the translations of a and b, so a path that comes near the origin between two far
// motions has the error of those sizes, not of its own small translation there.
constexpr double bound_sclerp = 12;
constexpr double bound_transform = 8;           // per component / (1 + |p| + |t|); max 3.2
constexpr double bound_to_homogeneous = 5;      // per entry / max(1, max |entry|); max 2.1
constexpr double bound_to_dual_quaternion = 6;  // the motion back, per entry; max 2.6
constexpr double bound_product = 10;            // a * b, per entry; max 4.9
constexpr double bound_compose = 128;           // 1024 factors, per entry; max 58
constexpr double bound_blend = 12;              // per component / max(1, max |component|); max 5.8
// Constant speed of sclerp: |angle(t) - t angle| in rad (max 3.9 eps) and |slide(t) - t slide| in
// length units with translations of scale 2 (max 47 eps).
constexpr double bound_speed_turn = 8;
constexpr double bound_speed_slide = 96;

// ---- statistics and table -----------------------------------------------------------------------

/// Error statistics in eps, and the relative scale (the error's denominator) at the maximum.
struct scaled_stats {
    error_stats error;
    long double scale_at_max = 0;

    template <class Describe>
    void add(long double difference, long double scale, long double epsilon, Describe describe) {
        if (error.add(double(difference / scale / epsilon))) {
            scale_at_max = scale;
            error.worst_case = describe();
        }
    }
};

struct rigid_row {
    std::string operation;
    std::string inputs;
    std::string scalar;
    std::string scale;  // what the error is divided by
    double bound;       // eps
    scaled_stats stats;

    [[nodiscard]] bool exceeded() const { return !(stats.error.max <= bound); }
};

template <class T>
const char* scalar_name() {
    return sizeof(T) == sizeof(float) ? "float" : "double";
}

template <class T>
std::string describe_scalar(T x) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", std::numeric_limits<T>::max_digits10, double(x));
    return buf;
}
template <class T>
std::string describe(const quaternion<T>& q) {
    char buf[160];
    const int digits = std::numeric_limits<T>::max_digits10;
    std::snprintf(buf, sizeof buf, "(%.*g, %.*g, %.*g, %.*g)", digits, double(q.w), digits,
                  double(q.x), digits, double(q.y), digits, double(q.z));
    return buf;
}
template <class T>
std::string describe(const dual_quaternion<T>& dq) {
    return describe(dq.real) + " + ε" + describe(dq.dual);
}
template <class T>
std::string describe(const vec3<T>& v) {
    char buf[128];
    const int digits = std::numeric_limits<T>::max_digits10;
    std::snprintf(buf, sizeof buf, "(%.*g, %.*g, %.*g)", digits, double(v.x), digits, double(v.y),
                  digits, double(v.z));
    return buf;
}

// ---- inputs
// --------------------------------------------------------------------------------------

inline double gaussian(rng& g) {
    const double u1 = 1.0 - g.uniform();  // (0, 1]
    const double u2 = g.uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * 3.141592653589793 * u2);
}

template <class T>
vec3<T> gaussian_vector(rng& g, double scale) {
    const double x = gaussian(g), y = gaussian(g), z = gaussian(g);
    return {T(scale * x), T(scale * y), T(scale * z)};
}

template <class T>
quaternion<T> to_quat(const q4<T>& q) {
    return {q[0], q[1], q[2], q[3]};
}
template <class T>
hq wide(const quaternion<T>& q) {
    return {real(q.w), real(q.x), real(q.y), real(q.z)};
}

/// Rotation uniform (rounded once from high precision), translation Gaussian of scale `reach`.
template <class T>
dual_quaternion<T> random_motion(rng& g, double reach = 2) {
    const quaternion<T> q = to_quat(g.template unit_quaternion<T>());
    return quat::to_dual_quaternion(q, gaussian_vector<T>(g, reach));
}

/// q followed (in q's frame) by a turn of `angle` about a random axis, in high precision, rounded
/// once to T.
template <class T>
quaternion<T> turned(rng& g, const quaternion<T>& q, real angle) {
    const hv axis = widen(g.unit_vector());
    const hq turn = exp_map(hv{angle * axis[0], angle * axis[1], angle * axis[2]});
    return to_quat(narrow<T>(normalized(mul(wide(q), turn))));
}

/// 10^-k in the reference type.
inline real power_of_ten(int k) {
    real x = 1;
    for (int i = 0; i < k; ++i) x /= 10;
    return x;
}

// ---- high-precision dual quaternions (row 5 and 6) ---------------------------------------------

struct hdq {
    hq r, d;
};

template <class T>
hdq wide(const dual_quaternion<T>& dq) {
    return {wide(dq.real), wide(dq.dual)};
}
inline hq add(const hq& a, const hq& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]};
}
inline hq scaled(const hq& a, real s) { return {s * a[0], s * a[1], s * a[2], s * a[3]}; }
inline hdq dq_mul(const hdq& a, const hdq& b) {
    return {mul(a.r, b.r), add(mul(a.r, b.d), mul(a.d, b.r))};
}
inline hdq dq_inverse(const hdq& a) {
    const real n2 = dot4(a.r, a.r);
    return {scaled(conj(a.r), 1 / n2), scaled(conj(a.d), 1 / n2)};
}
/// Translation 2 dual real* / |real|^2 (vector part).
inline hv translation(const hdq& a) {
    const hq p = mul(a.d, conj(a.r));
    const real k = 2 / dot4(a.r, a.r);
    return {k * p[1], k * p[2], k * p[3]};
}

/// Turn angle in [0, pi] and slide along the axis of the motion a (the screw's angle and
/// displacement); the slide is 0 when the rotation is exactly the identity.
struct screw_parameters {
    real angle;
    real slide;
};
inline screw_parameters screw_of(hdq a) {
    if (a.r[0] < 0) a = {negated(a.r), negated(a.d)};
    const hv v{a.r[1], a.r[2], a.r[3]};
    const real s = norm(v);
    const real angle = 2 * r_atan2(s, a.r[0]);
    if (s == 0) return {angle, 0};
    const hv t = translation(a);
    return {angle, (t[0] * v[0] + t[1] * v[1] + t[2] * v[2]) / s};
}

// ---- measurements ---------------------------------------------------------------------------

inline long double matrix_error_scale(const matrix4& reference) {
    return std::max(1.0L, max_abs(reference));
}

/// sclerp(a, b, t) against a exp(t log(a^-1 b)) of the long double matrices.
template <class T>
void measure_sclerp(scaled_stats& s, const dual_quaternion<T>& a, const dual_quaternion<T>& b,
                    T t) {
    const quat::test::scaled_difference d = quat::test::sclerp_difference(a, b, t);
    s.add(d.difference, d.scale, eps<T>, [&] {
        return "a = " + describe(a) + ", b = " + describe(b) + ", t = " + describe_scalar(t);
    });
}

/// Largest component difference of the point `got` to R p + t of the matrix m, over 1 + |p| + |t|.
template <class T>
long double point_error(const matrix4& m, const vec3<T>& p, const vec3<T>& got,
                        long double& scale) {
    using L = long double;
    const L x[3] = {L(p.x), L(p.y), L(p.z)};
    const L y[3] = {L(got.x), L(got.y), L(got.z)};
    long double difference = 0, p2 = 0, t2 = 0;
    for (int i = 0; i < 3; ++i) {
        const long double ref = m[i][0] * x[0] + m[i][1] * x[1] + m[i][2] * x[2] + m[i][3];
        difference = std::max(difference, std::fabs(y[i] - ref));
        p2 += x[i] * x[i];
        t2 += m[i][3] * m[i][3];
    }
    scale = 1 + std::sqrt(p2) + std::sqrt(t2);
    return difference;
}

template <class T>
struct transform_stats {
    scaled_stats single, aos, soa;
};

/// transform(dq, p), and the array-of-structs and struct-of-arrays batches, on `points` points per
/// motion, |p| log-uniform in [1e-2, 1e2].
template <class T>
void measure_transform(rng& g, int motions, transform_stats<T>& out) {
    constexpr std::size_t points = 8;
    for (int i = 0; i < motions; ++i) {
        const dual_quaternion<T> dq = random_motion<T>(g);
        const matrix4 m = reference_matrix(dq);
        std::array<vec3<T>, points> p, aos;
        std::array<T, points> x, y, z, ox, oy, oz;
        for (std::size_t j = 0; j < points; ++j) {
            const v3<double> d = g.unit_vector();
            const double length = std::pow(10.0, g.uniform(-2, 2));
            p[j] = {T(length * d[0]), T(length * d[1]), T(length * d[2])};
            x[j] = p[j].x;
            y[j] = p[j].y;
            z[j] = p[j].z;
        }
        quat::transform(dq, p.data(), aos.data(), points);
        quat::transform(dq, quat::soa_points<const T>{x.data(), y.data(), z.data(), points},
                        quat::soa_points<T>{ox.data(), oy.data(), oz.data(), points});
        for (std::size_t j = 0; j < points; ++j) {
            const auto what = [&] { return "dq = " + describe(dq) + ", p = " + describe(p[j]); };
            long double scale = 1;
            long double e = point_error(m, p[j], quat::transform(dq, p[j]), scale);
            out.single.add(e, scale, eps<T>, what);
            e = point_error(m, p[j], aos[j], scale);
            out.aos.add(e, scale, eps<T>, what);
            e = point_error(m, p[j], vec3<T>{ox[j], oy[j], oz[j]}, scale);
            out.soa.add(e, scale, eps<T>, what);
        }
    }
}

template <class T>
struct conversion_stats {
    scaled_stats to_homogeneous, to_dual_quaternion, round_trip;
};

/// A motion in high precision: rotation `q` (unit), translation Gaussian of scale 2; its 4x4
/// matrix rounded entry by entry to T.
template <class T>
quat::homogeneous_matrix<T> rounded_matrix(const hq& q, const hv& t) {
    const real w = q[0], x = q[1], y = q[2], z = q[3];
    const real m[3][4] = {
        {w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y), t[0]},
        {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x), t[1]},
        {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z, t[2]}};
    quat::homogeneous_matrix<T> out = quat::homogeneous_matrix<T>::identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 4; ++j) out(i, j) = T(m[i][j]);
    return out;
}

/// Conversions on one family: random rotations (edge = false) or rotations by 10^-k and pi - 10^-k
/// (k = 1..15), 0 and pi about random axes (edge = true); translations Gaussian, scale 2.
template <class T>
void measure_conversions(rng& g, int count, bool edge, conversion_stats<T>& out) {
    for (int i = 0; i < count; ++i) {
        hq q;
        if (edge) {
            const int k = i % 32;  // 0..14: 10^-(k+1); 15..29: pi - 10^-(k-14); 30: 0; 31: pi
            const real angle = k < 15    ? power_of_ten(k + 1)
                               : k < 30  ? r_pi() - power_of_ten(k - 14)
                               : k == 30 ? real(0)
                                         : r_pi();
            const hv axis = widen(g.unit_vector());
            q = exp_map(hv{angle * axis[0], angle * axis[1], angle * axis[2]});
        } else {
            q = widen(g.template unit_quaternion<double>());
            q = normalized(q);
        }
        const vec3<T> t = gaussian_vector<T>(g, 2);
        const hv wt{real(t.x), real(t.y), real(t.z)};

        // to_homogeneous of the dual quaternion rounded once from q, and the round trip.
        const dual_quaternion<T> dq = quat::to_dual_quaternion(to_quat(narrow<T>(q)), t);
        const matrix4 ref = reference_matrix(dq);
        const long double scale = matrix_error_scale(ref);
        const auto what_dq = [&] { return "dq = " + describe(dq); };
        const quat::homogeneous_matrix<T> h = quat::to_homogeneous(dq);
        out.to_homogeneous.add(max_difference(reference_matrix(h), ref), scale, eps<T>, what_dq);
        out.round_trip.add(max_difference(reference_matrix(quat::to_dual_quaternion(h)), ref),
                           scale, eps<T>, what_dq);

        // to_dual_quaternion of the matrix rounded entry by entry from (q, t).
        const quat::homogeneous_matrix<T> m = rounded_matrix<T>(q, wt);
        const matrix4 m_ref = reference_matrix(m);
        const dual_quaternion<T> back = quat::to_dual_quaternion(m);
        out.to_dual_quaternion.add(
            max_difference(reference_matrix(back), m_ref), matrix_error_scale(m_ref), eps<T>,
            [&] { return "rotation " + describe(to_quat(narrow<T>(q))) + ", t = " + describe(t); });
    }
}

/// a * b against the product of the long double matrices.
template <class T>
scaled_stats measure_product(rng& g, int count) {
    scaled_stats s;
    for (int i = 0; i < count; ++i) {
        const dual_quaternion<T> a = random_motion<T>(g), b = random_motion<T>(g);
        const matrix4 ref = reference_matrix(a) * reference_matrix(b);
        s.add(max_difference(reference_matrix(a * b), ref), matrix_error_scale(ref), eps<T>,
              [&] { return "a = " + describe(a) + ", b = " + describe(b); });
    }
    return s;
}

/// compose of `factors` small steps (turn uniform in [0, 0.1] rad, translation Gaussian of scale
/// 0.1) against the long double chain product of their matrices.
template <class T>
scaled_stats measure_compose(rng& g, int chains, int factors) {
    scaled_stats s;
    std::vector<dual_quaternion<T>> steps(static_cast<std::size_t>(factors));
    for (int c = 0; c < chains; ++c) {
        matrix4 ref = quat::test::identity4();
        for (auto& step : steps) {
            const quaternion<T> q = turned(g, quaternion<T>::identity(), real(g.uniform(0, 0.1)));
            step = quat::to_dual_quaternion(q, gaussian_vector<T>(g, 0.1));
            ref = ref * reference_matrix(step);
        }
        const dual_quaternion<T> got = quat::compose(steps.data(), steps.size());
        s.add(max_difference(reference_matrix(got), ref), matrix_error_scale(ref), eps<T>,
              [&] { return "chain " + std::to_string(c) + ", result " + describe(got); });
    }
    return s;
}

/// blend of 4 random motions with weights uniform in [0, 1] against the definition evaluated in
/// high precision: the sum with each term's sign taken (as quat does, by the sign of the dot
/// product of the real parts in T) onto the first one's hemisphere, divided by |real|, the dual
/// part's component along the real part removed. Error: largest component difference over
/// max(1, largest reference component).
template <class T>
scaled_stats measure_blend(rng& g, int count) {
    scaled_stats s;
    constexpr std::size_t n = 4;
    for (int i = 0; i < count; ++i) {
        std::array<dual_quaternion<T>, n> x;
        std::array<T, n> w;
        for (std::size_t j = 0; j < n; ++j) {
            x[j] = random_motion<T>(g);
            w[j] = T(g.uniform());
        }
        hq r{0, 0, 0, 0}, d{0, 0, 0, 0};
        for (std::size_t j = 0; j < n; ++j) {
            const real k = quat::dot(x[j].real, x[0].real) < T(0) ? -real(w[j]) : real(w[j]);
            r = add(r, scaled(wide(x[j].real), k));
            d = add(d, scaled(wide(x[j].dual), k));
        }
        const real length = r_sqrt(dot4(r, r));
        r = scaled(r, 1 / length);
        d = scaled(d, 1 / length);
        d = add(d, scaled(r, -dot4(r, d)));
        const dual_quaternion<T> got = quat::blend(x, w);
        const hq gr = wide(got.real), gd = wide(got.dual);
        real difference = 0, largest = 1;
        for (std::size_t j = 0; j < 4; ++j) {
            difference = std::max({difference, r_abs(gr[j] - r[j]), r_abs(gd[j] - d[j])});
            largest = std::max({largest, r_abs(r[j]), r_abs(d[j])});
        }
        s.add(static_cast<long double>(difference), static_cast<long double>(largest), eps<T>, [&] {
            std::string what;
            for (std::size_t j = 0; j < n; ++j)
                what += (j ? ", " : "") + describe_scalar(w[j]) + " × " + describe(x[j]);
            return what;
        });
    }
    return s;
}

// ---- constant speed ---------------------------------------------------------------------------

enum class interpolation { sclerp, blend, glm_lerp };

struct speed_stats {
    error_stats turn;   // |angle(t) - t angle|, rad
    error_stats slide;  // |slide(t) - t slide|, length units
};

template <class T>
dual_quaternion<T> interpolate(interpolation how, const dual_quaternion<T>& a,
                               const dual_quaternion<T>& b, T t) {
    switch (how) {
        case interpolation::sclerp:
            return quat::sclerp(a, b, t);
        case interpolation::blend:
            return quat::blend(std::array<dual_quaternion<T>, 2>{a, b},
                               std::array<T, 2>{T(1) - t, t});
        case interpolation::glm_lerp: {
            using gq = glm::qua<T, glm::defaultp>;
            const auto in = [](const quaternion<T>& q) { return gq(q.w, q.x, q.y, q.z); };
            const glm::tdualquat<T, glm::defaultp> x(in(a.real), in(a.dual)),
                y(in(b.real), in(b.dual));
            const glm::tdualquat<T, glm::defaultp> r = glm::normalize(glm::lerp(x, y, t));
            return {{r.real.w, r.real.x, r.real.y, r.real.z},
                    {r.dual.w, r.dual.x, r.dual.y, r.dual.z}};
        }
    }
    return a;
}

/// For random pairs (b brought onto a's hemisphere, so only the speed differs), at t = i / 64:
/// the turn angle and the slide along the axis of a^-1 x(t) against t times those of a^-1 b, both
/// evaluated in high precision from the T results.
template <class T>
speed_stats measure_speed(rng& g, int pairs, interpolation how) {
    speed_stats s;
    for (int i = 0; i < pairs; ++i) {
        const dual_quaternion<T> a = random_motion<T>(g);
        dual_quaternion<T> b = random_motion<T>(g);
        if (quat::dot(a.real, b.real) < T(0)) b = -b;
        const hdq a_inverse = dq_inverse(wide(a));
        const screw_parameters whole = screw_of(dq_mul(a_inverse, wide(b)));
        for (int k = 0; k <= 64; ++k) {
            const T t = T(k) / T(64);
            const dual_quaternion<T> x = interpolate(how, a, b, t);
            const screw_parameters part = screw_of(dq_mul(a_inverse, wide(x)));
            const real wt = real(t);
            const auto what = [&] {
                return "a = " + describe(a) + ", b = " + describe(b) +
                       ", t = " + std::to_string(k) + "/64";
            };
            if (s.turn.add(double(r_abs(part.angle - wt * whole.angle))))
                s.turn.worst_case = what();
            if (s.slide.add(double(r_abs(part.slide - wt * whole.slide))))
                s.slide.worst_case = what();
        }
    }
    return s;
}

// ---- the run ------------------------------------------------------------------------------------

template <class T>
struct rigid_runner {
    bool quick;
    std::uint64_t seed;
    std::vector<rigid_row>& rows;

    int n(int full, int small) const { return quick ? small : full; }
    rng fresh(std::uint64_t salt) const { return rng{seed * 7919 + 100 + salt}; }
    void push(const char* operation, const std::string& inputs, const char* scale, double bound,
              const scaled_stats& stats) {
        rows.push_back(rigid_row{operation, inputs, scalar_name<T>(), scale, bound, stats});
    }

    void sclerp() {
        const char* op = "sclerp(a, b, t) vs a exp(t log(a⁻¹b))";
        const char* scale = "max(1, max \\|entry\\| of a, b, result)";
        const int count = n(20000, 1000);
        {
            rng g = fresh(1);
            scaled_stats s;
            for (int i = 0; i < count; ++i) {
                const auto a = random_motion<T>(g), b = random_motion<T>(g);
                measure_sclerp(s, a, b, T(g.uniform()));
            }
            push(op, "random motions (translations σ = 2), t ∈ [0, 1]", scale, bound_sclerp, s);
        }
        {
            rng g = fresh(2);
            scaled_stats s;
            for (int i = 0; i < count; ++i) {
                const int k = i % 14;  // 1..13: relative angle 10^-k; 0: equal rotations
                const auto a = random_motion<T>(g);
                const quaternion<T> qb = k == 0 ? a.real : turned(g, a.real, power_of_ten(k));
                const auto b = quat::to_dual_quaternion(
                    qb, quat::translation_of(a) + gaussian_vector<T>(g, 1));
                measure_sclerp(s, a, b, T(g.uniform()));
            }
            push(op, "relative angle 10^-k (k = 1..13) and 0 (pure translation), t ∈ [0, 1]", scale,
                 bound_sclerp, s);
        }
        {
            rng g = fresh(3);
            scaled_stats s;
            for (int i = 0; i < count; ++i) {
                const int k = 1 + i % 4;
                const auto a = random_motion<T>(g);
                const quaternion<T> qb = turned(g, a.real, r_pi() - power_of_ten(k));
                const auto b = quat::to_dual_quaternion(
                    qb, quat::translation_of(a) + gaussian_vector<T>(g, 1));
                measure_sclerp(s, a, b, T(g.uniform()));
            }
            push(op, "relative angle π − 10^-k (k = 1..4), t ∈ [0, 1]", scale, bound_sclerp, s);
        }
    }

    void transform() {
        rng g = fresh(4);
        transform_stats<T> s;
        measure_transform(g, n(100000, 2000), s);
        const char* inputs = "random motions, 8 points each, \\|p\\| 1e-2 … 1e2";
        const char* scale = "1 + \\|p\\| + \\|t\\|";
        push("transform(dq, p) vs R p + t", inputs, scale, bound_transform, s.single);
        push("transform(dq, points, out, n), array of structs", inputs, scale, bound_transform,
             s.aos);
        push("transform(dq, soa_points), struct of arrays", inputs, scale, bound_transform, s.soa);
    }

    void conversions() {
        const char* scale = "max(1, max \\|entry\\|)";
        for (bool edge : {false, true}) {
            rng g = fresh(edge ? 6 : 5);
            conversion_stats<T> s;
            measure_conversions(g, n(100000, 2000), edge, s);
            const std::string inputs =
                edge ? "rotation angle 10^-k, π − 10^-k (k = 1..15), 0, π; translations σ = 2"
                     : "random motions (translations σ = 2)";
            push("to_homogeneous(dq) entries", inputs, scale, bound_to_homogeneous,
                 s.to_homogeneous);
            push("to_dual_quaternion(m), m rounded from the exact matrix", inputs, scale,
                 bound_to_dual_quaternion, s.to_dual_quaternion);
            push("dq → to_homogeneous → to_dual_quaternion", inputs, scale,
                 bound_to_dual_quaternion, s.round_trip);
        }
    }

    void products() {
        const char* scale = "max(1, max \\|entry\\|)";
        rng g = fresh(7);
        push("a * b vs the 4x4 product", "random motions (translations σ = 2)", scale,
             bound_product, measure_product<T>(g, n(100000, 2000)));
        rng h = fresh(8);
        push("compose of 1024 motions vs the 4x4 chain product",
             "steps: turn ∈ [0, 0.1] rad, translation σ = 0.1", scale, bound_compose,
             measure_compose<T>(h, n(1000, 20), 1024));
    }

    void blend() {
        rng g = fresh(9);
        push("blend of 4 motions vs its definition", "random motions, weights ∈ [0, 1]",
             "max(1, max \\|component\\|)", bound_blend, measure_blend<T>(g, n(100000, 2000)));
    }
};

struct speed_row {
    const char* name;
    const char* scalar;
    speed_stats stats;
    bool bounded;  // quat's sclerp: held to bound_speed_turn / bound_speed_slide eps
    double turn_bound, slide_bound;

    [[nodiscard]] bool exceeded() const {
        return bounded && !(stats.turn.max <= turn_bound && stats.slide.max <= slide_bound);
    }
};

template <class T>
void speed_rows(bool quick, std::uint64_t seed, std::vector<speed_row>& rows) {
    const int pairs = quick ? 200 : 10000;
    const double e = double(std::numeric_limits<T>::epsilon());
    const struct {
        interpolation how;
        const char* name;
    } methods[] = {{interpolation::sclerp, "quat::sclerp(a, b, t)"},
                   {interpolation::blend, "quat::blend({a, b}, {1 − t, t})"},
                   {interpolation::glm_lerp, "glm::normalize(glm::lerp(a, b, t))"}};
    for (const auto& m : methods) {
        rng g{seed * 7919 + 110};  // the same pairs for every method
        const bool bounded = m.how == interpolation::sclerp;
        rows.push_back(speed_row{m.name, scalar_name<T>(), measure_speed<T>(g, pairs, m.how),
                                 bounded, bound_speed_turn * e, bound_speed_slide * e});
    }
}

inline std::string format_scale(long double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", double(s));
    return buf;
}

inline std::string format_rad(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1e", v);
    return buf;
}

/// Prints both tables; returns the number of rows over their bounds.
inline int run_rigid(bool quick, std::uint64_t seed) {
    std::vector<rigid_row> rows;
    rigid_runner<float> f{quick, seed, rows};
    rigid_runner<double> d{quick, seed, rows};
    f.sclerp();
    d.sclerp();
    f.transform();
    d.transform();
    f.conversions();
    d.conversions();
    f.products();
    d.products();
    f.blend();
    d.blend();

    std::printf(
        "| operation | inputs | type | max (eps) | RMS (eps) | error relative to | its value at "
        "the max | bound (eps) |\n|---|---|---|---|---|---|---|---|\n");
    for (const rigid_row& r : rows)
        std::printf("| %s | %s | %s | %s | %s | %s | %s | ≤ %s%s |\n", r.operation.c_str(),
                    r.inputs.c_str(), r.scalar.c_str(), format_number(r.stats.error.max).c_str(),
                    format_number(r.stats.error.rms()).c_str(), r.scale.c_str(),
                    format_scale(r.stats.scale_at_max).c_str(), format_number(r.bound).c_str(),
                    r.exceeded() ? " **exceeded**" : "");
    std::printf(
        "\nReference: long double (tests/support/rigid_reference.hpp: 4x4 matrices of the "
        "rounded inputs and outputs, Gauss-Jordan inverse, expm by scaling and squaring, logm by "
        "Denman-Beavers square roots); blend's in %s. Seed %llu, %s sample counts.\n\n",
        reference_name(), static_cast<unsigned long long>(seed), quick ? "quick" : "full");

    std::vector<speed_row> speed;
    speed_rows<float>(quick, seed, speed);
    speed_rows<double>(quick, seed, speed);
    std::printf(
        "Constant speed: random pairs (rotation uniform, translations σ = 2, b on a's "
        "hemisphere), t = i/64 (i = 0..64); deviation of the turn angle and of the slide along "
        "the screw axis of a⁻¹ x(t) from t times those of a⁻¹ b, evaluated in %s.\n\n",
        reference_name());
    std::printf(
        "| interpolation x(t) | type | turn: max \\|angle(t) − t angle\\| (rad) | turn: RMS (rad) "
        "| "
        "slide: max \\|slide(t) − t slide\\| | slide: RMS | bound "
        "|\n|---|---|---|---|---|---|---|\n");
    for (const speed_row& r : speed) {
        const std::string bound = r.bounded ? "≤ " + format_rad(r.turn_bound) + " rad, " +
                                                  format_rad(r.slide_bound) +
                                                  (r.exceeded() ? " **exceeded**" : "")
                                            : "—";
        std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", r.name, r.scalar,
                    format_rad(r.stats.turn.max).c_str(), format_rad(r.stats.turn.rms()).c_str(),
                    format_rad(r.stats.slide.max).c_str(), format_rad(r.stats.slide.rms()).c_str(),
                    bound.c_str());
    }

    int exceeded = 0;
    for (const rigid_row& r : rows) {
        if (!r.exceeded()) continue;
        ++exceeded;
        std::fprintf(stderr, "EXCEEDED: %s [%s, %s]: max %s eps > %s; worst input %s\n",
                     r.operation.c_str(), r.inputs.c_str(), r.scalar.c_str(),
                     format_number(r.stats.error.max).c_str(), format_number(r.bound).c_str(),
                     r.stats.error.worst_case.c_str());
    }
    for (const speed_row& r : speed) {
        if (!r.exceeded()) continue;
        ++exceeded;
        std::fprintf(
            stderr, "EXCEEDED: constant speed of %s [%s]: turn %s rad at %s; slide %s at %s\n",
            r.name, r.scalar, format_rad(r.stats.turn.max).c_str(), r.stats.turn.worst_case.c_str(),
            format_rad(r.stats.slide.max).c_str(), r.stats.slide.worst_case.c_str());
    }
    if (exceeded > 0) std::fprintf(stderr, "%d rigid-motion rows over their bounds\n", exceeded);
    return exceeded;
}

}  // namespace rigid
}  // namespace accuracy
