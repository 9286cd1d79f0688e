// Wahba's problem: the rotation that best aligns one set of vectors with another, as scipy's
// Rotation.align_vectors finds it, with the residual and scipy's sensitivity matrix.
#ifndef QUAT_FITTING_ALIGN_VECTORS_HPP_INCLUDED
#define QUAT_FITTING_ALIGN_VECTORS_HPP_INCLUDED

#include <cstddef>
#include <optional>

#include "../config.hpp"
#include "../detail/containers.hpp"
#include "../matrix.hpp"
#include "../quaternion.hpp"
#include "../rotation_matrix.hpp"
#include "../vec3.hpp"
#include "detail/wahba.hpp"

namespace quat {

/// The rotation that best aligns two sets of vectors, and how well it does (align_vectors).
template <class T>
struct alignment {
    /// Unit quaternion, w >= 0, of the rotation R minimizing sum w_i |targets_i - R sources_i|^2.
    quaternion<T> rotation;
    /// sqrt(sum w_i |targets_i - R sources_i|^2), summed from the residuals.
    T rssd;
    /// False when other rotations fit as well: one pair, collinear vectors, and a few symmetric
    /// sets (see align_vectors for the thresholds).
    bool unique;
};

/// An alignment and scipy's sensitivity matrix (align_vectors_with_sensitivity): an alignment
/// with one more field, so it passes wherever an alignment<T> is taken.
template <class T>
struct alignment_with_sensitivity : alignment<T> {
    /// Symmetric 3x3 matrix, read as sensitivity(row, col), proportional to the covariance of the
    /// rotation's error as a small rotation vector in the targets' frame: scipy's (1.10) matrix
    /// for return_sensitivity=True.
    matrix3<T> sensitivity;
};

#include "../detail/isa_namespace.inc"

/// The rotation R minimizing sum |targets[i] - R sources[i]|^2 (Wahba's problem), the one scipy's
/// Rotation.align_vectors(a=targets, b=sources) returns: always a proper rotation, never a
/// reflection. targets and sources are equally long containers of vec3<T> with data() and size(),
/// or C arrays (QUAT_ASSERT; unchecked, other lengths give the NaN result below); the vectors need
/// not be unit, and longer ones count more, as in scipy. Any finite sizes, subnormal to max(), give
/// the same rotation (the data are scaled by powers of two first). unique is false when other
/// rotations fit as well: when the sources, or the targets, of the pairs with a positive weight and
/// non-zero vectors all lie within 64 epsilon radians of one line (B = sum targets[i] sources[i]^T
/// has rank one or zero), or the two best rotations tie to rounding (Davenport's K's top two
/// eigenvalues within 32 epsilon of max |B(i, j)|: a few symmetric sets). Then the optimal rotation
/// nearest the identity: rotation_between(sources[0], targets[0]) for one pair, the identity for no
/// pairs (rssd 0). A NaN or infinite component gives a NaN rotation and rssd, unique = false.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr alignment<T> align_vectors(const Targets& targets,
                                                   const Sources& sources) noexcept {
    QUAT_ASSERT(detail::same_size(targets, sources),
                "quat::align_vectors: targets and sources differ in size");
    if (!detail::same_size(targets, sources)) return detail::nan_wahba<T>(false).result;
    return detail::solve_wahba<T>(detail::data_of(targets), detail::data_of(sources),
                                  detail::size_of(sources), [](std::size_t) { return T(1); })
        .result;
}

/// align_vectors with weights (a container of scalars convertible to T, as long as the vectors;
/// other lengths as in align_vectors(targets, sources)):
/// R minimizes sum weights[i] |targets[i] - R sources[i]|^2, and rssd is weighted alike. A zero
/// weight drops its pair; weights may spread over many orders of magnitude (the rotation is
/// polished by Newton steps where they leave Davenport's eigenvector coarse). One infinite weight
/// (scipy >= 1.11): its pair is aligned exactly in direction, by the shortest arc, the others
/// choose the turn about that pair's target, and rssd leaves that pair out; unique is then false
/// when the other pairs have no component across that target (the turn is 0). Two or more infinite
/// weights (scipy raises), a NaN weight, or an infinite weight on a zero vector give a NaN result.
/// Precondition: weights >= 0 (QUAT_ASSERT; unchecked, a negative weight counts against its pair,
/// and rssd may be NaN).
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr alignment<T> align_vectors(const Targets& targets, const Sources& sources,
                                                   const Weights& weights) noexcept {
    QUAT_ASSERT(detail::same_size(targets, sources, weights),
                "quat::align_vectors: targets, sources and weights differ in size");
    if (!detail::same_size(targets, sources, weights)) return detail::nan_wahba<T>(false).result;
    const auto* w = detail::data_of(weights);
    const detail::wahba_solution<T> solution = detail::solve_wahba<T>(
        detail::data_of(targets), detail::data_of(sources), detail::size_of(sources),
        [w](std::size_t i) { return static_cast<T>(w[i]); });
    QUAT_ASSERT(!solution.negative, "quat::align_vectors: a weight is negative");
    return solution.result;
}

namespace detail {

/// The alignment of count pairs, or std::nullopt where it is NaN or its rssd overflows.
template <class T, class Weight>
[[nodiscard]] constexpr std::optional<alignment<T>> checked_alignment(const vec3<T>* targets,
                                                                      const vec3<T>* sources,
                                                                      std::size_t count,
                                                                      Weight weight) noexcept {
    const alignment<T> result = solve_wahba<T>(targets, sources, count, weight).result;
    if (!is_finite(result.rotation.w) || !is_finite(result.rssd)) return std::nullopt;
    return result;
}

}  // namespace detail

/// align_vectors(targets, sources), or std::nullopt for input it does not align: no pairs,
/// containers of different sizes, a NaN or infinite component, or an rssd beyond max() (vectors
/// near max() that stay apart). A set that fits other rotations as well is not bad input: it gives
/// an alignment with unique = false, as align_vectors does. Never asserts.
template <class Targets, class Sources, class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr std::optional<alignment<T>> try_align_vectors(
    const Targets& targets, const Sources& sources) noexcept {
    const std::size_t count = detail::size_of(sources);
    if (count == 0 || detail::size_of(targets) != count) return std::nullopt;
    return detail::checked_alignment<T>(detail::data_of(targets), detail::data_of(sources), count,
                                        [](std::size_t) { return T(1); });
}

/// align_vectors(targets, sources, weights), or std::nullopt as try_align_vectors(targets, sources)
/// and also when the weights differ in size, a weight is negative or NaN, no weight is positive, or
/// more than one is infinite. Never asserts.
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr std::optional<alignment<T>> try_align_vectors(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    const std::size_t count = detail::size_of(sources);
    if (count == 0 || detail::size_of(targets) != count || detail::size_of(weights) != count)
        return std::nullopt;
    const auto* w = detail::data_of(weights);
    bool positive = false;
    for (std::size_t i = 0; i < count; ++i) {
        const T wi = static_cast<T>(w[i]);
        if (!(wi >= T(0))) return std::nullopt;  // negative or NaN: the debug check's case
        positive = positive || wi > T(0);
    }
    if (!positive) return std::nullopt;
    return detail::checked_alignment<T>(detail::data_of(targets), detail::data_of(sources), count,
                                        [w](std::size_t i) { return static_cast<T>(w[i]); });
}

/// align_vectors(targets, sources, weights) and scipy's sensitivity matrix: mean(weights) / zeta
/// (kappa I + B B^T) with B = sum weights[i] targets[i] sources[i]^T, kappa and zeta symmetric
/// functions of its singular values (see alignment_with_sensitivity). Multiplied by the harmonic
/// mean of the targets' error variances (weights inversely proportional to them), it is the
/// covariance of the rotation's error. Huge, infinite or NaN elements when unique is false; NaN
/// elements when a weight is infinite (scipy raises) or the containers differ in size
/// (QUAT_ASSERT).
template <class Targets, class Sources, class Weights,
          class T = detail::element_scalar_t<vec3, Targets>>
[[nodiscard]] constexpr alignment_with_sensitivity<T> align_vectors_with_sensitivity(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    QUAT_ASSERT(
        detail::same_size(targets, sources, weights),
        "quat::align_vectors_with_sensitivity: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    const detail::wahba_solution<T> solution =
        detail::same_size(targets, sources, weights)
            ? detail::solve_wahba<T>(detail::data_of(targets), detail::data_of(sources),
                                     detail::size_of(sources),
                                     [w](std::size_t i) { return static_cast<T>(w[i]); })
            : detail::nan_wahba<T>(false);
    QUAT_ASSERT(!solution.negative, "quat::align_vectors_with_sensitivity: a weight is negative");
    return {solution.result, detail::wahba_sensitivity(solution, detail::size_of(sources))};
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_FITTING_ALIGN_VECTORS_HPP_INCLUDED
