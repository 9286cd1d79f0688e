// The solve behind se3_keyframe_path: each segment's cubic in se(3), C2 across the keyframes.
//
// On segment j, X(t) = X_j exp(xi(u)), u = (t - t_j) / h_j, with xi = (rho, omega) a cubic twist,
// xi(0) = 0 and xi(1) = log(X_j^-1 X_(j+1)) = (L_rho, L_omega). Locally the motion is the rotation
// exp(omega) and the position p = Jl(omega) rho (in X_j's frame). Its rotation part is
// rotation_spline's segment exactly (the same cubic in the rotation vector, the same end
// conditions), and the angular motion does not depend on rho, so the orientation is the rotation
// spline's and only the translation is solved here. The unknowns are the body-frame linear
// velocities v_k = R^T dp/dt at the keyframes; given the rotation they enter the positions
// linearly, so continuity of the acceleration is a linear, block-tridiagonal system.
//
// With e_j = d rho / dt at the end of segment j, v_(k+1) = R^T (Jl e_j + (Jl)' L_rho) gives
// e_j = M_j v_(j+1) + f_j, M_j = Jr(L_omega)^-1 (as Jl^-1 R = Jr^-1), f_j = -Jl^-1 (Jl)' L_rho.
// The acceleration R^T d2p/dt2 at the end of segment k - 1 (R^T (Jl rho'' + 2 (Jl)' rho' +
// (Jl)'' rho), with rho'' of the Hermite cubic) equals the one at the start of segment k
// (rho''(0) + omega_k x v_k, as Jl = I + [omega]x / 2 + ... there) when, p = k - 1, s = k,
//     (2 / h_p) Jr_p v_(k-1) + ((4 / h_p + 4 / h_s) I + 2 R_p^T (Jl_p)' M_p - [omega_k]x) v_k
//         + (2 / h_s) M_s v_(k+1)
//     = 6 Jr_p L_rho,p / h_p^2 - (4 / h_p) Jr_p f_p - 2 R_p^T (Jl_p)' f_p - R_p^T (Jl_p)'' L_rho,p
//         + 6 L_rho,s / h_s^2 - 2 f_s / h_s,
// where Jr_p, R_p, (Jl_p)' and (Jl_p)'' are taken at the end of segment p. Without rotation it is
// the clamped cubic spline's system, component by component. The end velocities are those of the
// end segments' screws, L_rho / h, as rotation_spline's are its end slerps'.
#ifndef QUAT_TRAJECTORY_DETAIL_SE3_CUBICS_HPP_INCLUDED
#define QUAT_TRAJECTORY_DETAIL_SE3_CUBICS_HPP_INCLUDED

#include <cstddef>
#include <type_traits>
#include <vector>

#include "../../conversions.hpp"
#include "../../detail/math.hpp"
#include "../../detail/relative_rotation.hpp"
#include "../../lie/detail/rotation_vector_jacobian.hpp"
#include "../../matrix.hpp"
#include "../../paths/detail/block_tridiagonal.hpp"
#include "../../paths/rotation_spline.hpp"
#include "../../quaternion.hpp"
#include "../../vec3.hpp"
#include "hermite_cubic.hpp"
#include "left_jacobian_rates.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// One segment of an se3_keyframe_path: the twist's rotation vector and linear part.
template <class T>
struct se3_cubic {
    hermite_cubic<T> angular, linear;
};

/// The segments' twist cubics through the keyframes (count >= 2, normalized rotations), the
/// angular velocities at the keyframes read from `orientation`, the rotation spline through the
/// same keyframes. Solved in double for float, in the unit of time the rotation spline uses (the
/// geometric mean of the shortest and longest durations).
template <class T>
void se3_cubics(const std::vector<T>& times, const std::vector<quaternion<T>>& rotations,
                const std::vector<vec3<T>>& positions, const rotation_spline<T>& orientation,
                std::vector<se3_cubic<T>>& cubics) {
    using S = std::conditional_t<std::is_same_v<T, float>, double, T>;
    const std::size_t count = times.size(), segments = count - 1;
    struct record {
        S dt;
        vec3<S> angle, rise, omega, shift, x, end_rate;
        quaternion<S> turn;
        matrix3<S> to_velocity, from_velocity, diagonal;
    };
    std::vector<record> work(segments + 1);
    S shortest = infinity<S>(), longest = S(0);
    for (std::size_t j = 0; j < segments; ++j) {
        record& w = work[j];
        w.dt = static_cast<S>(times[j + 1]) - static_cast<S>(times[j]);
        shortest = w.dt < shortest ? w.dt : shortest;
        longest = w.dt > longest ? w.dt : longest;
    }
    const S unit_of_time = detail::sqrt(shortest) * detail::sqrt(longest);
    for (std::size_t k = 0; k < count; ++k)
        work[k].omega = vec3<S>(orientation.angular_velocity(times[k])) * unit_of_time;
    cubics.resize(segments);
    for (std::size_t j = 0; j < segments; ++j) {
        record& w = work[j];
        w.dt = w.dt / unit_of_time;
        const quaternion<S> q(rotations[j]);
        w.turn = relative_rotation<true>(q, quaternion<S>(rotations[j + 1]));
        w.angle = to_rotation_vector(w.turn);
        const S n = norm(w.angle), inverse = inverse_jacobian_coefficient(n);
        w.to_velocity = skew_polynomial(w.angle, S(1), -one_minus_cos_over_square(n),
                                        n_minus_sin_over_cube(n * n, n));
        w.from_velocity = skew_polynomial(w.angle, S(1), S(0.5), inverse);
        const vec3<S> step =
            rotate_unchecked(conjugate(q), vec3<S>(positions[j + 1]) - vec3<S>(positions[j]));
        w.rise = skew_polynomial(w.angle, S(1), S(-0.5), inverse) * step;  // Jl^-1 step
        if (count == 2) {  // the screw: its cubics' higher terms would round to tiny values
            cubics[0] = {{vec3<T>{}, vec3<T>{}, narrow<T>(w.angle)},
                         {vec3<T>{}, vec3<T>{}, narrow<T>(w.rise)}};
            return;
        }
    }
    // The rotation cubics, and at the end of each segment the rates of Jl, f, and the parts of
    // the equations above that segment j brings to keyframe j + 1 (coupling in `diagonal`, the
    // right side in `x`) and to keyframe j (the right side in `end_rate`, reused for it).
    for (std::size_t j = 0; j < segments; ++j) {
        record& w = work[j];
        const hermite_cubic<S> turning =
            hermite_cubic_of(w.angle, w.omega * w.dt, (w.from_velocity * work[j + 1].omega) * w.dt);
        cubics[j].angular = {narrow<T>(turning.a), narrow<T>(turning.b), narrow<T>(turning.c)};
        const cubic_motion<S> end = cubic_motion_at(turning, S(1), w.dt);
        const left_jacobian_rates<S> rates = left_jacobian_rates_of(w.angle, end.rate, end.second);
        const S n = norm(w.angle);
        const auto back = [&](const vec3<S>& v) { return rotate_unchecked(conjugate(w.turn), v); };
        const typename left_jacobian_rates<S>::terms along = rates(w.rise);
        w.shift = -(skew_polynomial(w.angle, S(1), S(-0.5), inverse_jacobian_coefficient(n)) *
                    along.rate);
        matrix3<S> coupling{};
        for (int c = 0; c < 3; ++c) {
            const matrix3<S>& m = w.from_velocity;
            const vec3<S> column = back(rates(vec3<S>{m(0, c), m(1, c), m(2, c)}).rate) * S(2);
            coupling(0, c) = column.x;
            coupling(1, c) = column.y;
            coupling(2, c) = column.z;
        }
        w.diagonal = coupling;
        w.x = w.to_velocity * (w.rise * (S(6) / (w.dt * w.dt)) - w.shift * (S(4) / w.dt)) -
              back(rates(w.shift).rate) * S(2) - back(along.second);
        w.end_rate = w.rise * (S(6) / (w.dt * w.dt)) - w.shift * (S(2) / w.dt);
    }
    // Unknown m is the velocity at keyframe m + 1, between segments m and m + 1.
    const std::size_t inner = count - 2;
    const vec3<S> first = work[0].rise / work[0].dt;
    const vec3<S> last = work[segments - 1].rise / work[segments - 1].dt;
    for (std::size_t m = 0; m < inner; ++m) {
        record& p = work[m];
        const record& s = work[m + 1];
        p.diagonal = p.diagonal + skew_polynomial(s.omega, S(4) / p.dt + S(4) / s.dt, S(-1), S(0));
        p.x += s.end_rate;
        if (m == 0) p.x -= p.to_velocity * first * (S(2) / p.dt);
        if (m + 1 == inner) p.x -= s.from_velocity * last * (S(2) / s.dt);
    }
    solve_block_tridiagonal(
        inner, [&](std::size_t m) { return work[m].to_velocity * (S(2) / work[m].dt); },
        [&](std::size_t m) -> matrix3<S>& { return work[m].diagonal; },
        [&](std::size_t m) { return work[m + 1].from_velocity * (S(2) / work[m + 1].dt); },
        [&](std::size_t m) -> vec3<S>& { return work[m].x; });
    const auto velocity = [&](std::size_t k) -> vec3<S> {
        return k == 0 ? first : k == segments ? last : work[k - 1].x;
    };
    for (std::size_t j = 0; j < segments; ++j) {
        const record& w = work[j];
        const hermite_cubic<S> moving = hermite_cubic_of(
            w.rise, velocity(j) * w.dt, (w.from_velocity * velocity(j + 1) + w.shift) * w.dt);
        cubics[j].linear = {narrow<T>(moving.a), narrow<T>(moving.b), narrow<T>(moving.c)};
    }
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_DETAIL_SE3_CUBICS_HPP_INCLUDED
