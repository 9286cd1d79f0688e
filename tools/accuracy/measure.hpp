// The measurements: each runs one operation of one library over one input family and returns the
// error statistics against the high-precision reference (errors in units of eps of T).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "harness.hpp"
#include "libraries.hpp"

namespace accuracy {

template <class T>
std::string describe(const q4<T>& q) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "q = (%.17g, %.17g, %.17g, %.17g)", double(q[0]), double(q[1]),
                  double(q[2]), double(q[3]));
    return buf;
}
template <class T>
std::string describe(const v3<T>& v) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", double(v[0]), double(v[1]),
                  double(v[2]));
    return buf;
}

inline real max_abs_difference(const hq& a, const hq& b) {
    real m = 0;
    for (int i = 0; i < 4; ++i) m = r_abs(a[i] - b[i]) > m ? r_abs(a[i] - b[i]) : m;
    return m;
}
inline real dot4(const hq& a, const hq& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}
inline hq negated(const hq& q) { return {-q[0], -q[1], -q[2], -q[3]}; }

// ---- input families ------------------------------------------------------------------------

/// Uniform random rotations.
template <class T>
std::vector<q4<T>> random_rotations(rng& g, int n) {
    std::vector<q4<T>> out;
    for (int i = 0; i < n; ++i) out.push_back(g.template unit_quaternion<T>());
    return out;
}

/// Rotations by 0, 10^-k, pi - 10^-k (k = 0..15) and pi about the coordinate axes and random axes.
template <class T>
std::vector<q4<T>> near_identity_and_half_turns(rng& g, int random_axes) {
    std::vector<v3<double>> axes{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}};
    for (int i = 0; i < random_axes; ++i) axes.push_back(g.unit_vector());
    std::vector<double> angles{0.0, 3.141592653589793};
    for (int k = 0; k <= 15; ++k) {
        angles.push_back(std::pow(10.0, -k));
        angles.push_back(3.141592653589793 - std::pow(10.0, -k));
    }
    std::vector<q4<T>> out;
    for (const auto& a : axes)
        for (double angle : angles)
            out.push_back(
                narrow<T>(exp_map(widen(v3<double>{angle * a[0], angle * a[1], angle * a[2]}))));
    return out;
}

// ---- measurements ----------------------------------------------------------------------------

/// quaternion -> matrix -> quaternion; error = max component difference to q/|q| (up to sign).
template <class Lib, class T>
error_stats measure_matrix_round_trip(const std::vector<q4<T>>& inputs) {
    error_stats s;
    for (const q4<T>& q : inputs) {
        const hq ref = normalized(widen(q));
        hq got = widen(Lib::matrix_round_trip(q));
        if (dot4(got, ref) < 0) got = negated(got);
        if (s.add(in_eps<T>(max_abs_difference(got, ref)))) s.worst_case = describe(q);
    }
    return s;
}

/// normalize; error = max component difference to q/|q| computed in high precision.
template <class Lib, class T>
error_stats measure_normalize(const std::vector<q4<T>>& inputs) {
    error_stats s;
    for (const q4<T>& q : inputs) {
        const hq ref = normalized(widen(q));
        if (s.add(in_eps<T>(max_abs_difference(widen(Lib::normalize(q)), ref))))
            s.worst_case = describe(q);
    }
    return s;
}

/// Quaternions with components of magnitude 10^e, e uniform in [lo, hi], either one scale for the
/// whole quaternion (same_scale) or one per component.
template <class T>
std::vector<q4<T>> scaled_quaternions(rng& g, int n, int lo, int hi, bool same_scale) {
    std::vector<q4<T>> out;
    for (int i = 0; i < n; ++i) {
        q4<double> q = g.unit_quaternion();
        const double common = std::pow(10.0, g.uniform(lo, hi));
        for (double& c : q) c *= same_scale ? common : std::pow(10.0, g.uniform(lo, hi));
        out.push_back(narrow<T>(q));
    }
    return out;
}

struct slerp_case {
    double t;
    std::string what;
};

/// slerp: norm error ||r| - 1| and rotation-angle error to the reference, both in eps.
template <class Lib, class T>
void measure_slerp(const std::vector<std::pair<q4<T>, q4<T>>>& pairs, const std::vector<T>& ts,
                   error_stats& norm_err, error_stats& angle_err) {
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const auto& [a, b] = pairs[i];
        const T t = ts[i];
        const hq got = widen(Lib::slerp(a, b, t));
        const hq ref = slerp(widen(a), widen(b), real(t));
        const std::string what = std::string("a = ") + describe(a) + ", b = " + describe(b) +
                                 ", t = " + std::to_string(double(t));
        if (norm_err.add(in_eps<T>(r_abs(norm(got) - 1)))) norm_err.worst_case = what;
        if (angle_err.add(in_eps<T>(rotation_angle_between(got, ref)))) angle_err.worst_case = what;
    }
}

/// Pairs (a, +-a * exp(delta n)) with delta = 10^-k, k = 0..15, and delta = 0.
template <class T>
std::vector<std::pair<q4<T>, q4<T>>> nearby_pairs(rng& g, int per_k, bool opposite) {
    std::vector<std::pair<q4<T>, q4<T>>> out;
    for (int k = 0; k <= 16; ++k) {
        const double delta = k == 16 ? 0.0 : std::pow(10.0, -k);
        for (int i = 0; i < per_k; ++i) {
            const q4<T> a = g.template unit_quaternion<T>();
            const v3<double> n = g.unit_vector();
            hq b =
                mul(widen(a), exp_map(widen(v3<double>{delta * n[0], delta * n[1], delta * n[2]})));
            if (opposite) b = negated(b);
            out.emplace_back(a, narrow<T>(b));
        }
    }
    return out;
}

/// Rotation vectors with angle 10^e, e uniform in [log10(1e-10), log10(pi)], random axes.
template <class T>
std::vector<v3<T>> rotation_vectors(rng& g, int n) {
    std::vector<v3<T>> out;
    for (int i = 0; i < n; ++i) {
        const double angle = i == n - 1
                                 ? 3.141592653589793
                                 : std::pow(10.0, g.uniform(-10, std::log10(3.141592653589793)));
        const v3<double> a = g.unit_vector();
        out.push_back(narrow<T>(v3<double>{angle * a[0], angle * a[1], angle * a[2]}));
    }
    return out;
}

/// exp map; error = max(|w - w_ref|, |u - u_ref| / |u_ref|) in eps: absolute in the scalar part,
/// relative in the vector part, so tiny angles are held to their own precision.
template <class Lib, class T>
error_stats measure_exp(const std::vector<v3<T>>& inputs) {
    error_stats s;
    for (const v3<T>& v : inputs) {
        const hq ref = exp_map(widen(v));
        const hq got = widen(Lib::exp(v));
        const hv du{got[1] - ref[1], got[2] - ref[2], got[3] - ref[3]};
        const real rel = norm(du) / norm(hv{ref[1], ref[2], ref[3]});
        const real e = r_abs(got[0] - ref[0]) > rel ? r_abs(got[0] - ref[0]) : rel;
        if (s.add(in_eps<T>(e))) s.worst_case = std::string("v = ") + describe(v);
    }
    return s;
}

/// log map of q = exp(v) rounded to T; error = |v - v_ref| / |v_ref| in eps.
template <class Lib, class T>
error_stats measure_log(const std::vector<v3<T>>& inputs) {
    error_stats s;
    for (const v3<T>& v : inputs) {
        const q4<T> q = narrow<T>(exp_map(widen(v)));
        const hv ref = log_map(widen(q));
        const hv got = widen(Lib::log(q));
        const hv d{got[0] - ref[0], got[1] - ref[1], got[2] - ref[2]};
        if (s.add(in_eps<T>(norm(d) / norm(ref)))) s.worst_case = describe(q);
    }
    return s;
}

/// Where rotate's quaternion comes from.
enum class rotate_input {
    unit_rounded_once,  // the best unit quaternion T can hold (|q|^2 - 1 below 1 eps)
    normalized,         // Lib::normalize of an arbitrary quaternion, as users usually get one
};

/// A quaternion with components uniform in [-1, 1] times one scale 10^e, e uniform in [-3, 3],
/// rounded to T: no rotation in particular and far from unit length.
template <class T>
q4<T> arbitrary_quaternion(rng& g) {
    for (;;) {
        const q4<double> p{g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)};
        if (p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3] < 1e-4) continue;
        const double scale = std::pow(10.0, g.uniform(-3, 3));
        return narrow<T>(q4<double>{scale * p[0], scale * p[1], scale * p[2], scale * p[3]});
    }
}

/// rotate(q, v): length error ||r| - |v|| / |v| and direction error (angle in radians between r
/// and the reference rotation of v by q / |q| evaluated in high precision), both in eps. The
/// reference is the rotation the stored q represents, so normalize's own rounding of the direction
/// is not charged to rotate, while a rotate that ignores |q| != 1 is.
template <class Lib, class T>
void measure_rotate(rng& g, int n, rotate_input input, error_stats& length,
                    error_stats& direction) {
    for (int i = 0; i < n; ++i) {
        const q4<T> q = input == rotate_input::unit_rounded_once
                            ? g.template unit_quaternion<T>()
                            : Lib::normalize(arbitrary_quaternion<T>(g));
        const v3<double> dir = g.unit_vector();
        const double scale = std::pow(10.0, g.uniform(-3, 3));
        const v3<T> v = narrow<T>(v3<double>{scale * dir[0], scale * dir[1], scale * dir[2]});
        const hv got = widen(Lib::rotate(q, v));
        const hq unit = normalized(widen(q));
        const hv wide = widen(v);
        const hq image = mul(mul(unit, hq{0, wide[0], wide[1], wide[2]}), conj(unit));
        const hv ref{image[1], image[2], image[3]};
        const real nv = norm(wide);
        const hv c{got[1] * ref[2] - got[2] * ref[1], got[2] * ref[0] - got[0] * ref[2],
                   got[0] * ref[1] - got[1] * ref[0]};
        const real d = got[0] * ref[0] + got[1] * ref[1] + got[2] * ref[2];
        const std::string what = describe(q) + ", v = " + describe(v);
        if (length.add(in_eps<T>(r_abs(norm(got) - nv) / nv))) length.worst_case = what;
        if (direction.add(in_eps<T>(r_atan2(norm(c), d)))) direction.worst_case = what;
    }
}

}  // namespace accuracy
