// Rigid motions over many elements: moving many points by one dual quaternion or homogeneous
// matrix (array of structs and struct of arrays), and composing many dual quaternions. The loops
// (detail/transform_points.hpp, detail/chained_product.hpp), aliasing rules and instruction-set
// namespaces are those of batch/rotations.hpp.
#ifndef QUAT_BATCH_RIGID_MOTIONS_HPP_INCLUDED
#define QUAT_BATCH_RIGID_MOTIONS_HPP_INCLUDED

#include <cstddef>

#include "../config.hpp"
#include "../conversions.hpp"
#include "../detail/containers.hpp"
#include "../quaternion.hpp"
#include "../rigid/dual_quaternion.hpp"
#include "../rigid/homogeneous_matrix.hpp"
#include "../vec3.hpp"
#include "detail/chained_product.hpp"
#include "detail/overlap.hpp"
#include "detail/transform_points.hpp"
#include "soa.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"
namespace detail {

// The four chains of chained_product for dual quaternions, their running products stored
// component-major (component c of chain j at a[c][j]): each step is then the same arithmetic on
// four lanes, which compilers turn into vector instructions even at SSE2. Held as four dual
// quaternions (chain_values), the 32 running components overflow SSE2's 16 registers and the loop
// stays scalar: 2.4 times slower (measured by rigid_chain/quat/dual_quaternion/float/1024, g++ 12,
// x86-64).
template <class T>
struct dual_chain_components {
    static constexpr void run_products(const dual_quaternion<T>* f, std::size_t run,
                                       dual_quaternion<T> (&chain)[product_chains]) noexcept {
        constexpr std::size_t lanes = product_chains;
        T a[8][lanes] = {};  // real w, x, y, z, then dual w, x, y, z of each chain
        for (std::size_t j = 0; j < lanes; ++j) a[0][j] = T(1);
        for (std::size_t i = 0; i < run; ++i) {
            T b[8][lanes] = {};
            for (std::size_t j = 0; j < lanes; ++j) {
                const dual_quaternion<T>& factor = f[j * run + i];
                const T components[8] = {factor.real.w, factor.real.x, factor.real.y,
                                         factor.real.z, factor.dual.w, factor.dual.x,
                                         factor.dual.y, factor.dual.z};
                for (std::size_t c = 0; c < 8; ++c) b[c][j] = components[c];
            }
            for (std::size_t j = 0; j < lanes; ++j) {
                const quaternion<T> ar{a[0][j], a[1][j], a[2][j], a[3][j]};
                const quaternion<T> ad{a[4][j], a[5][j], a[6][j], a[7][j]};
                const quaternion<T> br{b[0][j], b[1][j], b[2][j], b[3][j]};
                const quaternion<T> bd{b[4][j], b[5][j], b[6][j], b[7][j]};
                const quaternion<T> real = ar * br, dual = ar * bd + ad * br;
                const T components[8] = {real.w, real.x, real.y, real.z,
                                         dual.w, dual.x, dual.y, dual.z};
                for (std::size_t c = 0; c < 8; ++c) a[c][j] = components[c];
            }
        }
        for (std::size_t j = 0; j < lanes; ++j)
            chain[j] = {{a[0][j], a[1][j], a[2][j], a[3][j]}, {a[4][j], a[5][j], a[6][j], a[7][j]}};
    }
};

}  // namespace detail

/// output[i] = R input[i] + t for i < count (array of structs), the rigid motion of the 4x4 matrix
/// m: 9 multiplications and 9 additions per point. output == input is allowed; other overlaps are
/// not. Precondition: last row (0, 0, 0, 1), not read.
template <class T>
void transform(const homogeneous_matrix<T>& m, const vec3<T>* input, vec3<T>* output,
               std::size_t count) noexcept {
    QUAT_ASSERT(
        detail::same_or_disjoint(input, count * sizeof(vec3<T>), output, count * sizeof(vec3<T>)),
        "quat::transform: output partially overlaps input");
    detail::transform_points<true>(rotation_block(m), translation_of(m), input, output, count);
}

/// output[i] = transform(dq, input[i]) for unit dq (array of structs): dq becomes a matrix and a
/// translation once. Aliasing as for the matrix overload.
template <class T>
void transform(const dual_quaternion<T>& dq, const vec3<T>* input, vec3<T>* output,
               std::size_t count) noexcept {
    transform(to_homogeneous(dq), input, output, count);
}

/// Struct-of-arrays form of the matrix overload: each output array may be its own input array or
/// not overlap any input. Precondition: output.count >= input.count.
template <class T>
void transform(const homogeneous_matrix<T>& m, soa_points<const detail::type_identity_t<T>> input,
               soa_points<T> output) noexcept {
    QUAT_ASSERT(output.count >= input.count, "quat::transform: output shorter than input");
    QUAT_ASSERT(detail::soa_same_or_disjoint({input.x, input.y, input.z}, output, input.count),
                "quat::transform: an output array partially overlaps an input array");
    detail::transform_points<true>(rotation_block(m), translation_of(m), input, output);
}

/// Struct-of-arrays form of the dual-quaternion overload; aliasing as for the matrix overload.
template <class T>
void transform(const dual_quaternion<T>& dq, soa_points<const detail::type_identity_t<T>> input,
               soa_points<T> output) noexcept {
    transform(to_homogeneous(dq), input, output);
}

/// Container form of the array-of-structs transform by unit dq: any contiguous input and output
/// of vec3<T>. Precondition: size(output) >= size(input) (QUAT_ASSERT); unchecked, the first
/// min(size(input), size(output)) points, never past either container.
template <class T, class Input, class Output,
          class = detail::if_arrays_of<vec3<T>, vec3<T>, Input, Output>>
void transform(const dual_quaternion<T>& dq, const Input& input, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(input),
                "quat::transform: output shorter than input");
    transform(dq, detail::data_of(input), detail::data_of(output),
              detail::common_size(input, output));
}
/// Container form of the array-of-structs transform by the 4x4 matrix m, with the precondition of
/// the one by dq.
template <class T, class Input, class Output,
          class = detail::if_arrays_of<vec3<T>, vec3<T>, Input, Output>>
void transform(const homogeneous_matrix<T>& m, const Input& input, Output&& output) noexcept {
    QUAT_ASSERT(detail::size_of(output) >= detail::size_of(input),
                "quat::transform: output shorter than input");
    transform(m, detail::data_of(input), detail::data_of(output),
              detail::common_size(input, output));
}

/// The product dq[0] dq[1] ... dq[count - 1] (dq[count - 1] applies first); identity when
/// count == 0. Four interleaved chains as in the quaternion compose: the same motion by
/// associativity, rounded differently.
template <class T>
[[nodiscard]] constexpr dual_quaternion<T> compose(const dual_quaternion<T>* dq,
                                                   std::size_t count) noexcept {
    return detail::chained_product<dual_quaternion<T>, detail::dual_chain_components<T>>(dq, count);
}

/// compose over any contiguous container or view of dual_quaternion<T>.
template <class Range, class T = detail::element_scalar_t<dual_quaternion, Range>>
[[nodiscard]] constexpr dual_quaternion<T> compose(const Range& factors) noexcept {
    return compose(detail::data_of(factors), detail::size_of(factors));
}

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_BATCH_RIGID_MOTIONS_HPP_INCLUDED
