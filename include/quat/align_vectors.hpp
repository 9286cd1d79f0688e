// Wahba's problem: the rotation that best aligns one set of vectors with another, as scipy's
// Rotation.align_vectors finds it, with the residual and scipy's sensitivity matrix.
#ifndef QUAT_ALIGN_VECTORS_HPP_INCLUDED
#define QUAT_ALIGN_VECTORS_HPP_INCLUDED

#include <cstddef>
#include <limits>
#include <utility>

#include "align.hpp"
#include "config.hpp"
#include "conversions.hpp"
#include "detail/containers.hpp"
#include "detail/math.hpp"
#include "detail/symmetric_eigen.hpp"
#include "nearest_rotation.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"
#include "vec3.hpp"

namespace quat {

/// The rotation that best aligns two sets of vectors, and how well it does (align_vectors).
template <class T>
struct alignment {
    /// Unit quaternion, w >= 0, of the rotation R minimizing sum w_i |targets_i - R sources_i|^2.
    quaternion<T> rotation;
    /// sqrt(sum w_i |targets_i - R sources_i|^2), summed from the residuals.
    T rssd;
    /// False when other rotations fit as well: one pair, collinear vectors, and a few symmetric sets.
    bool unique;
};

/// An alignment and scipy's sensitivity matrix (align_vectors_with_sensitivity).
template <class T>
struct alignment_with_sensitivity {
    quaternion<T> rotation;  ///< As alignment::rotation.
    T rssd;                  ///< As alignment::rssd.
    bool unique;             ///< As alignment::unique.
    /// Symmetric 3x3 matrix, read as sensitivity(row, col), proportional to the covariance of the
    /// rotation's error as a small rotation vector in the targets' frame: scipy's (1.10) matrix
    /// for return_sensitivity=True. Not a rotation: rotation_matrix only stores it.
    rotation_matrix<T> sensitivity;
};

namespace detail {

// The T of a container of vec3<T>: declared only, for the type of its data.
template <class T>
T vec3_scalar(const vec3<T>*) noexcept;
template <class Vectors>
using vec3_scalar_t =
    decltype(detail::vec3_scalar(detail::data_of(std::declval<const Vectors&>())));

template <class T>
struct wahba_solution {
    alignment<T> result;
    rotation_matrix<T> profile;  // Davenport's attitude profile matrix B = sum w_i t_i s_i^T
    T total_weight;
};

// sum w_i t_i . (R s_i) = trace(R^T B), so R is the rotation nearest to B: the eigenvector of the
// largest eigenvalue of Horn's (Davenport's) K of B (Davenport's q-method; Markley & Crassidis,
// Fundamentals of Spacecraft Attitude Determination and Control, 2014, ch. 5). K's eigenvalues are
// s0 + s1 + s2 and s0 - s1 - s2, ... for B's singular values s0 >= s1 >= |s2| (s2 < 0 when
// det B < 0), relative to max |B(i, j)|: the optimum is unique when the gap 2 (s1 + s2) exceeds
// sqrt(epsilon) of that.
template <class T, class Weight>
[[nodiscard]] constexpr wahba_solution<T> solve_wahba(const vec3<T>* targets,
                                                      const vec3<T>* sources, std::size_t count,
                                                      Weight weight) noexcept {
    // Summed in blocks of summation_block pairs, each block from zero: rounding errors then grow
    // with the block length plus the number of blocks, not with the count. For 1e6 noisy pairs in
    // float the plain running sums put the rotation 114 eps from its long double value; blocked,
    // 2.7 eps (double: 16.6 and 2.5 eps).
    T b[3][3] = {}, total = T(0), lowest = T(0);
    for (std::size_t start = 0; start < count; start += summation_block) {
        const std::size_t end = count - start < summation_block ? count : start + summation_block;
        T block[3][3] = {};
        for (std::size_t i = start; i < end; ++i) {
            const T w = weight(i);
            const vec3<T> t = targets[i] * w, s = sources[i];
            block[0][0] += t.x * s.x;
            block[0][1] += t.x * s.y;
            block[0][2] += t.x * s.z;
            block[1][0] += t.y * s.x;
            block[1][1] += t.y * s.y;
            block[1][2] += t.y * s.z;
            block[2][0] += t.z * s.x;
            block[2][1] += t.z * s.y;
            block[2][2] += t.z * s.z;
            total += w;
            lowest = w < lowest ? w : lowest;
        }
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) b[r][c] += block[r][c];
    }
    QUAT_ASSERT(!(lowest < T(0)), "quat::align_vectors: a weight is negative");
    const rotation_matrix<T> profile{b};
    const symmetric_eigen4<T> eigen = detail::horn_eigen(profile);
    const T tie = detail::sqrt(std::numeric_limits<T>::epsilon());
    const bool unique = eigen.values[0] - eigen.values[1] > tie;  // false for NaN
    quaternion<T> q = eigen.vectors[0];
    if (!unique && count == 1 && eigen.values[0] > T(0)) {
        q = rotation_between(sources[0], targets[0]);
    } else {
        if (!unique && detail::is_finite(eigen.values[0])) {
            // The optimal rotations span the eigenvectors tied with the largest; of those, the one
            // nearest the identity (the projection of 1 onto the span), which for collinear pairs
            // is the shortest arc, as for one pair, and for B = 0 (no data) the identity. When
            // every optimal rotation is a half turn, the projection is 0 and any of them will do.
            quaternion<T> nearest{T(0), T(0), T(0), T(0)};
            for (int n = 0; n < 4; ++n)
                if (eigen.values[0] - eigen.values[n] <= tie)
                    nearest += eigen.vectors[n] * eigen.vectors[n].w;
            if (squared_norm(nearest) > T(0)) q = nearest;
        }
        q = normalize(q.w < T(0) ? -q : q);
    }
    // The residuals themselves: sum w (|t|^2 + |s|^2) - 2 trace(R^T B), scipy's formula, cancels
    // down to about sqrt(epsilon) times the vectors' length when they fit exactly.
    const rotation_matrix<T> r = to_matrix(q);
    T squares = T(0);
    for (std::size_t start = 0; start < count; start += summation_block) {
        const std::size_t end = count - start < summation_block ? count : start + summation_block;
        T block = T(0);
        for (std::size_t i = start; i < end; ++i)
            block += weight(i) * squared_norm(targets[i] - rotate(r, sources[i]));
        squares += block;
    }
    return {{q, detail::sqrt(squares), unique}, profile, total};
}

// scipy's sensitivity mean(w) / zeta (kappa I + B B^T), kappa = s0 s1 + s1 s2 + s2 s0 and
// zeta = (s0 + s1) (s1 + s2) (s2 + s0) for B's singular values signed as above, here without an
// SVD: with lambda = s0 + s1 + s2 = trace(R^T B), kappa = (lambda^2 - |B|_F^2) / 2 and
// zeta = lambda kappa - det B (Markley, "Attitude determination using vector observations: a fast
// optimal matrix algorithm", J. Astronaut. Sci. 41(2), 1993). B is scaled to a largest element of 1
// first, and the scale put back at the end (sensitivity scales as 1 / |B|).
template <class T>
[[nodiscard]] constexpr rotation_matrix<T> wahba_sensitivity(const wahba_solution<T>& solution,
                                                             std::size_t count) noexcept {
    T scale = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scale = detail::max(scale, detail::abs(solution.profile(i, j)));
    if (!(scale > T(0))) scale = T(1);
    rotation_matrix<T> b{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) b(i, j) = solution.profile(i, j) / scale;
    const rotation_matrix<T> r = to_matrix(solution.result.rotation);
    T lambda = T(0), frobenius = T(0);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            lambda += r(i, j) * b(i, j);
            frobenius += b(i, j) * b(i, j);
        }
    const T kappa = (lambda * lambda - frobenius) / T(2);
    const T zeta = lambda * kappa - determinant(b);
    const T factor =
        solution.total_weight / static_cast<T>(static_cast<double>(count)) / (scale * zeta);
    rotation_matrix<T> sensitivity{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            sensitivity(i, j) = factor * ((i == j ? kappa : T(0)) + dot(row(b, i), row(b, j)));
    return sensitivity;
}

}  // namespace detail

/// The rotation R minimizing sum |targets[i] - R sources[i]|^2 (Wahba's problem), the one scipy's
/// Rotation.align_vectors(a=targets, b=sources) returns: always a proper rotation, never a
/// reflection. targets and sources are equally long (QUAT_ASSERT) containers of vec3<T> with data()
/// and size(), or C arrays; the vectors need not be unit, and longer ones count more, as in scipy.
/// When the optimum is not unique (unique = false: the top two eigenvalues of Davenport's K,
/// relative to max |B(i, j)| for B = sum targets[i] sources[i]^T, within sqrt(epsilon)), the
/// optimal rotation nearest the identity: rotation_between(sources[0], targets[0]) for one pair,
/// the identity for no pairs (rssd 0). A NaN or infinite component gives a NaN rotation and rssd,
/// unique = false.
template <class Targets, class Sources, class T = detail::vec3_scalar_t<Targets>>
[[nodiscard]] constexpr alignment<T> align_vectors(const Targets& targets,
                                                   const Sources& sources) noexcept {
    QUAT_ASSERT(detail::size_of(targets) == detail::size_of(sources),
                "quat::align_vectors: targets and sources differ in size");
    return detail::solve_wahba<T>(detail::data_of(targets), detail::data_of(sources),
                                  detail::size_of(sources), [](std::size_t) { return T(1); })
        .result;
}

/// align_vectors with weights (a container of scalars convertible to T, as long as the vectors):
/// R minimizes sum weights[i] |targets[i] - R sources[i]|^2, and rssd is weighted alike. A zero
/// weight drops its pair. Precondition: weights >= 0 (QUAT_ASSERT; unchecked, a negative weight
/// counts against its pair, and rssd may be NaN); a NaN or infinite weight gives a NaN result.
template <class Targets, class Sources, class Weights, class T = detail::vec3_scalar_t<Targets>>
[[nodiscard]] constexpr alignment<T> align_vectors(const Targets& targets, const Sources& sources,
                                                   const Weights& weights) noexcept {
    QUAT_ASSERT(detail::size_of(targets) == detail::size_of(sources) &&
                    detail::size_of(weights) == detail::size_of(sources),
                "quat::align_vectors: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    return detail::solve_wahba<T>(detail::data_of(targets), detail::data_of(sources),
                                  detail::size_of(sources),
                                  [w](std::size_t i) { return static_cast<T>(w[i]); })
        .result;
}

/// align_vectors(targets, sources, weights) and scipy's sensitivity matrix: mean(weights) / zeta
/// (kappa I + B B^T) with B = sum weights[i] targets[i] sources[i]^T, kappa and zeta symmetric
/// functions of its singular values (see alignment_with_sensitivity). Multiplied by the harmonic
/// mean of the targets' error variances (weights inversely proportional to them), it is the
/// covariance of the rotation's error. Huge, infinite or NaN elements when unique is false.
template <class Targets, class Sources, class Weights, class T = detail::vec3_scalar_t<Targets>>
[[nodiscard]] constexpr alignment_with_sensitivity<T> align_vectors_with_sensitivity(
    const Targets& targets, const Sources& sources, const Weights& weights) noexcept {
    QUAT_ASSERT(
        detail::size_of(targets) == detail::size_of(sources) &&
            detail::size_of(weights) == detail::size_of(sources),
        "quat::align_vectors_with_sensitivity: targets, sources and weights differ in size");
    const auto* w = detail::data_of(weights);
    const detail::wahba_solution<T> solution = detail::solve_wahba<T>(
        detail::data_of(targets), detail::data_of(sources), detail::size_of(sources),
        [w](std::size_t i) { return static_cast<T>(w[i]); });
    return {solution.result.rotation, solution.result.rssd, solution.result.unique,
            detail::wahba_sensitivity(solution, detail::size_of(sources))};
}

}  // namespace quat

#endif  // QUAT_ALIGN_VECTORS_HPP_INCLUDED
