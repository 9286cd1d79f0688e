// Slerp approximations without trigonometry, for when the exact slerp (paths/interpolation.hpp)
// costs too much: corrected_nlerp, nlerp with a polynomial correction of t (rotation angle within
// 5.9e-4 rad of slerp), and slerp_fast, polynomials in the cosine of half the angle (within 3.4e-8
// rad in double and 4e-7 rad in float). nlerp (paths/interpolation.hpp) is the cheap end of the
// family (0.14 rad). The bounds are asserted by tests/test_slerp_fast.cpp and measured on 10^6
// samples by `quat_accuracy --slerp-fast`; the times are the benchmarks
// slerp_fast/quat/<method>/<type>.
#ifndef QUAT_PATHS_SLERP_FAST_HPP_INCLUDED
#define QUAT_PATHS_SLERP_FAST_HPP_INCLUDED

#include <type_traits>

#include "../config.hpp"
#include "../detail/math.hpp"
#include "../quaternion.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// 1 when the sign bit of x is clear, -1 when it is set, without a branch for the built-in types: a
/// branch on the sign of a . b goes either way on random input and costs more than the polynomials.
template <class T>
[[nodiscard]] constexpr T sign_factor(T x) noexcept {
    if constexpr (std::is_same_v<T, float>) {
        return __builtin_copysignf(T(1), x);
    } else if constexpr (std::is_same_v<T, double>) {
        return __builtin_copysign(T(1), x);
    } else if constexpr (std::is_same_v<T, long double>) {
        return __builtin_copysignl(T(1), x);
    } else {
        return x < T(0) ? T(-1) : T(1);
    }
}

}  // namespace detail

/// nlerp from unit a (t = 0) to unit b (t = 1) along the shorter arc with t corrected so that the
/// speed is nearly constant: rotation angle within 5.9e-4 rad of slerp's, |result| = 1 to rounding,
/// exactly a at t = 0 and b or -b at t = 1 (the sign bit of dot(a, b) picks -b). Preconditions:
/// unit a and b (the length is divided out as if they were) and t in [0, 1] (beyond, the angle
/// error grows quickly).
template <class T>
[[nodiscard]] constexpr quaternion<T> corrected_nlerp(const quaternion<T>& a,
                                                      const quaternion<T>& b,
                                                      detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a) && detail::is_near_unit(b),
                "quat::corrected_nlerp: a or b is not a unit quaternion");
    // nlerp at tau is slerp at t when tau = 1/2 + tan((t - 1/2) theta) / (2 tan(theta / 2)), theta
    // the 4D angle between a and the nearer of b, -b. zeux (Arseny Kapoulkine), "Approximating
    // slerp" (2015), writes tau = t + t (t - 1/2) (t - 1) k: tau is 0 and 1 at the ends whatever k
    // is, and tau(1 - t) = 1 - tau(t). Here k is quadratic in d = |a . b| with coefficients linear
    // in w = t (1 - t) = 1/4 - (t - 1/2)^2, fitted by bench/fit_corrected_nlerp.py to the smallest
    // largest rotation-angle error (5.8e-4 rad; plain nlerp's is 0.14 rad). const, not constexpr: a
    // user scalar need not be a literal type.
    const T k00 = T(1.112132429948791), k01 = T(-1.0468288499833223);
    const T k10 = T(-1.741641016389086), k11 = T(2.5617072945285786);
    const T k20 = T(0.6675284572043932), k21 = T(-1.5895475706814315);
    const T d = dot(a, b);
    const T x = detail::abs(d);
    const T w = t - t * t;
    const T k = (k00 + k01 * w) + x * ((k10 + k11 * w) + x * (k20 + k21 * w));
    const T tau = t - (t - T(0.5)) * w * k;
    // |(1 - tau) a + tau b|^2 = 1 - 2 tau (1 - tau) (1 - x) for unit a and b: exactly 1 at tau = 0
    // and tau = 1, where the division then leaves the end point as it is. Four divisions, not one
    // reciprocal and four multiplications: the sum is ready when the square root is, and a
    // multiplication after the reciprocal lengthens the chain (Zen 5, g++ 12, a loop of independent
    // calls: 5.6 ns against 6.2 with the reciprocal folded into the weights, 5.8 with it applied
    // to the sum).
    const T squared_length = T(1) + (x * T(2) - T(2)) * (tau - tau * tau);
    return (a * (T(1) - tau) + b * (tau * detail::sign_factor(d))) / detail::sqrt(squared_length);
}

/// Slerp from unit a (t = 0) to unit b (t = 1) along the shorter arc, approximated without
/// trigonometry: rotation angle within 3.4e-8 rad of slerp's in double and 4e-7 rad in float (about
/// the exact slerp's own rounding), |result| = 1 within the same, exactly a at t = 0 and b or -b at
/// t = 1 (the sign bit of dot(a, b) picks -b). Preconditions: unit a and b and t in [0, 1];
/// outside, the angle and length errors grow quickly.
template <class T>
[[nodiscard]] constexpr quaternion<T> slerp_fast(const quaternion<T>& a, const quaternion<T>& b,
                                                 detail::type_identity_t<T> t) noexcept {
    QUAT_ASSERT(detail::is_near_unit(a) && detail::is_near_unit(b),
                "quat::slerp_fast: a or b is not a unit quaternion");
    // With psi half the 4D angle between a and the nearer of b, -b (psi <= pi/4), c = cos psi and
    // alpha = 2t - 1, slerp's weights are E - O for a and E + O for b, where E = cos(alpha psi) /
    // (2c) is even in alpha and O = sin(alpha psi) / (2 sin psi) odd, so one evaluation serves
    // both. As power series in y = c - 1 (from the Chebyshev equations that cos(alpha psi) and
    // sin(alpha psi) / sin psi satisfy as functions of c, as in Eberly 2011, "A fast and accurate
    // algorithm for computing SLERP", J. Graphics, GPU, and Game Tools 15(3)), with u = t - 1/2 and
    // w = t (1 - t): E = 1/2 - (w y / c) P(w, y), O = u - u w y R(w, y), P = 2 + (1 - 4w) y / 3 +
    // ..., R = 4/3 - (6 + 8w) y / 15 + ... Halving the angle keeps y in [cos(pi/4) - 1, 0], where
    // cubics in y suffice; w = 0 at both ends makes the weights exactly (1, 0) and (0, 1) there.
    // bench/fit_slerp_fast.py fits the coefficients to the smallest largest rotation-angle and
    // length errors (3.33e-8 both before rounding, within the 3.4e-8 rad that the tests assert; the
    // series themselves, cut after y^3, leave 1.4e-5 rad). const, not constexpr: a user scalar need
    // not be a literal type.
    const T p00 = T(2.0000036702103374);
    const T p10 = T(0.3335047863139534), p11 = T(-1.3337634041499677);
    const T p20 = T(-0.06481534760799428), p21 = T(0.1712160812299326),
            p22 = T(0.35801086529937354);
    const T p30 = T(0.025435000954561436), p31 = T(-0.05846757933736984),
            p32 = T(-0.16262932866110547);
    const T r00 = T(1.3332819707202537);
    const T r10 = T(-0.40120298637938917), r11 = T(-0.5342158551913353);
    const T r20 = T(0.14357184224791386), r21 = T(0.257330323741846), r22 = T(0.1300863069559305);
    const T r30 = T(-0.09100478817206194), r31 = T(-0.21791497866289397);
    const T d = dot(a, b);
    // The coefficients depend on t alone, so they are computed while the dot product and the
    // square root are still on their way.
    const T u = t - T(0.5);
    const T w = t - t * t;
    const T p1 = p10 + p11 * w, p2 = p20 + w * (p21 + w * p22), p3 = p30 + w * (p31 + w * p32);
    const T r1 = r10 + r11 * w, r2 = r20 + w * (r21 + w * r22), r3 = r30 + r31 * w;
    const T c = detail::sqrt(detail::abs(d) * T(0.5) + T(0.5));
    const T inverse_c = T(1) / c;
    const T y = c - T(1);
    const T y2 = y * y;
    const T even = T(0.5) - (w * y) * ((p00 + y * p1) + y2 * (p2 + y * p3)) * inverse_c;
    const T odd = u - (u * w * y) * ((r00 + y * r1) + y2 * (r2 + y * r3));
    return a * (even - odd) + b * ((even + odd) * detail::sign_factor(d));
}
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_PATHS_SLERP_FAST_HPP_INCLUDED
