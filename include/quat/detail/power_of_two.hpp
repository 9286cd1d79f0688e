// Exact scaling by powers of two, which moves a vector's length into the range where products
// of lengths neither overflow nor underflow without changing its direction, and the compensated
// cross product the near-parallel cases need.
#ifndef QUAT_DETAIL_POWER_OF_TWO_HPP_INCLUDED
#define QUAT_DETAIL_POWER_OF_TWO_HPP_INCLUDED

#include <limits>
#include <type_traits>

#include "math.hpp"

namespace quat {

#include "isa_namespace.inc"
namespace detail {

/// 2^e for a small |e|, exactly, in a constant expression.
template <class T>
[[nodiscard]] constexpr T power_of_two(int e) noexcept {
    T result(1);
    for (; e > 0; --e) result = result * T(2);
    for (; e < 0; ++e) result = result * T(0.5);
    return result;
}

/// True when |v|^2 lies where the products of align.hpp (up to |a|^2 |b|^2 and its rounding
/// errors) neither overflow nor underflow: within 2^(+-max_exponent/4), so in double lengths from
/// 3e-39 to 3e38 and in float from 1.5e-5 to 65536. A user scalar is trusted with any length.
template <class T>
[[nodiscard]] constexpr bool in_product_range(T squared_length) noexcept {
    if constexpr (std::is_floating_point_v<T>) {
        constexpr T high = power_of_two<T>(std::numeric_limits<T>::max_exponent / 4);
        return squared_length >= T(1) / high && squared_length <= high;
    } else {
        return true;
    }
}

/// The power of two p with x / p in [1, 2), for a finite x > 0: dividing by it is exact (bar what
/// underflows beside x), and it exists for every such x, subnormal ones included.
template <class T>
[[nodiscard]] constexpr T binade_of(T x) noexcept {
    T p(1);
    // Steps of 2^32, 2^8 and 2: at most a few dozen exact products even for subnormal x. p is
    // divided only while it stays above x, so it never underflows. An array, not a braced list:
    // std::initializer_list's members are not keyed by instruction set.
    constexpr int exponents[] = {32, 8, 1};
    for (const int e : exponents) {
        const T step = power_of_two<T>(e);
        while (x / p >= step) p = p * step;
        while (x / p < T(1) / step) p = p / step;
    }
    return x / p < T(1) ? p / T(2) : p;  // x / p was in [1/2, 2)
}

/// binade_of(x) for x > 0, and 1 for x = 0: the power of two that scales a size of 0 or more into
/// [1, 2) (or leaves 0 alone).
template <class T>
[[nodiscard]] constexpr T binade_or_one(T x) noexcept {
    return x > T(0) ? binade_of(x) : T(1);
}

/// v divided by the power of two that brings its largest |component| into [1, 2): the same
/// direction exactly, whatever v's length. Precondition: has_direction(v).
/// Written for any vector with x, y and z (vec3 and autodiff vectors alike), so that this
/// foundation header knows no type of quat's.
template <class Vector>
[[nodiscard]] constexpr Vector scaled_by_power_of_two(const Vector& v) noexcept {
    return v / binade_of(max(max(abs(v.x), abs(v.y)), abs(v.z)));
}

/// a x b with each component from difference_of_products: relative error at most 2 units of
/// roundoff per component, also where a and b are nearly parallel or opposite and the naive
/// cross product keeps only rounding noise.
template <class Vector>
[[nodiscard]] constexpr Vector accurate_cross(const Vector& a, const Vector& b) noexcept {
    return {difference_of_products(a.y, b.z, a.z, b.y), difference_of_products(a.z, b.x, a.x, b.z),
            difference_of_products(a.x, b.y, a.y, b.x)};
}

}  // namespace detail
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_DETAIL_POWER_OF_TWO_HPP_INCLUDED
