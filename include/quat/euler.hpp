// Euler angles: the 12 axis sequences, intrinsic or extrinsic, and conversions to and from them.
#ifndef QUAT_EULER_HPP_INCLUDED
#define QUAT_EULER_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <utility>

#include "axis_angle.hpp"
#include "config.hpp"
#include "conversions.hpp"
#include "detail/math.hpp"
#include "quaternion.hpp"
#include "rotation_matrix.hpp"

namespace quat {

/// Axis sequences: six Tait–Bryan (three different axes) and six proper Euler (first == third).
enum class sequence { xyz, xzy, yxz, yzx, zxy, zyx, xyx, xzx, yxy, yzy, zxz, zyz };

/// intrinsic: R = R_S0(a0) R_S1(a1) R_S2(a2), turns about the moving (body) axes in the order S0,
/// S1, S2. extrinsic: R = R_S2(a2) R_S1(a1) R_S0(a0), turns about the fixed axes in the order S0,
/// S1, S2.
enum class frame { intrinsic, extrinsic };

/// Three angles in radians for the axis sequence S in frame F. The default, euler<T>{yaw, pitch,
/// roll}, is the thesis's R = Rz(yaw) Ry(pitch) Rx(roll). Conventions are part of the type, so
/// angles of one convention never silently pass for another.
template <class T, sequence S = sequence::zyx, frame F = frame::intrinsic>
struct euler {
    /// The angles in radians, in the order of the sequence's letters.
    /// @{
    T angles[3];
    /// @}

    static constexpr ::quat::sequence axis_sequence = S;  ///< for generic code
    static constexpr ::quat::frame rotation_frame = F;    ///< for generic code

    /// Angles left uninitialized, as in a plain struct; euler<T, S, F>{} is all zero.
    euler() = default;
    /// The angles a0, a1, a2 in radians, in the order of the sequence's letters.
    [[gnu::always_inline]] constexpr euler(T a0, T a1, T a2) noexcept : angles{a0, a1, a2} {}
    /// The angles from an array: euler<T>{{a0, a1, a2}}.
    [[gnu::always_inline]] constexpr euler(const T (&values)[3]) noexcept
        : angles{values[0], values[1], values[2]} {}
    /// Conversion from another precision, same convention: euler<double>{ef}. Conventions never
    /// convert into each other implicitly or explicitly; use to_euler<S, F>(e) for that.
    template <class U>
    [[gnu::always_inline]] constexpr explicit euler(const euler<U, S, F>& e) noexcept
        : angles{static_cast<T>(e.angles[0]), static_cast<T>(e.angles[1]),
                 static_cast<T>(e.angles[2])} {}

    /// Angle i in {0, 1, 2}, in the order of the sequence's letters.
    [[nodiscard]] [[gnu::always_inline]] constexpr T& operator[](std::size_t i) noexcept {
        QUAT_ASSERT(i < 3, "Euler angle index out of range");
        return angles[i];
    }
    /// Angle i in {0, 1, 2}, read-only.
    [[nodiscard]] [[gnu::always_inline]] constexpr const T& operator[](
        std::size_t i) const noexcept {
        QUAT_ASSERT(i < 3, "Euler angle index out of range");
        return angles[i];
    }
};

#include "detail/isa_namespace.inc"
/// Angle I of e, for structured bindings: auto [a0, a1, a2] = e;
template <std::size_t I, class T, sequence S, frame F>
[[nodiscard]] constexpr T& get(euler<T, S, F>& e) noexcept {
    static_assert(I < 3, "an euler has three angles");
    return e.angles[I];
}
/// Angle I of e, read-only.
template <std::size_t I, class T, sequence S, frame F>
[[nodiscard]] constexpr const T& get(const euler<T, S, F>& e) noexcept {
    static_assert(I < 3, "an euler has three angles");
    return e.angles[I];
}
/// Angle I of an rvalue e.
template <std::size_t I, class T, sequence S, frame F>
[[nodiscard]] constexpr T&& get(euler<T, S, F>&& e) noexcept {
    static_assert(I < 3, "an euler has three angles");
    return static_cast<T&&>(e.angles[I]);
}
}  // inline namespace isa_...

/// Result of extract_euler: the angles, and whether the rotation is at gimbal lock, where only the
/// sum or difference of the first and third angles is determined and the third angle is set to 0.
template <class T, sequence S, frame F>
struct euler_extraction {
    euler<T, S, F> angles;  ///< The angles, e[2] == 0 at gimbal lock.
    bool gimbal_lock;       ///< True when the middle angle is at its singular value.
};

#include "detail/isa_namespace.inc"  // NOLINT(readability-duplicate-include): opened again
namespace detail {

struct axis_triple {
    int first, second, third;  // 0 = x, 1 = y, 2 = z
};

[[nodiscard]] constexpr axis_triple axes_of(sequence s) noexcept {
    constexpr axis_triple table[] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0},
                                     {2, 0, 1}, {2, 1, 0}, {0, 1, 0}, {0, 2, 0},
                                     {1, 0, 1}, {1, 2, 1}, {2, 0, 2}, {2, 1, 2}};
    return table[static_cast<int>(s)];
}

// The order in which the three elementary rotations are multiplied, left to right:
// intrinsic R_S0 R_S1 R_S2 as written, extrinsic reversed.
template <sequence S, frame F>
[[nodiscard]] constexpr axis_triple product_order() noexcept {
    constexpr axis_triple a = axes_of(S);
    if constexpr (F == frame::intrinsic) return a;
    else return {a.third, a.second, a.first};
}

}  // namespace detail

/// Unit quaternion of the Euler angles e (the product of three axis rotations, in closed form).
template <class T, sequence S, frame F>
[[nodiscard]] constexpr quaternion<T> to_quaternion(const euler<T, S, F>& e) noexcept {
    constexpr detail::axis_triple order = detail::product_order<S, F>();
    const T first = F == frame::intrinsic ? e[0] : e[2], middle = e[1],
            last = F == frame::intrinsic ? e[2] : e[0];
    const T h0 = first * T(0.5), h1 = middle * T(0.5), h2 = last * T(0.5);  // half angles, exact
    const T c0 = detail::cos(h0), s0 = detail::sin(h0);
    const T c1 = detail::cos(h1), s1 = detail::sin(h1);
    const T c2 = detail::cos(h2), s2 = detail::sin(h2);
    // q_a(first) q_b(middle): (c0 c1, s0 c1 e_a + c0 s1 e_b + s0 s1 e_a x e_b), e_a x e_b =
    // ±e_rest.
    const int a = order.first, b = order.second, rest = 3 - a - b;
    const T parity = (b - a + 3) % 3 == 1 ? T(1) : T(-1);
    T v[3]{};
    v[a] = s0 * c1;
    v[b] = c0 * s1;
    v[rest] = parity * s0 * s1;
    const T w = c0 * c1;
    // (w, v) q_m(last) = (w c2 - s2 v_m, w s2 e_m + c2 v + s2 v x e_m); (v x e_m) = (0, v_m+2,
    // -v_m+1) in the cyclic coordinates starting at m.
    const int m = order.third, m1 = (m + 1) % 3, m2 = (m + 2) % 3;
    T r[3]{};
    r[m] = w * s2 + c2 * v[m];
    r[m1] = c2 * v[m1] + s2 * v[m2];
    r[m2] = c2 * v[m2] - s2 * v[m1];
    return {w * c2 - s2 * v[m], r[0], r[1], r[2]};
}

/// Rotation matrix of the Euler angles e, multiplied out as sparse products of axis rotations.
template <class T, sequence S, frame F>
[[nodiscard]] constexpr rotation_matrix<T> to_matrix(const euler<T, S, F>& e) noexcept {
    constexpr detail::axis_triple order = detail::product_order<S, F>();
    const T angle[3] = {F == frame::intrinsic ? e[0] : e[2], e[1],
                        F == frame::intrinsic ? e[2] : e[0]};
    const int axis[3] = {order.first, order.second, order.third};
    // Start from R_first itself (no arithmetic), then R <- R R_m(t) for the other two: column m
    // stays, columns m+1 and m+2 turn by t within their plane.
    rotation_matrix<T> r = rotation_matrix<T>::identity();
    {
        const int m1 = (axis[0] + 1) % 3, m2 = (axis[0] + 2) % 3;
        const T c = detail::cos(angle[0]), s = detail::sin(angle[0]);
        r(m1, m1) = c;
        r(m2, m1) = s;
        r(m1, m2) = -s;
        r(m2, m2) = c;
    }
    for (int n = 1; n < 3; ++n) {
        const int m1 = (axis[n] + 1) % 3, m2 = (axis[n] + 2) % 3;
        const T c = detail::cos(angle[n]), s = detail::sin(angle[n]);
        for (int i = 0; i < 3; ++i) {
            const T p = r(i, m1), q = r(i, m2);
            r(i, m1) = c * p + s * q;
            r(i, m2) = c * q - s * p;
        }
    }
    return r;
}

/// Euler angles of the unit quaternion q in the convention S, F, with the flag for gimbal lock.
/// Method of Bernardes & Viollet (PLoS ONE 17(11), 2022): one atan2-based formula for all twelve
/// sequences. First and third angles in [-pi, pi]; middle in [-pi/2, pi/2] (Tait–Bryan) or [0, pi]
/// (proper). At gimbal lock (middle angle within about 2 epsilon of its limit, where q no longer
/// determines the split) the third angle e[2] is 0. Any non-zero scale of q gives the same angles.
template <sequence S, frame F = frame::intrinsic, class T>
[[nodiscard]] constexpr euler_extraction<T, S, F> extract_euler(const quaternion<T>& q) noexcept {
    // Solve the intrinsic product order i, j, k: R = R_i(alpha) R_j(beta) R_k(gamma). For the
    // extrinsic frame that order is the sequence reversed and the angles come out reversed.
    constexpr detail::axis_triple order = detail::product_order<S, F>();
    const int i = order.first, j = order.second, k = 3 - i - j;
    const bool proper = order.first == order.third;
    const T parity = (j - i + 3) % 3 == 1 ? T(1) : T(-1);
    // Angles need no particular scale, but the products below must not overflow or underflow.
    const T size = squared_norm(q), epsilon = detail::epsilon<T>();
    const quaternion<T> p = size > epsilon && size < T(1) / epsilon ? q : normalize(q);
    const T v[3] = {p.x, p.y, p.z};
    // Proper i-j-i: (w, v_i, v_j, parity v_k) = (cos(b/2) cos(s), cos(b/2) sin(s), sin(b/2) cos(d),
    // sin(b/2) sin(d)), s = (alpha + gamma)/2, d = (alpha - gamma)/2. Tait–Bryan i-j-k reduces to
    // it by q R_j(pi/2), which turns gamma about e_k into -parity gamma about e_i, beta into beta +
    // pi/2.
    const T a = proper ? p.w : p.w - v[j];
    const T b = proper ? v[i] : v[i] - parity * v[k];
    const T c = proper ? v[j] : v[j] + p.w;
    const T d = proper ? parity * v[k] : parity * v[k] + v[i];
    const T cos_part = detail::sqrt(a * a + b * b), sin_part = detail::sqrt(c * c + d * d);
    T beta = T(2) * detail::atan2(sin_part, cos_part);
    // alpha = s + d and gamma = s - d, each from one atan2 of a complex product, (a + ib)(c ± id),
    // which is more accurate than adding two angles and lands in [-pi, pi] without wrapping.
    T alpha{}, gamma{};
    const bool at_zero = sin_part <= epsilon * cos_part, at_pi = cos_part <= epsilon * sin_part;
    // At a lock only alpha + gamma (at zero) or alpha - gamma (at pi) is known: the angle that
    // ends up in e[2] is set to 0 (gamma for intrinsic, alpha for extrinsic, which is reversed).
    const bool zero_gamma = F == frame::intrinsic;
    if (at_zero) {
        const T sum = detail::atan2(T(2) * a * b, a * a - b * b);  // angle of (a + ib)^2
        alpha = zero_gamma ? sum : T(0);
        gamma = zero_gamma ? T(0) : sum;
    } else if (at_pi) {
        const T difference = detail::atan2(T(2) * c * d, c * c - d * d);  // angle of (c + id)^2
        alpha = zero_gamma ? difference : T(0);
        gamma = zero_gamma ? T(0) : -difference;
    } else {
        alpha = detail::atan2(a * d + b * c, a * c - b * d);
        gamma = detail::atan2(b * c - a * d, a * c + b * d);
    }
    if (!proper) {
        beta -= detail::pi<T>() / T(2);
        gamma = -parity * gamma;
    }
    euler<T, S, F> angles{};
    angles[0] = F == frame::intrinsic ? alpha : gamma;
    angles[1] = beta;
    angles[2] = F == frame::intrinsic ? gamma : alpha;
    return {angles, at_zero || at_pi};
}

/// Euler angles of the unit quaternion q in the convention S, F (see extract_euler for ranges and
/// gimbal lock).
template <sequence S, frame F = frame::intrinsic, class T>
[[nodiscard]] constexpr euler<T, S, F> to_euler(const quaternion<T>& q) noexcept {
    return extract_euler<S, F>(q).angles;
}

/// Euler angles of the rotation matrix m (through its quaternion; see extract_euler).
template <sequence S, frame F = frame::intrinsic, class T>
[[nodiscard]] constexpr euler<T, S, F> to_euler(const rotation_matrix<T>& m) noexcept {
    return to_euler<S, F>(to_quaternion(m));
}

/// Euler angles of an axis-angle rotation (unit axis).
template <sequence S, frame F = frame::intrinsic, class T>
[[nodiscard]] constexpr euler<T, S, F> to_euler(const axis_angle<T>& rotation) noexcept {
    return to_euler<S, F>(to_quaternion(rotation));
}

/// The same rotation's angles in another convention.
template <sequence S, frame F = frame::intrinsic, class T, sequence S0, frame F0>
[[nodiscard]] constexpr euler<T, S, F> to_euler(const euler<T, S0, F0>& e) noexcept {
    return to_euler<S, F>(to_quaternion(e));
}

/// Axis and angle in [0, pi] of the Euler angles e.
template <class T, sequence S, frame F>
[[nodiscard]] constexpr axis_angle<T> to_axis_angle(const euler<T, S, F>& e) noexcept {
    return to_axis_angle(to_quaternion(e));
}
}  // inline namespace isa_...

}  // namespace quat

namespace std {

/// An euler is a tuple of three angles for structured bindings.
template <class T, ::quat::sequence S, ::quat::frame F>
struct tuple_size<::quat::euler<T, S, F>> : integral_constant<size_t, 3> {};
/// Each angle has the type T.
template <size_t I, class T, ::quat::sequence S, ::quat::frame F>
struct tuple_element<I, ::quat::euler<T, S, F>> {
    using type = T;  ///< the angle type
};

}  // namespace std

#endif  // QUAT_EULER_HPP_INCLUDED
