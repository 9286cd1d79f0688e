// `quat_accuracy --slerp-fast`: the rotation-angle error of quat::slerp_fast (an approximation, so
// measured in radians, not eps) against the high-precision slerp of the same inputs, in float and
// double, on random, nearly equal, nearly opposite and sign-flipped pairs at 65 values of t.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include <quat/fast_slerp.hpp>

#include "measure.hpp"

namespace accuracy {

/// slerp_fast's documented bounds (include/quat/fast_slerp.hpp, tests/test_fast_slerp.cpp), rad.
template <class T>
constexpr double slerp_fast_bound = sizeof(T) == sizeof(float) ? 1e-6 : 1e-8;

struct fast_slerp_result {
    error_stats angle;  // rad
    error_stats norm;   // ||r| - 1|, absolute
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
            const hq arc_end = quat::dot(qa, qb) < T(0) ? negated(widen(b)) : widen(b);
            for (int i = 0; i <= 64; ++i) {
                const T t = T(i) / T(64);
                const quat::quaternion<T> f = quat::slerp_fast(qa, qb, t);
                const hq got = widen(q4<T>{f.w, f.x, f.y, f.z});
                // The reference follows the arc slerp_fast chose by the sign of a . b in T, which
                // differs from the exactly shorter arc only when a . b is within rounding of 0.
                const hq ref = slerp_along(widen(a), arc_end, real(t));
                const std::string what = std::string("a = ") + describe(a) +
                                         ", b = " + describe(b) + ", t = " + std::to_string(i) +
                                         "/64";
                if (r.angle.add(double(rotation_angle_between(got, ref))))
                    r.angle.worst_case = what;
                if (r.norm.add(double(r_abs(norm(got) - 1)))) r.norm.worst_case = what;
            }
        }
    }
    return r;
}

/// Prints one line per type; returns the number of types whose maximum exceeds the bound.
inline int run_fast_slerp(bool quick, std::uint64_t seed) {
    const int per_family = quick ? 500 : 5000;
    int over = 0;
    std::printf(
        "slerp_fast against the %s slerp of the same inputs (65 values of t in [0, 1], "
        "random, nearly equal, nearly opposite and b = -a pairs; seed %llu):\n",
        reference_name(), static_cast<unsigned long long>(seed));
    auto report = [&](const char* type, const fast_slerp_result& r, double bound) {
        std::printf(
            "  %-6s %ld samples: rotation angle max %.2e rad, rms %.2e rad (bound %.0e); "
            "max ||r| - 1| %.2e\n",
            type, r.angle.count, r.angle.max, r.angle.rms(), bound, r.norm.max);
        std::printf("         worst at %s\n", r.angle.worst_case.c_str());
        if (!(r.angle.max <= bound)) ++over;
    };
    rng gf{seed * 7919 + 9};
    report("float", measure_fast_slerp<float>(gf, per_family), slerp_fast_bound<float>);
    rng gd{seed * 7919 + 9};
    report("double", measure_fast_slerp<double>(gd, per_family), slerp_fast_bound<double>);
    return over;
}

}  // namespace accuracy
