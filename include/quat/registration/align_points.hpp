// Point-set registration: the rigid motion (align_points) or the similarity
// (align_points_with_scale) that best maps one set of corresponding points onto another in the
// least-squares sense, after Kabsch (1976) and Umeyama ("Least-squares estimation of transformation
// parameters between two point patterns", IEEE PAMI 13(4), 1991), with the rotation from
// align_vectors' q-method instead of an SVD: the centred points are a Wahba problem, so there is
// never a reflection.
#ifndef QUAT_REGISTRATION_ALIGN_POINTS_HPP_INCLUDED
#define QUAT_REGISTRATION_ALIGN_POINTS_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../detail/math.hpp"
#include "../fitting/align_vectors.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../rigid/similarity.hpp"
#include "../vec3.hpp"
#include "detail/registration.hpp"

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
/// whose motion holds R and t of x -> scale R x + t, and rms the residual of that map. motion alone
/// is not the fit: transform(fit.motion, p) leaves the scale out. to_similarity(fit) is the fit
/// with its scale, to apply (transform), compose, invert or write as a 4x4 matrix (to_matrix4).
template <class T>
struct similarity_alignment : point_alignment<T> {
    /// The uniform scale, > 0.
    T scale;
};

#include "../detail/isa_namespace.inc"
namespace detail {

/// True when every weight is finite and >= 0 and, with `some_positive`, one at least is > 0: the
/// weighted registrations' precondition.
template <class T, class Weight>
[[nodiscard]] constexpr bool valid_weights(const Weight* weights, std::size_t count,
                                           bool some_positive = false) noexcept {
    bool positive = false;
    for (std::size_t i = 0; i < count; ++i) {
        const T w = static_cast<T>(weights[i]);
        if (!(w >= T(0)) || !detail::is_finite(w)) return false;
        positive = positive || w > T(0);
    }
    return positive || !some_positive;
}

/// solve_registration over arrays of points (of any precision) and a container of weights; the NaN
/// result, unique false, where paired says the containers differ in size.
template <class T, class Targets, class Sources, class Weight>
[[nodiscard]] constexpr similarity_alignment<T> register_arrays(const Targets& targets,
                                                                const Sources& sources,
                                                                Weight weight, bool scaled,
                                                                bool paired) noexcept {
    if (!paired) {
        const T nan = quiet_nan<T>();
        return {{{nan_quaternion<T>(), nan_quaternion<T>()}, nan, false}, nan};
    }
    const auto* t = detail::data_of(targets);
    const auto* s = detail::data_of(sources);
    const registration<T> r = solve_registration<T>([t](std::size_t i) { return vec3<T>(t[i]); },
                                                    [s](std::size_t i) { return vec3<T>(s[i]); },
                                                    detail::size_of(sources), weight, scaled);
    return {{to_dual_quaternion(r.rotation, r.translation), r.rms, r.unique}, r.scale};
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
    if (weights != nullptr && !valid_weights<T>(weights, count, true)) return std::nullopt;
    const similarity_alignment<T> result =
        weights == nullptr
            ? register_arrays<T>(
                  targets, sources, [](std::size_t) { return T(1); }, scaled, true)
            : register_arrays<T>(
                  targets, sources, [weights](std::size_t i) { return static_cast<T>(weights[i]); },
                  scaled, true);
    if (!detail::is_finite(result.motion.real.w) || !detail::is_finite(result.rms) ||
        !detail::is_finite(largest_magnitude(result.motion.dual)) ||
        !detail::is_finite(result.scale))
        return std::nullopt;
    return result;
}

}  // namespace detail

/// The fitted similarity x -> scale R x + t, scale included: {fit.motion, fit.scale}.
template <class T>
[[nodiscard]] constexpr similarity<T> to_similarity(const similarity_alignment<T>& fit) noexcept {
    return {fit.motion, fit.scale};
}

/// The rigid motion x -> R x + t minimizing sum |targets[i] - (R sources[i] + t)|^2 (Kabsch), as a
/// unit dual quaternion: never a reflection. targets and sources are equally long containers of
/// vec3<T> with data() and size(), or C arrays, of corresponding points (QUAT_ASSERT; unchecked,
/// other lengths give the NaN result below, and no element past either container is read). The
/// centroids are taken in two passes, so points far from the origin keep their spread. unique is
/// false when the targets, or the sources, less their centroid, all lie within 64 epsilon radians
/// of one line (collinear points, fewer than three distinct): then the rotation is the one
/// align_vectors chooses for the centred points. No points: the identity, rms 0, not unique. A NaN
/// or infinite component gives NaN in every component, rms NaN, unique false; try_align_points
/// checks instead.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr point_alignment<T> align_points(const Targets& targets,
                                                        const Sources& sources) noexcept {
    QUAT_ASSERT(detail::same_size(targets, sources),
                "quat::align_points: targets and sources differ in size");
    return detail::register_arrays<T>(
        targets, sources, [](std::size_t) { return T(1); }, false,
        detail::same_size(targets, sources));
}

/// align_points with weights (a container of scalars convertible to T, as long as the points;
/// other lengths as in align_points(targets, sources)):
/// the motion minimizing sum weights[i] |targets[i] - (R sources[i] + t)|^2, with rms weighted
/// alike. A zero weight drops its pair; only the weights' ratios count. Precondition: weights >= 0
/// and finite (QUAT_ASSERT); unchecked, a negative, NaN or infinite weight gives the NaN result.
/// No positive weight: the identity, rms 0, not unique.
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr point_alignment<T> align_points(const Targets& targets,
                                                        const Sources& sources,
                                                        const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(targets, sources, weights),
                "quat::align_points: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    QUAT_ASSERT(detail::valid_weights<T>(w, detail::size_of(weights)),
                "quat::align_points: a weight is negative, NaN or infinite");
    return detail::register_arrays<T>(
        targets, sources, [w](std::size_t i) { return static_cast<T>(w[i]); }, false,
        detail::same_size(targets, sources, weights));
}

/// The similarity x -> scale R x + t minimizing sum |targets[i] - (scale R sources[i] + t)|^2
/// (Umeyama 1991): motion holds R and t, scale > 0 is trace(R^T B) / sum |sources[i] - cs|^2 with
/// B the centred points' sum targets_c sources_c^T, rms the residual of the similarity. As
/// align_points otherwise; unique is also false (and scale 1) where the targets or the sources all
/// coincide, which leaves the scale undetermined.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr similarity_alignment<T> align_points_with_scale(
    const Targets& targets, const Sources& sources) noexcept {
    QUAT_ASSERT(detail::same_size(targets, sources),
                "quat::align_points_with_scale: targets and sources differ in size");
    return detail::register_arrays<T>(
        targets, sources, [](std::size_t) { return T(1); }, true,
        detail::same_size(targets, sources));
}

/// align_points_with_scale with weights, as align_points(targets, sources, weights).
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr similarity_alignment<T> align_points_with_scale(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(targets, sources, weights),
                "quat::align_points_with_scale: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    QUAT_ASSERT(detail::valid_weights<T>(w, detail::size_of(weights)),
                "quat::align_points_with_scale: a weight is negative, NaN or infinite");
    return detail::register_arrays<T>(
        targets, sources, [w](std::size_t i) { return static_cast<T>(w[i]); }, true,
        detail::same_size(targets, sources, weights));
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

#endif  // QUAT_REGISTRATION_ALIGN_POINTS_HPP_INCLUDED
