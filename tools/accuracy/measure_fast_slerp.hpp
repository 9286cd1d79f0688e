// `quat_accuracy --slerp-fast`: the fast-slerp family (nlerp, corrected_nlerp, slerp_fast and the
// exact slerp beside them) against the high-precision slerp of the same inputs, in float and
// double: the rotation angle between result and reference (in radians: the approximations' errors
// are not a few eps) and | |r| - 1 |, on random, nearly equal, nearly opposite and sign-flipped
// pairs at t = 0, t = 1 and 63 random t between, 1.3 million samples per method and type.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <quat/paths/interpolation.hpp>
#include <quat/paths/slerp_fast.hpp>

#include "measure.hpp"

namespace accuracy {

/// One member of the family and its documented bounds: rotation angle (rad) and | |r| - 1 |. The
/// approximations' angle bounds are those of include/quat/paths/slerp_fast.hpp, asserted by
/// tests/test_slerp_fast.cpp and quoted in the benchmark labels (bench/bench_other.cpp), and their
/// lengths are unit to 4 eps (tests/support/tolerance.hpp's unit_norm) except slerp_fast's; the
/// exact slerp's are the main table's targets (4 eps angle, 2 eps length, as in main.cpp).
struct fast_slerp_method {
    const char* name;
    double angle_bound_float, angle_bound_double;
    double norm_bound_float, norm_bound_double;
};

inline constexpr double fast_slerp_eps_float = std::numeric_limits<float>::epsilon();
inline constexpr double fast_slerp_eps_double = std::numeric_limits<double>::epsilon();

inline constexpr fast_slerp_method fast_slerp_methods[] = {
    {"nlerp", 0.143, 0.143, 4 * fast_slerp_eps_float, 4 * fast_slerp_eps_double},
    {"corrected_nlerp", 5.9e-4, 5.9e-4, 4 * fast_slerp_eps_float, 4 * fast_slerp_eps_double},
    {"slerp_fast", 4e-7, 3.4e-8, 4e-7, 3.4e-8},
    {"slerp", 4 * fast_slerp_eps_float, 4 * fast_slerp_eps_double, 2 * fast_slerp_eps_float,
     2 * fast_slerp_eps_double},
};
inline constexpr int fast_slerp_method_count = 4;

/// The result of method m (the order of fast_slerp_methods).
template <class T>
quat::quaternion<T> fast_slerp_evaluate(int method, const quat::quaternion<T>& a,
                                        const quat::quaternion<T>& b, T t) {
    switch (method) {
        case 0:
            return quat::nlerp(a, b, t);
        case 1:
            return quat::corrected_nlerp(a, b, t);
        case 2:
            return quat::slerp_fast(a, b, t);
        default:
            return quat::slerp(a, b, t);
    }
}
/// The approximations pick -b by the sign bit of a . b, nlerp and slerp by a . b < 0; the two
/// differ only at a . b = -0.
constexpr bool fast_slerp_uses_sign_bit(int method) { return method == 1 || method == 2; }

struct fast_slerp_result {
    error_stats angle[fast_slerp_method_count];  // rad
    error_stats norm[fast_slerp_method_count];   // | |r| - 1 |, absolute
};

/// Pairs of one family: 0 random, 1 nearly equal (b = a exp(delta n), delta = 10^-k, k = 1..15),
/// 2 rotations nearly pi apart (a . b near 0), 3 b = -a.
template <class T>
std::vector<std::pair<q4<T>, q4<T>>> fast_slerp_pairs(rng& g, int family, int count) {
    std::vector<std::pair<q4<T>, q4<T>>> out;
    for (int i = 0; i < count; ++i) {
        const q4<T> a = g.template unit_quaternion<T>();
        hq b = widen(g.template unit_quaternion<T>());
        if (family == 1 || family == 2) {
            const double delta = std::pow(10.0, -(1 + i % 15));
            const v3<double> n = g.unit_vector();
            const hq turn = exp_map(widen(v3<double>{delta * n[0], delta * n[1], delta * n[2]}));
            // family 2: a (0, axis) is orthogonal to a in 4D, the rotation pi away from a.
            const v3<double> axis = g.unit_vector();
            const hq start =
                family == 1 ? widen(a)
                            : mul(widen(a), hq{0, real(axis[0]), real(axis[1]), real(axis[2])});
            b = mul(start, turn);
        }
        if (family == 3) b = negated(widen(a));
        out.emplace_back(a, narrow<T>(normalized(b)));
    }
    return out;
}

template <class T>
fast_slerp_result measure_fast_slerp(rng& g, int pairs_per_family) {
    fast_slerp_result r;
    for (int family = 0; family < 4; ++family) {
        for (const auto& [a, b] : fast_slerp_pairs<T>(g, family, pairs_per_family)) {
            const quat::quaternion<T> qa{a[0], a[1], a[2], a[3]}, qb{b[0], b[1], b[2], b[3]};
            // The reference follows the arc the method chose by the sign of a . b in T, which
            // differs from the exactly shorter arc only when a . b is within rounding of 0.
            const T d = quat::dot(qa, qb);
            const hq end_by_compare = d < T(0) ? negated(widen(b)) : widen(b);
            const hq end_by_sign_bit = std::signbit(d) ? negated(widen(b)) : widen(b);
            for (int i = 0; i <= 64; ++i) {
                const T t = i == 0 ? T(0) : i == 64 ? T(1) : T(g.uniform());
                const hq ref_compare = slerp_along(widen(a), end_by_compare, real(t));
                const hq ref_sign_bit = slerp_along(widen(a), end_by_sign_bit, real(t));
                for (int m = 0; m < fast_slerp_method_count; ++m) {
                    const quat::quaternion<T> f = fast_slerp_evaluate(m, qa, qb, t);
                    const hq got = widen(q4<T>{f.w, f.x, f.y, f.z});
                    const hq& ref = fast_slerp_uses_sign_bit(m) ? ref_sign_bit : ref_compare;
                    const bool worst_angle =
                        r.angle[m].add(double(rotation_angle_between(got, ref)));
                    const bool worst_norm = r.norm[m].add(double(r_abs(norm(got) - 1)));
                    if (worst_angle || worst_norm) {
                        char t_text[40];
                        std::snprintf(t_text, sizeof t_text, ", t = %.9g", double(t));
                        const std::string what =
                            std::string("a = ") + describe(a) + ", b = " + describe(b) + t_text;
                        if (worst_angle) r.angle[m].worst_case = what;
                        if (worst_norm) r.norm[m].worst_case = what;
                    }
                }
            }
        }
    }
    return r;
}

/// Prints the table (one line per method: the largest rotation-angle error and length error
/// | |r| - 1 | in float and double, each with its bound); returns the number of maxima above their
/// bound.
inline int run_fast_slerp(bool quick, std::uint64_t seed) {
    const int per_family = quick ? 500 : 5000;
    rng gf{seed * 7919 + 9};
    const fast_slerp_result f = measure_fast_slerp<float>(gf, per_family);
    rng gd{seed * 7919 + 9};
    const fast_slerp_result d = measure_fast_slerp<double>(gd, per_family);
    std::printf(
        "The fast-slerp family against the %s slerp of the same inputs: random, nearly equal, "
        "nearly opposite and b = -a pairs at t = 0, 1 and 63 random t; %ld samples per method and "
        "type (seed %llu). Largest error (bound); length = | |r| - 1 |.\n\n",
        reference_name(), f.angle[0].count, static_cast<unsigned long long>(seed));
    std::printf(
        "| method | angle, float (rad) | angle, double (rad) | length, float | "
        "length, double |\n|---|---|---|---|---|\n");
    int over = 0;
    auto cell = [&](const error_stats& s, double bound) {
        if (!(s.max <= bound)) ++over;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.2e (%.3g)%s", s.max, bound,
                      s.max <= bound ? "" : " OVER");
        return std::string(buf);
    };
    for (int m = 0; m < fast_slerp_method_count; ++m) {
        const fast_slerp_method& info = fast_slerp_methods[m];
        const std::string af = cell(f.angle[m], info.angle_bound_float);
        const std::string ad = cell(d.angle[m], info.angle_bound_double);
        const std::string nf = cell(f.norm[m], info.norm_bound_float);
        const std::string nd = cell(d.norm[m], info.norm_bound_double);
        std::printf("| %s | %s | %s | %s | %s |\n", info.name, af.c_str(), ad.c_str(), nf.c_str(),
                    nd.c_str());
    }
    std::printf("\nWorst inputs (angle):\n");
    for (int m = 0; m < fast_slerp_method_count; ++m) {
        std::printf("  %-15s float:  %s\n", fast_slerp_methods[m].name,
                    f.angle[m].worst_case.c_str());
        std::printf("  %-15s double: %s\n", "", d.angle[m].worst_case.c_str());
    }
    return over;
}

}  // namespace accuracy
