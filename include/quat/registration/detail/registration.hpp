// The least-squares rigid motion or similarity between corresponding point sets, behind
// registration/align_points.hpp: three passes over the points in blocks of struct-of-arrays form,
// so that the sums vectorize, and, for data whose sizes the passes cannot take as they are, the
// same passes on the centred data divided by powers of two.
#ifndef QUAT_REGISTRATION_DETAIL_REGISTRATION_HPP_INCLUDED
#define QUAT_REGISTRATION_DETAIL_REGISTRATION_HPP_INCLUDED

#include <cstddef>
#include <optional>
#include <type_traits>

#include "../../detail/math.hpp"
#include "../../detail/power_of_two.hpp"
#include "../../fitting/detail/wahba.hpp"
#include "../../quaternion.hpp"
#include "../../rotation_matrix.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

// x -> scale R x + translation, its weighted RMS residual, and whether it is the only best fit.
template <class T>
struct registration {
    quaternion<T> rotation;
    vec3<T> translation;
    T rms;
    T scale;
    bool unique;
};

// Partial sums per quantity for large sets (a vector register of floats: each lane sums every
// eighth pair, so the sums vectorize without reassociation by the compiler), over blocks of pairs
// copied to struct-of-arrays form. Measured on 4096 float pairs (g++ 12, -march=native, AVX-512):
// align_points takes 9.7 us in blocks of 256 pairs, 12.8 us in blocks of 64, 24.4 us pair by pair
// as before; clang 19 does not vectorize the copy and stays at 30 us either way. Sets below 64
// pairs are summed in one lane (register_in_range). Each quantity's term is written out in the
// functions that add a pair (add in sum_pairs), with no loop of its own: g++ 12 vectorizes the loop
// over the lanes at -O2 only where nothing inside it loops (100 double pairs: 3.2 us with the
// loops, 1.7 us written out).
inline constexpr std::size_t registration_lanes = 8;

// A block of pairs less their offsets, coordinate by coordinate, padded to whole lanes with zero
// pairs of zero weight (which add nothing to any sum, and nothing below zero to any maximum).
template <class T, std::size_t Lanes, std::size_t Size>
struct pair_block {
    static_assert(Size % Lanes == 0, "a block holds whole lanes");
    static constexpr std::size_t size = Size;
    T target[3][size];
    T source[3][size];
    T weight[size];
    std::size_t padded;
};

template <class T, std::size_t Lanes, std::size_t Size, class Target, class Source, class Weight>
constexpr void load_pairs(pair_block<T, Lanes, Size>& block, std::size_t start, std::size_t count,
                          Target target, Source source, Weight weight, const vec3<T>& target_offset,
                          const vec3<T>& source_offset) noexcept {
    const auto load = [&](std::size_t i) {
        const vec3<T> a = target(start + i) - target_offset, b = source(start + i) - source_offset;
        block.target[0][i] = a.x;
        block.target[1][i] = a.y;
        block.target[2][i] = a.z;
        block.source[0][i] = b.x;
        block.source[1][i] = b.y;
        block.source[2][i] = b.z;
        block.weight[i] = weight(start + i);
    };
    // A whole block in a loop of constant length, which compilers vectorize.
    if (count == Size) {
        for (std::size_t i = 0; i < Size; ++i) load(i);
    } else {
        for (std::size_t i = 0; i < count; ++i) load(i);
    }
    block.padded = (count + Lanes - 1) / Lanes * Lanes;
    for (std::size_t i = count; i < block.padded; ++i) {
        for (std::size_t c = 0; c < 3; ++c) block.target[c][i] = block.source[c][i] = T(0);
        block.weight[i] = T(0);
    }
}

// Per lane, the totals of `Count` quantities over all pairs less the offsets: add(block, i, lane,
// sums) adds pair i's terms to sums[k][lane] (or takes their maximum). Each block's sums start from
// zero and are added to the totals, so rounding grows with the block length plus the number of
// blocks; the last `Maxima` quantities of sum_pairs are maxima instead, combined as such.
template <class T, std::size_t Count, std::size_t Lanes>
struct lane_totals {
    T value[Count][Lanes];

    // The sum over the lanes of quantity k, and the largest of them (for a maximum).
    [[nodiscard]] constexpr T sum(std::size_t k) const noexcept {
        T total(0);
        for (std::size_t lane = 0; lane < Lanes; ++lane) total += value[k][lane];
        return total;
    }
    [[nodiscard]] constexpr T largest(std::size_t k) const noexcept {
        T top = value[k][0];
        for (std::size_t lane = 1; lane < Lanes; ++lane) top = detail::max(top, value[k][lane]);
        return top;
    }
};

// sum_pairs' loop over the blocks, through a block the caller provides.
template <class T, std::size_t Count, std::size_t Maxima, std::size_t Lanes, class Block,
          class Target, class Source, class Weight, class Add>
[[nodiscard]] constexpr lane_totals<T, Count, Lanes> sum_blocks(
    Block& block, std::size_t count, Target target, Source source, Weight weight,
    const vec3<T>& target_offset, const vec3<T>& source_offset, Add add) noexcept {
    lane_totals<T, Count, Lanes> totals{};
    for (std::size_t start = 0; start < count; start += Block::size) {
        const std::size_t size = count - start < Block::size ? count - start : Block::size;
        T sums[Count][Lanes] = {};
        if constexpr (Lanes == 1) {
            for (std::size_t i = 0; i < size; ++i) {
                load_pairs(block, start + i, 1, target, source, weight, target_offset,
                           source_offset);
                add(block, 0, 0, sums);
            }
        } else {
            load_pairs(block, start, size, target, source, weight, target_offset, source_offset);
            for (std::size_t i = 0; i < block.padded; i += Lanes)
                for (std::size_t lane = 0; lane < Lanes; ++lane) add(block, i + lane, lane, sums);
        }
        // The last `Maxima` quantities are maxima: they carry over, the others are added.
        for (std::size_t k = 0; k + Maxima < Count; ++k)
            for (std::size_t lane = 0; lane < Lanes; ++lane) totals.value[k][lane] += sums[k][lane];
        for (std::size_t k = Count - Maxima; k < Count; ++k)
            for (std::size_t lane = 0; lane < Lanes; ++lane)
                totals.value[k][lane] = detail::max(totals.value[k][lane], sums[k][lane]);
    }
    return totals;
}

// sum_blocks through a block left uncleared, at run time only (a constexpr function cannot hold
// one before C++20): load_pairs writes every element the sums read, and clearing a block of 256
// double pairs (14 KiB) in each of the three passes took a fifth of the time for 100 pairs.
template <class T, std::size_t Count, std::size_t Maxima, std::size_t Lanes, class Block,
          class Target, class Source, class Weight, class Add>
[[nodiscard]] lane_totals<T, Count, Lanes> sum_blocks_uncleared(std::size_t count, Target target,
                                                                Source source, Weight weight,
                                                                const vec3<T>& target_offset,
                                                                const vec3<T>& source_offset,
                                                                Add add) noexcept {
    Block block;
    return sum_blocks<T, Count, Maxima, Lanes>(block, count, target, source, weight, target_offset,
                                               source_offset, add);
}

template <class T, std::size_t Count, std::size_t Maxima, std::size_t Lanes, std::size_t Size,
          class Target, class Source, class Weight, class Add>
[[nodiscard]] constexpr lane_totals<T, Count, Lanes> sum_pairs(std::size_t count, Target target,
                                                               Source source, Weight weight,
                                                               const vec3<T>& target_offset,
                                                               const vec3<T>& source_offset,
                                                               Add add) noexcept {
    // One lane reads the pairs where they are, one at a time into a one-pair block (registers):
    // copying them to a cleared block first took about 10 % of align_points for four pairs. Either
    // way the sums restart from zero every `Size` pairs, so the result is the same. A local block:
    // the compiler then knows that its stores do not alias the input.
    using block_type = pair_block<T, Lanes, Lanes == 1 ? 1 : Size>;
    if (!constant_evaluated())
        return sum_blocks_uncleared<T, Count, Maxima, Lanes, block_type>(
            count, target, source, weight, target_offset, source_offset, add);
    block_type block{};
    return sum_blocks<T, Count, Maxima, Lanes>(block, count, target, source, weight, target_offset,
                                               source_offset, add);
}

// The registration in three passes, for data whose sizes the passes can take as they are: the
// weighted sums; then B of the pairs less that first mean, with the remainders that correct the
// mean (B = sum w a b^T - dt ds^T / W for the remainders' sums dt, ds, exactly the B of the
// corrected centroids); then the residuals. With `scaled` the scale is Umeyama's trace(R^T B) / sum
// w |b|^2, otherwise it is `unit`. Empty where the data need solve_registration's centred path: a
// NaN or infinite value, a negative or NaN weight, no positive weight, weights or centred sizes
// outside [min()^(1/4), max()^(1/4)] (scale_of), a sum that overflows.
template <class T, std::size_t Lanes, std::size_t Size, class Target, class Source, class Weight>
[[nodiscard]] constexpr std::optional<registration<T>> register_in_lanes(
    Target target, Source source, std::size_t count, Weight weight, bool scaled, T unit,
    T as_is_gap = T(1)) noexcept {
    const vec3<T> origin{T(0), T(0), T(0)};
    // The weights' total, the weighted sums of targets and sources, a sum that is 0 while every
    // value is finite (NaN or an overflow's infinity otherwise); the heaviest weight and minus the
    // lowest, as maxima.
    const lane_totals<T, 10, Lanes> first = sum_pairs<T, 10, 2, Lanes, Size>(
        count, target, source, weight, origin, origin,
        [](const auto& block, std::size_t i, std::size_t lane, auto& s) {
            const T w = block.weight[i];
            const T t0 = block.target[0][i], t1 = block.target[1][i], t2 = block.target[2][i];
            const T s0 = block.source[0][i], s1 = block.source[1][i], s2 = block.source[2][i];
            s[0][lane] += w;
            s[1][lane] += t0 * w;
            s[2][lane] += t1 * w;
            s[3][lane] += t2 * w;
            s[4][lane] += s0 * w;
            s[5][lane] += s1 * w;
            s[6][lane] += s2 * w;
            s[7][lane] += (t0 + t1 + t2 + s0 + s1 + s2 + w) * T(0);
            s[8][lane] = detail::max(s[8][lane], w);
            s[9][lane] = detail::max(s[9][lane], -w);
        });
    const T total = first.sum(0);
    if (!(first.sum(7) == T(0)) || !(first.largest(9) <= T(0)) || !(total > T(0)) ||
        !detail::is_finite(total) || scale_of(first.largest(8)) != T(1))
        return std::nullopt;
    const vec3<T> mean_target = vec3<T>{first.sum(1), first.sum(2), first.sum(3)} / total;
    const vec3<T> mean_source = vec3<T>{first.sum(4), first.sum(5), first.sum(6)} / total;

    // B of the pairs less the first means (0 to 8), the remainders' weighted sums (9 to 14), the
    // sources' spread (15), and the largest centred components (16, 17).
    const lane_totals<T, 18, Lanes> second = sum_pairs<T, 18, 2, Lanes, Size>(
        count, target, source, weight, mean_target, mean_source,
        [](const auto& block, std::size_t i, std::size_t lane, auto& s) {
            const T w = block.weight[i];
            const T t0 = block.target[0][i], t1 = block.target[1][i], t2 = block.target[2][i];
            const T s0 = block.source[0][i], s1 = block.source[1][i], s2 = block.source[2][i];
            const T wa0 = t0 * w, wa1 = t1 * w, wa2 = t2 * w;
            s[0][lane] += wa0 * s0;
            s[1][lane] += wa0 * s1;
            s[2][lane] += wa0 * s2;
            s[3][lane] += wa1 * s0;
            s[4][lane] += wa1 * s1;
            s[5][lane] += wa1 * s2;
            s[6][lane] += wa2 * s0;
            s[7][lane] += wa2 * s1;
            s[8][lane] += wa2 * s2;
            s[9][lane] += wa0;
            s[10][lane] += wa1;
            s[11][lane] += wa2;
            s[12][lane] += s0 * w;
            s[13][lane] += s1 * w;
            s[14][lane] += s2 * w;
            s[15][lane] += (s0 * s0 + s1 * s1 + s2 * s2) * w;
            s[16][lane] = detail::max(s[16][lane], largest_magnitude(vec3<T>{t0, t1, t2}));
            s[17][lane] = detail::max(s[17][lane], largest_magnitude(vec3<T>{s0, s1, s2}));
        });
    const vec3<T> target_rest{second.sum(9), second.sum(10), second.sum(11)};
    const vec3<T> source_rest{second.sum(12), second.sum(13), second.sum(14)};
    const T rest_t[3] = {target_rest.x, target_rest.y, target_rest.z};
    const T rest_s[3] = {source_rest.x, source_rest.y, source_rest.z};
    T b[3][3] = {};
    T spread = second.sum(15);
    bool finite = detail::is_finite(spread);
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) {
            b[r][c] = second.sum(3 * r + c) - rest_t[r] * rest_s[c] / total;
            finite = finite && detail::is_finite(b[r][c]);
        }
    if (!finite || scale_of(second.largest(16)) != T(1) || scale_of(second.largest(17)) != T(1))
        return std::nullopt;
    spread -= dot(source_rest, source_rest) / total;
    const vec3<T> ct = mean_target + target_rest / total, cs = mean_source + source_rest / total;
    const alignment<T> fit = rotation_of_profile(
        b, count, [&](std::size_t i) { return target(i) - ct; },
        [&](std::size_t i) { return source(i) - cs; }, weight, as_is_gap);
    const rotation_matrix<T> m = to_matrix(fit.rotation);
    T scale = unit;
    bool determined = true;
    if (scaled) {
        T along(0);  // trace(R^T B)
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 3; ++c)
                along += m(static_cast<int>(r), static_cast<int>(c)) * b[r][c];
        // along >= 0 at the optimal rotation; 0 (targets or sources all equal) or no spread
        // leaves the scale undetermined.
        determined = along > T(0) && spread > T(0);
        scale = determined ? along / spread : unit;
    }

    // The residuals of the pairs less the corrected centroids, target - scale R source, in units
    // of the power of two p of the larger side, so that their squares stay in range.
    const T side = detail::max(second.largest(16), scale * second.largest(17));
    const T p = binade_or_one(side);
    rotation_matrix<T> turn{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) turn(r, c) = m(r, c) * (scale / p);
    const T inverse_p = T(1) / p;
    const lane_totals<T, 1, Lanes> third = sum_pairs<T, 1, 0, Lanes, Size>(
        count, target, source, weight, ct, cs,
        [&turn, inverse_p](const auto& block, std::size_t i, std::size_t lane, auto& s) {
            const T t0 = block.target[0][i], t1 = block.target[1][i], t2 = block.target[2][i];
            const T s0 = block.source[0][i], s1 = block.source[1][i], s2 = block.source[2][i];
            const T r0 = t0 * inverse_p - (turn(0, 0) * s0 + turn(0, 1) * s1 + turn(0, 2) * s2);
            const T r1 = t1 * inverse_p - (turn(1, 0) * s0 + turn(1, 1) * s1 + turn(1, 2) * s2);
            const T r2 = t2 * inverse_p - (turn(2, 0) * s0 + turn(2, 1) * s1 + turn(2, 2) * s2);
            s[0][lane] += block.weight[i] * (r0 * r0 + r1 * r1 + r2 * r2);
        });
    const T squares = third.sum(0);
    if (!detail::is_finite(squares)) return std::nullopt;
    return registration<T>{fit.rotation, ct - rotate(m, cs) * scale,
                           detail::sqrt(squares / total) * p, scale, fit.unique && determined};
}

// register_in_lanes in vector lanes for sets of 64 pairs or more, pair by pair below that. Few
// float pairs are summed and solved in double, where FOAM's closed form is within a small fraction
// of float's eps down to a gap bound of 1/256 (its error is about double's eps / bound^2), so they
// need no Newton steps: 3 and 4 float pairs took 40 % less time, their worst rotation error over
// 20,000 noisy sets fell from 22 to 0.84 float eps. Sets of built-in scalars take blocks of 32
// pairs a lane (7 KiB of float); larger scalars (autodiff types) keep the stack small with 8.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr std::optional<registration<T>> register_in_range(
    Target target, Source source, std::size_t count, Weight weight, bool scaled, T unit) noexcept {
    constexpr std::size_t lanes = registration_lanes;
    constexpr std::size_t per_lane = sizeof(T) <= sizeof(double) ? 32 : 8;
    constexpr std::size_t few = 63;
    if constexpr (std::is_same_v<T, float>) {
        if (count <= few) {
            const auto wide = register_in_lanes<double, 1, per_lane>(
                [&](std::size_t i) { return vec3<double>(target(i)); },
                [&](std::size_t i) { return vec3<double>(source(i)); }, count,
                [&](std::size_t i) { return double(weight(i)); }, scaled, double(unit), 1.0 / 256);
            if (!wide) return std::nullopt;
            return registration<float>{quaternion<float>(wide->rotation),
                                       vec3<float>(wide->translation), float(wide->rms),
                                       float(wide->scale), wide->unique};
        }
    }
    if (count <= few)
        return register_in_lanes<T, 1, per_lane>(target, source, count, weight, scaled, unit);
    return register_in_lanes<T, lanes, per_lane * lanes>(target, source, count, weight, scaled,
                                                         unit);
}

// The weighted mean of point(i), i < count, with weights weight(i) / total (total their sum):
// every term is at most its point's size, so nothing overflows, and a second pass adds the mean of
// the remainders, which recovers the digits the first pass rounded away (points far from the
// origin with a small spread keep their spread).
template <class T, class Point, class Weight>
[[nodiscard]] constexpr vec3<T> weighted_centroid(std::size_t count, Point point, Weight weight,
                                                  T total) noexcept {
    vec3<T> mean{T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) mean += point(i) * (weight(i) / total);
    vec3<T> correction{T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) correction += (point(i) - mean) * (weight(i) / total);
    return mean + correction;
}

// The registration of any finite data: register_in_range where the data allow it; otherwise the
// weights divided by the power of two of the largest, the centroids taken term by term (nothing
// overflows), and register_in_range of the centred targets and sources each divided by the power
// of two of its largest component, the rigid case with the fixed scale ps / pt between them. A NaN
// or infinite value or weight, or a negative one, gives NaN; no positive weight, the identity.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr registration<T> solve_registration(Target target, Source source,
                                                           std::size_t count, Weight raw_weight,
                                                           bool scaled) noexcept {
    if (const auto plain = register_in_range<T>(target, source, count, raw_weight, scaled, T(1)))
        return *plain;
    T largest(0);
    bool finite = true;
    for (std::size_t i = 0; i < count; ++i) {
        const T w = raw_weight(i);
        finite = finite && w >= T(0) && detail::is_finite(w) && detail::is_finite(target(i)) &&
                 detail::is_finite(source(i));
        largest = detail::max(largest, w);
    }
    const T nan = detail::quiet_nan<T>();
    const registration<T> failed{{nan, nan, nan, nan}, {nan, nan, nan}, nan, nan, false};
    if (!finite) return failed;
    if (!(largest > T(0)))
        return {quaternion<T>::identity(), {T(0), T(0), T(0)}, T(0), T(1), false};
    const T pw = binade_of(largest);
    const auto weight = [&](std::size_t i) { return raw_weight(i) / pw; };
    T total(0);
    for (std::size_t i = 0; i < count; ++i) total += weight(i);
    const vec3<T> ct = weighted_centroid(count, target, weight, total);
    const vec3<T> cs = weighted_centroid(count, source, weight, total);
    T target_size(0), source_size(0);
    for (std::size_t i = 0; i < count; ++i) {
        target_size = detail::max(target_size, largest_magnitude(target(i) - ct));
        source_size = detail::max(source_size, largest_magnitude(source(i) - cs));
    }
    const T pt = binade_or_one(target_size);
    const T ps = binade_or_one(source_size);
    const auto centred = register_in_range<T>([&](std::size_t i) { return (target(i) - ct) / pt; },
                                              [&](std::size_t i) { return (source(i) - cs) / ps; },
                                              count, weight, scaled, ps / pt);
    // Empty only where a centred point overflowed (points at both ends of the range).
    if (!centred) return failed;
    // target = ct + pt t', source = cs + ps s', t' ~ k R s' + c: scale k pt / ps.
    const T scale = centred->scale * (pt / ps);
    const rotation_matrix<T> m = to_matrix(centred->rotation);
    return {centred->rotation, ct + centred->translation * pt - rotate(m, cs) * scale,
            centred->rms * pt, scaled ? scale : T(1), centred->unique};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_REGISTRATION_DETAIL_REGISTRATION_HPP_INCLUDED
