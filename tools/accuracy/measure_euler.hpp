// Euler -> quaternion -> Euler round trip for all 24 conventions, on random angles and with the
// middle angle at and near gimbal lock. Error = rotation angle between the rotation of the input
// angles and the rotation of the returned angles, both evaluated in high precision.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "measure.hpp"

namespace accuracy {

inline constexpr quat::sequence all_sequences[12] = {
    quat::sequence::xyz, quat::sequence::xzy, quat::sequence::yxz, quat::sequence::yzx,
    quat::sequence::zxy, quat::sequence::zyx, quat::sequence::xyx, quat::sequence::xzx,
    quat::sequence::yxy, quat::sequence::yzy, quat::sequence::zxz, quat::sequence::zyz};

inline std::string convention_name(quat::sequence s, quat::frame f) {
    const std::array<int, 3> ax = axes_of(s);
    std::string name;
    for (int a : ax) name += char('x' + a);
    return name + (f == quat::frame::intrinsic ? " intrinsic" : " extrinsic");
}

/// Calls fn(integral_constant<sequence>, integral_constant<frame>) for each of the 24 conventions.
template <class Fn, std::size_t... I>
void for_each_convention(Fn&& fn, std::index_sequence<I...>) {
    (fn(std::integral_constant<quat::sequence, all_sequences[I / 2]>{},
        std::integral_constant < quat::frame,
        I % 2 == 0 ? quat::frame::intrinsic : quat::frame::extrinsic > {}),
     ...);
}
template <class Fn>
void for_each_convention(Fn&& fn) {
    for_each_convention(std::forward<Fn>(fn), std::make_index_sequence<24>{});
}

/// Random angles: first and third in [-pi, pi], middle in its canonical range.
template <class T>
std::vector<v3<T>> random_euler_angles(rng& g, int n, bool proper) {
    const double pi = 3.141592653589793;
    std::vector<v3<T>> out;
    for (int i = 0; i < n; ++i) {
        const double middle = proper ? g.uniform(0, pi) : g.uniform(-pi / 2, pi / 2);
        out.push_back(narrow<T>(v3<double>{g.uniform(-pi, pi), middle, g.uniform(-pi, pi)}));
    }
    return out;
}

/// Middle angle exactly at each gimbal-lock value L (+-pi/2 Tait-Bryan; 0, pi proper) and at
/// L +- 10^-k, k = 1..15, with random first and third angles.
template <class T>
std::vector<v3<T>> gimbal_lock_euler_angles(rng& g, int per_offset, bool proper) {
    const double pi = 3.141592653589793;
    const std::vector<double> locks =
        proper ? std::vector<double>{0.0, pi} : std::vector<double>{-pi / 2, pi / 2};
    std::vector<v3<T>> out;
    for (double lock : locks)
        for (int k = 0; k <= 15; ++k)
            for (double sign : {-1.0, 1.0}) {
                if (k == 0 && sign < 0) continue;
                const double middle = k == 0 ? lock : lock + sign * std::pow(10.0, -k);
                for (int i = 0; i < per_offset; ++i)
                    out.push_back(
                        narrow<T>(v3<double>{g.uniform(-pi, pi), middle, g.uniform(-pi, pi)}));
            }
    return out;
}

/// Round-trip error of one library in convention (S, F); empty when the library lacks it.
template <class Lib, class T, quat::sequence S, quat::frame F>
std::optional<error_stats> measure_euler(const std::vector<v3<T>>& inputs) {
    constexpr std::array<int, 3> ax = axes_of(S);
    constexpr bool intrinsic = F == quat::frame::intrinsic;
    error_stats s;
    for (const v3<T>& a : inputs) {
        const std::optional<v3<T>> back = Lib::template euler_round_trip<T, S, F>(a);
        if (!back) return std::nullopt;
        const real e = rotation_angle_between(euler_rotation(ax, intrinsic, widen(a)),
                                              euler_rotation(ax, intrinsic, widen(*back)));
        if (s.add(in_eps<T>(e)))
            s.worst_case =
                convention_name(S, F) + " angles " + describe(a) + " -> " + describe(*back);
    }
    return s;
}

/// Error statistics of one library over all 24 conventions (merged), or over the one convention
/// (S0, F0) when `only_one` is set; `per_convention` receives the max of each convention.
template <class Lib, class T>
std::optional<error_stats> measure_euler_family(
    rng& g, int n, bool gimbal, bool only_zyx_intrinsic,
    std::vector<std::pair<std::string, double>>* per_convention) {
    std::optional<error_stats> all;
    for_each_convention([&](auto s_c, auto f_c) {
        constexpr quat::sequence S = decltype(s_c)::value;
        constexpr quat::frame F = decltype(f_c)::value;
        if (only_zyx_intrinsic && !(S == quat::sequence::zyx && F == quat::frame::intrinsic))
            return;
        const bool proper = axes_of(S)[0] == axes_of(S)[2];
        // Every library sees the same inputs for a convention: a generator seeded per convention.
        rng local{g.state + 1000 * std::uint64_t(S) + std::uint64_t(F)};
        const std::vector<v3<T>> inputs = gimbal ? gimbal_lock_euler_angles<T>(local, n, proper)
                                                 : random_euler_angles<T>(local, n, proper);
        const std::optional<error_stats> st = measure_euler<Lib, T, S, F>(inputs);
        if (!st) return;
        if (per_convention) per_convention->emplace_back(convention_name(S, F), st->max);
        if (!all) all = error_stats{};
        all->merge(*st);
    });
    return all;
}

}  // namespace accuracy
