// Point-set registration: the rigid motion (align_points) or the similarity (align_points_with_scale)
// that best maps one set of corresponding points onto another in the least-squares sense, after
// Kabsch (1976) and Umeyama ("Least-squares estimation of transformation parameters between two
// point patterns", IEEE PAMI 13(4), 1991), with the rotation from align_vectors' q-method instead of
// an SVD: the centred points are a Wahba problem, so there is never a reflection.
#ifndef QUAT_ALIGN_POINTS_HPP_INCLUDED
#define QUAT_ALIGN_POINTS_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "align_vectors.hpp"
#include "config.hpp"
#include "detail/containers.hpp"
#include "detail/math.hpp"
#include "detail/power_of_two.hpp"
#include "dual_quaternion.hpp"
#include "quaternion.hpp"
#include "vec3.hpp"

namespace quat {

/// The rigid motion that best maps sources onto targets, and how well it does (align_points).
template <class T>
struct point_alignment {
    /// Unit dual quaternion of x -> R x + t minimizing sum w_i |targets_i - (R sources_i + t)|^2;
    /// to_homogeneous(motion) is its 4x4 matrix.
    dual_quaternion<T> motion;
    /// The weighted root-mean-square residual sqrt(sum w_i |targets_i - motion(sources_i)|^2 /
    /// sum w_i), summed from the residuals.
    T rms;
    /// False when other motions fit as well: the points (of positive weight) lie on one line or
    /// coincide, fewer than three distinct among them (see align_points for the threshold).
    bool unique;
};

/// The similarity that best maps sources onto targets (align_points_with_scale): a point_alignment
/// whose motion holds R and t of x -> scale R x + t, and rms the residual of that map.
template <class T>
struct similarity_alignment : point_alignment<T> {
    /// The uniform scale, > 0.
    T scale;
};

#include "detail/isa_namespace.inc"
namespace detail {

/// True when every weight is finite and >= 0: the weighted registrations' precondition.
template <class T, class Weight>
[[nodiscard]] constexpr bool valid_weights(const Weight* weights, std::size_t count) noexcept {
    for (std::size_t i = 0; i < count; ++i) {
        const T w = static_cast<T>(weights[i]);
        if (!(w >= T(0)) || !detail::is_finite(w)) return false;
    }
    return true;
}

/// The weighted mean of point(i), i < count, with weights weight(i) / total (total their sum):
/// every term is at most its point's size, so nothing overflows, and a second pass adds the mean of
/// the remainders, which recovers the digits the first pass rounded away (points far from the
/// origin with a small spread keep their spread).
template <class T, class Point, class Weight>
[[nodiscard]] constexpr vec3<T> weighted_centroid(std::size_t count, Point point, Weight weight,
                                                  T total) noexcept {
    vec3<T> mean{T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) mean += point(i) * (weight(i) / total);
    vec3<T> correction{T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) correction += (point(i) - mean) * (weight(i) / total);
    return mean + correction;
}

/// The registration in three passes, for data whose sizes lie where Wahba's plain path needs them
/// (as align_vectors' solver tests them): the weighted sums; then B of the points less that first
/// mean, with the remainders that correct the mean (B = sum w a b^T - dt ds^T / W for the
/// remainders' sums dt, ds, exactly the B of the corrected centroids); then the residuals. The
/// scale is trace(R^T B) / sum w |b|^2. Empty where the data need the careful path (a NaN,
/// infinite, negative or all-zero weight, non-finite values, sizes out of range).
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr std::optional<similarity_alignment<T>> plain_registration(
    Target target, Source source, std::size_t count, Weight weight, bool scaled) noexcept {
    T total(0), lowest(0), heaviest(0), check(0);
    vec3<T> target_sum{T(0), T(0), T(0)}, source_sum{T(0), T(0), T(0)};
    for (std::size_t i = 0; i < count; ++i) {
        const T w = weight(i);
        const vec3<T> a = target(i), b = source(i);
        total += w;
        target_sum += a * w;
        source_sum += b * w;
        // 0 while every value is finite; NaN (or an overflow's infinity) otherwise.
        check += (a.x + a.y + a.z + b.x + b.y + b.z + w) * T(0);
        lowest = lowest < w ? lowest : w;
        heaviest = heaviest > w ? heaviest : w;
    }
    if (!(check == T(0)) || !(lowest >= T(0)) || !(total > T(0)) || !is_finite(total) ||
        scale_of(heaviest) != T(1))
        return std::nullopt;
    const vec3<T> mean_target = target_sum / total, mean_source = source_sum / total;
    T b[3][3] = {};
    vec3<T> target_rest{T(0), T(0), T(0)}, source_rest{T(0), T(0), T(0)};
    T spread(0), target_size(0), source_size(0);
    for (std::size_t i = 0; i < count; ++i) {
        const T w = weight(i);
        const vec3<T> a = target(i) - mean_target, b_i = source(i) - mean_source;
        const vec3<T> wa = a * w;
        const T wa_r[3] = {wa.x, wa.y, wa.z}, b_c[3] = {b_i.x, b_i.y, b_i.z};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) b[r][c] += wa_r[r] * b_c[c];
        target_rest += wa;
        source_rest += b_i * w;
        spread += w * dot(b_i, b_i);
        target_size = max(target_size, largest_magnitude(a));
        source_size = max(source_size, largest_magnitude(b_i));
    }
    const T rest_t[3] = {target_rest.x, target_rest.y, target_rest.z};
    const T rest_s[3] = {source_rest.x, source_rest.y, source_rest.z};
    bool finite = is_finite(spread);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            b[r][c] -= rest_t[r] * rest_s[c] / total;
            finite = finite && is_finite(b[r][c]);
        }
    if (!finite || scale_of(target_size) != T(1) || scale_of(source_size) != T(1))
        return std::nullopt;
    spread -= dot(source_rest, source_rest) / total;
    const vec3<T> ct = mean_target + target_rest / total, cs = mean_source + source_rest / total;
    const auto centred_target = [&](std::size_t i) { return target(i) - ct; };
    const auto centred_source = [&](std::size_t i) { return source(i) - cs; };
    const alignment<T> fit = rotation_of_profile(b, count, centred_target, centred_source, weight);
    const rotation_matrix<T> m = to_matrix(fit.rotation);
    T scale(1);
    bool determined = true;
    if (scaled) {
        T along(0);  // trace(R^T B)
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) along += m(r, c) * b[r][c];
        determined = along > T(0) && spread > T(0);
        scale = determined ? along / spread : T(1);
    }
    T squares(0);
    for (std::size_t i = 0; i < count; ++i) {
        const vec3<T> residual = centred_target(i) - rotate(m, centred_source(i)) * scale;
        squares += weight(i) * dot(residual, residual);
    }
    if (!is_finite(squares)) return std::nullopt;
    const vec3<T> translation = ct - rotate(m, cs) * scale;
    return similarity_alignment<T>{{to_dual_quaternion(fit.rotation, translation),
                                    sqrt(squares / total), fit.unique && determined},
                                   scale};
}

/// The registration of point sets: the centroids, the rotation of the centred points (Wahba's
/// problem), then the scale (Umeyama's trace(R^T B) / sum w |s_i - cs|^2, or 1) and the residual.
template <class T, class Target, class Source, class Weight>
[[nodiscard]] constexpr similarity_alignment<T> solve_registration(Target target, Source source,
                                                                   std::size_t count,
                                                                   Weight raw_weight,
                                                                   bool scaled) noexcept {
    if (const auto plain = plain_registration<T>(target, source, count, raw_weight, scaled))
        return *plain;
    T largest(0);
    bool finite = true;
    for (std::size_t i = 0; i < count; ++i) {
        const T w = raw_weight(i);
        const vec3<T> a = target(i), b = source(i);
        finite = finite && w >= T(0) && detail::is_finite(w) && detail::is_finite(a) &&
                 detail::is_finite(b);
        largest = detail::max(largest, w);
    }
    const T nan = detail::quiet_nan<T>();
    if (!finite) {
        const quaternion<T> q{nan, nan, nan, nan};
        return {{{q, q}, nan, false}, nan};
    }
    if (!(largest > T(0))) return {{dual_quaternion<T>::identity(), T(0), false}, T(1)};
    // Weights divided by the power of two of the largest: their sum neither overflows nor
    // underflows, and only their ratios count.
    const T pw = binade_of(largest);
    const auto weight = [&](std::size_t i) { return raw_weight(i) / pw; };
    T total(0);
    for (std::size_t i = 0; i < count; ++i) total += weight(i);
    const vec3<T> ct = weighted_centroid(count, target, weight, total);
    const vec3<T> cs = weighted_centroid(count, source, weight, total);
    const auto centred_target = [&](std::size_t i) { return target(i) - ct; };
    const auto centred_source = [&](std::size_t i) { return source(i) - cs; };
    const alignment<T> fit = solve_wahba<T>(centred_target, centred_source, count, weight).result;

    // The centred points divided by the powers of two of their largest components, so that
    // neither products of sizes nor sums of squares overflow or underflow.
    T target_size(0), source_size(0);
    for (std::size_t i = 0; i < count; ++i) {
        target_size = detail::max(target_size, largest_magnitude(centred_target(i)));
        source_size = detail::max(source_size, largest_magnitude(centred_source(i)));
    }
    const T pt = target_size > T(0) ? binade_of(target_size) : T(1);
    const T ps = source_size > T(0) ? binade_of(source_size) : T(1);
    const rotation_matrix<T> m = to_matrix(fit.rotation);
    const auto turned_source = [&](std::size_t i) { return rotate(m, centred_source(i) / ps); };
    T scale(1);
    bool determined = true;
    if (scaled) {
        T along(0), spread(0);
        for (std::size_t i = 0; i < count; ++i) {
            const vec3<T> s = turned_source(i);
            along += weight(i) * dot(centred_target(i) / pt, s);
            spread += weight(i) * dot(s, s);
        }
        // along >= 0 at the optimal rotation; 0 (targets or sources all equal) or no spread
        // leaves the scale undetermined.
        determined = along > T(0) && spread > T(0);
        scale = determined ? along / spread * (pt / ps) : T(1);
    }
    // The residuals in units of the larger side's power of two, so their squares stay in range.
    const T p = binade_of(detail::max(pt, scale * ps));
    const T factor = scale * (ps / p);
    T squares(0);
    for (std::size_t i = 0; i < count; ++i) {
        const vec3<T> residual = centred_target(i) / p - turned_source(i) * factor;
        squares += weight(i) * dot(residual, residual);
    }
    const vec3<T> translation = ct - rotate(m, cs) * scale;
    return {{to_dual_quaternion(fit.rotation, translation), sqrt(squares / total) * p,
             fit.unique && determined},
            scale};
}

/// solve_registration over arrays of points (of any precision) and a container of weights.
template <class T, class Targets, class Sources, class Weight>
[[nodiscard]] constexpr similarity_alignment<T> register_arrays(const Targets& targets,
                                                                const Sources& sources,
                                                                Weight weight,
                                                                bool scaled) noexcept {
    const auto* t = detail::data_of(targets);
    const auto* s = detail::data_of(sources);
    return solve_registration<T>([t](std::size_t i) { return vec3<T>(t[i]); },
                                 [s](std::size_t i) { return vec3<T>(s[i]); },
                                 detail::size_of(sources), weight, scaled);
}

/// The checked registration: empty for no points, mismatched sizes, non-finite values, a negative,
/// NaN or infinite weight, no positive weight, or a residual beyond max().
template <class T, class Targets, class Sources, class Weights>
[[nodiscard]] constexpr std::optional<similarity_alignment<T>> try_register(
    const Targets& targets, const Sources& sources, const Weights* weights,
    std::size_t weight_count, bool scaled) noexcept {
    const std::size_t count = detail::size_of(sources);
    if (count == 0 || detail::size_of(targets) != count || weight_count != count)
        return std::nullopt;
    bool positive = weights == nullptr;
    if (weights != nullptr) {
        if (!valid_weights<T>(weights, count)) return std::nullopt;
        for (std::size_t i = 0; i < count; ++i) positive = positive || weights[i] > 0;
    }
    if (!positive) return std::nullopt;
    const similarity_alignment<T> result =
        weights == nullptr
            ? register_arrays<T>(
                  targets, sources, [](std::size_t) { return T(1); }, scaled)
            : register_arrays<T>(
                  targets, sources, [weights](std::size_t i) { return static_cast<T>(weights[i]); },
                  scaled);
    if (!detail::is_finite(result.motion.real.w) || !detail::is_finite(result.rms) ||
        !detail::is_finite(largest_magnitude(result.motion.dual)) ||
        !detail::is_finite(result.scale))
        return std::nullopt;
    return result;
}

}  // namespace detail

/// The rigid motion x -> R x + t minimizing sum |targets[i] - (R sources[i] + t)|^2 (Kabsch), as a
/// unit dual quaternion: never a reflection. targets and sources are equally long (QUAT_ASSERT)
/// containers of vec3<T> with data() and size(), or C arrays, of corresponding points. The centroids
/// are taken in two passes, so points far from the origin keep their spread. unique is false when
/// the targets, or the sources, less their centroid, all lie within 64 epsilon radians of one line
/// (collinear points, fewer than three distinct): then the rotation is the one align_vectors
/// chooses for the centred points. No points: the identity, rms 0, not unique. A NaN or infinite
/// component gives NaN in every component, rms NaN, unique false; try_align_points checks instead.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr point_alignment<T> align_points(const Targets& targets,
                                                        const Sources& sources) noexcept {
    QUAT_ASSERT(detail::size_of(targets) == detail::size_of(sources),
                "quat::align_points: targets and sources differ in size");
    return detail::register_arrays<T>(
        targets, sources, [](std::size_t) { return T(1); }, false);
}

/// align_points with weights (a container of scalars convertible to T, as long as the points):
/// the motion minimizing sum weights[i] |targets[i] - (R sources[i] + t)|^2, with rms weighted
/// alike. A zero weight drops its pair; only the weights' ratios count. Precondition: weights >= 0
/// and finite (QUAT_ASSERT); unchecked, a negative, NaN or infinite weight gives the NaN result.
/// No positive weight: the identity, rms 0, not unique.
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr point_alignment<T> align_points(const Targets& targets,
                                                        const Sources& sources,
                                                        const Weights& weights) noexcept {
    QUAT_ASSERT(detail::size_of(targets) == detail::size_of(sources) &&
                    detail::size_of(weights) == detail::size_of(sources),
                "quat::align_points: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    QUAT_ASSERT(detail::valid_weights<T>(w, detail::size_of(weights)),
                "quat::align_points: a weight is negative, NaN or infinite");
    return detail::register_arrays<T>(
        targets, sources, [w](std::size_t i) { return static_cast<T>(w[i]); }, false);
}

/// The similarity x -> scale R x + t minimizing sum |targets[i] - (scale R sources[i] + t)|^2
/// (Umeyama 1991): motion holds R and t, scale > 0 is trace(R^T B) / sum |sources[i] - cs|^2 with
/// B the centred points' sum targets_c sources_c^T, rms the residual of the similarity. As
/// align_points otherwise; unique is also false (and scale 1) where the targets or the sources all
/// coincide, which leaves the scale undetermined.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr similarity_alignment<T> align_points_with_scale(
    const Targets& targets, const Sources& sources) noexcept {
    QUAT_ASSERT(detail::size_of(targets) == detail::size_of(sources),
                "quat::align_points_with_scale: targets and sources differ in size");
    return detail::register_arrays<T>(
        targets, sources, [](std::size_t) { return T(1); }, true);
}

/// align_points_with_scale with weights, as align_points(targets, sources, weights).
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr similarity_alignment<T> align_points_with_scale(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    QUAT_ASSERT(detail::size_of(targets) == detail::size_of(sources) &&
                    detail::size_of(weights) == detail::size_of(sources),
                "quat::align_points_with_scale: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    QUAT_ASSERT(detail::valid_weights<T>(w, detail::size_of(weights)),
                "quat::align_points_with_scale: a weight is negative, NaN or infinite");
    return detail::register_arrays<T>(
        targets, sources, [w](std::size_t i) { return static_cast<T>(w[i]); }, true);
}

/// align_points(targets, sources), or std::nullopt for input it does not register: no points,
/// different sizes, a NaN or infinite component, or a residual beyond max(). Collinear points are
/// not bad input: they give unique = false. Never asserts.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr std::optional<point_alignment<T>> try_align_points(
    const Targets& targets, const Sources& sources) noexcept {
    const auto result = detail::try_register<T>(targets, sources, static_cast<const T*>(nullptr),
                                                detail::size_of(sources), false);
    if (!result) return std::nullopt;
    return point_alignment<T>(*result);
}

/// align_points(targets, sources, weights), or std::nullopt as try_align_points(targets, sources)
/// and also for weights of another size, a negative, NaN or infinite weight, or none positive.
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr std::optional<point_alignment<T>> try_align_points(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    const auto result = detail::try_register<T>(targets, sources, detail::data_of(weights),
                                                detail::size_of(weights), false);
    if (!result) return std::nullopt;
    return point_alignment<T>(*result);
}

/// align_points_with_scale(targets, sources), or std::nullopt as try_align_points.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr std::optional<similarity_alignment<T>> try_align_points_with_scale(
    const Targets& targets, const Sources& sources) noexcept {
    return detail::try_register<T>(targets, sources, static_cast<const T*>(nullptr),
                                   detail::size_of(sources), true);
}

/// align_points_with_scale(targets, sources, weights), or std::nullopt as try_align_points with
/// weights.
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr std::optional<similarity_alignment<T>> try_align_points_with_scale(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    return detail::try_register<T>(targets, sources, detail::data_of(weights),
                                   detail::size_of(weights), true);
}

}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_ALIGN_POINTS_HPP_INCLUDED
