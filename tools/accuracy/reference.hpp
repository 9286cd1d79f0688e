// High-precision reference for the accuracy tool: every quantity the tool compares against is
// computed here, independently of quat, GLM and Eigen, in __float128 (libquadmath, 113-bit
// significand) when available, else long double (64-bit significand, still 11 bits beyond double).
#pragma once

#include <array>
#include <cmath>

#if defined(QUAT_ACCURACY_FLOAT128)
#include <quadmath.h>
#endif

namespace accuracy {

#if defined(QUAT_ACCURACY_FLOAT128)
__extension__ typedef __float128 real;
inline real r_sqrt(real x) { return sqrtq(x); }
inline real r_sin(real x) { return sinq(x); }
inline real r_cos(real x) { return cosq(x); }
inline real r_atan2(real y, real x) { return atan2q(y, x); }
inline real r_abs(real x) { return x < 0 ? -x : x; }
inline real r_fma(real a, real b, real c) { return fmaq(a, b, c); }
inline real r_pi() { return 4 * atanq(1); }
inline const char* reference_name() { return "__float128 (libquadmath)"; }
#else
using real = long double;
inline real r_sqrt(real x) { return std::sqrt(x); }
inline real r_sin(real x) { return std::sin(x); }
inline real r_cos(real x) { return std::cos(x); }
inline real r_atan2(real y, real x) { return std::atan2(y, x); }
inline real r_abs(real x) { return std::fabs(x); }
inline real r_fma(real a, real b, real c) { return std::fma(a, b, c); }
inline real r_pi() { return 3.141592653589793238462643383279502884L; }
inline const char* reference_name() { return "long double"; }
#endif

/// Plain containers the tool passes between libraries: scalar-first quaternion, 3-vector.
template <class T>
using q4 = std::array<T, 4>;
template <class T>
using v3 = std::array<T, 3>;

using hq = q4<real>;
using hv = v3<real>;

template <class T>
hq widen(const q4<T>& q) {
    return {real(q[0]), real(q[1]), real(q[2]), real(q[3])};
}
template <class T>
hv widen(const v3<T>& v) {
    return {real(v[0]), real(v[1]), real(v[2])};
}

inline hq mul(const hq& a, const hq& b) {
    return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}
inline hq conj(const hq& q) { return {q[0], -q[1], -q[2], -q[3]}; }
inline real norm(const hq& q) {
    return r_sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
}
inline real norm(const hv& v) { return r_sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
inline hq normalized(const hq& q) {
    const real n = norm(q);
    return {q[0] / n, q[1] / n, q[2] / n, q[3] / n};
}

/// Rotation angle in [0, pi] taking rotation a to rotation b (a, b need not be unit; sign-free).
inline real rotation_angle_between(const hq& a, const hq& b) {
    const hq d = mul(conj(normalized(a)), normalized(b));
    return 2 * r_atan2(r_sqrt(d[1] * d[1] + d[2] * d[2] + d[3] * d[3]), r_abs(d[0]));
}

/// Rotation by `angle` about coordinate axis `axis` (0 = x, 1 = y, 2 = z).
inline hq axis_rotation(int axis, real angle) {
    hq q{r_cos(angle / 2), 0, 0, 0};
    q[1 + axis] = r_sin(angle / 2);
    return q;
}

/// Euler angles to quaternion. intrinsic: q = q_i(a0) q_j(a1) q_k(a2); extrinsic: q_k(a2) q_j(a1)
/// q_i(a0).
inline hq euler_rotation(const std::array<int, 3>& axes, bool intrinsic, const hv& a) {
    const hq q0 = axis_rotation(axes[0], a[0]);
    const hq q1 = axis_rotation(axes[1], a[1]);
    const hq q2 = axis_rotation(axes[2], a[2]);
    return intrinsic ? mul(mul(q0, q1), q2) : mul(mul(q2, q1), q0);
}

/// Exponential map: rotation vector v (angle |v| about v/|v|) to unit quaternion.
inline hq exp_map(const hv& v) {
    const real angle = norm(v);
    if (angle == 0) return {1, 0, 0, 0};
    const real s = r_sin(angle / 2) / angle;
    return {r_cos(angle / 2), s * v[0], s * v[1], s * v[2]};
}

/// Logarithm map: unit quaternion (normalized here) to the rotation vector with angle in [0, pi].
inline hv log_map(const hq& q_in) {
    hq q = normalized(q_in);
    if (q[0] < 0) q = {-q[0], -q[1], -q[2], -q[3]};
    const real s = r_sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (s == 0) return {0, 0, 0};
    const real k = 2 * r_atan2(s, q[0]) / s;
    return {k * q[1], k * q[2], k * q[3]};
}

/// Slerp of the normalized a, b along the arc from a to b as given (no choice of sign); the angle
/// from atan2 of chord lengths.
inline hq slerp_along(const hq& a_in, const hq& b_in, real t) {
    const hq a = normalized(a_in), b = normalized(b_in);
    const hq d{a[0] - b[0], a[1] - b[1], a[2] - b[2], a[3] - b[3]};
    const hq s{a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]};
    const real theta = 2 * r_atan2(norm(d), norm(s));
    if (theta == 0) return a;
    const real ka = r_sin((1 - t) * theta) / r_sin(theta);
    const real kb = r_sin(t * theta) / r_sin(theta);
    return {ka * a[0] + kb * b[0], ka * a[1] + kb * b[1], ka * a[2] + kb * b[2],
            ka * a[3] + kb * b[3]};
}

/// Shortest-arc slerp of the normalized inputs.
inline hq slerp(const hq& a, const hq& b, real t) {
    const bool far = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0;
    return slerp_along(a, far ? hq{-b[0], -b[1], -b[2], -b[3]} : b, t);
}

}  // namespace accuracy
