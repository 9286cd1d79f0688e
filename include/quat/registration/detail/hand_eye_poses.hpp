// Hand-eye calibration from absolute poses, behind registration/hand_eye.hpp's hand_eye_from_poses:
// the motions between pairs of poses as views the closed-form solvers index, and the maximum-
// likelihood refinement of the mount X together with the target's pose W in the robot's base.
//
// Model: the hand's poses H_j (hand in base) are exact; the target's poses S_j (target in sensor)
// obey S_j = X^-1 H_j^-1 W and are measured as (exp(w_j) R_j, t_j + v_j), with w_j (radians, in the
// sensor's frame) and v_j (length) zero-mean isotropic Gaussian noise of unknown variances
// sigma_r^2 and sigma_t^2, independent over j. The negative log-likelihood over X, W, sigma_r and
// sigma_t is, up to constants, sum_j |r_j|^2 / (2 sigma_r^2) + |e_j|^2 / (2 sigma_t^2)
// + 3 n log(sigma_r sigma_t) for r_j = log(R_sj R_pj^T) and e_j = t_sj - t_pj, (R_pj, t_pj) the
// prediction X^-1 H_j^-1 W. For fixed X and W the variances that minimize it are the mean squared
// residual components; for fixed variances X and W are a weighted least-squares problem. The
// refinement alternates the two for two rounds: Gauss-Newton weighted by the closed form's
// residuals, then by the first round's. With many poses that is the likelihood's maximum (at 51
// poses within 1e-3 of the answer's uncertainty, tests/test_hand_eye_from_poses.cpp). With few,
// the likelihood has no maximum: it grows without bound as one kind of residual goes to 0, which
// 12 unknowns can nearly reach from 6 n residuals; two rounds stop short of that, and more rounds
// measured no better at 11 and 51 poses and worse at 4 (the 95th percentile of the rotation error
// 17-19 % larger with four rounds, examples/hand_eye.cpp's scene). Weighting by the variances
// that the data imply, not by a constant, is what keeps the answer independent of the unit of
// length: scaling every translation by s scales sigma_t by s and leaves the weighted cost's
// minimizer where it was (scaled).
#ifndef QUAT_REGISTRATION_DETAIL_HAND_EYE_POSES_HPP_INCLUDED
#define QUAT_REGISTRATION_DETAIL_HAND_EYE_POSES_HPP_INCLUDED

#include <cstddef>

#include "../../config.hpp"
#include "../../detail/math.hpp"
#include "../../lie/so3.hpp"
#include "../../matrix.hpp"
#include "../../quaternion.hpp"
#include "../../rigid/dual_quaternion.hpp"
#include "../../vec3.hpp"

namespace quat {
#include "../../detail/isa_namespace.inc"
namespace detail {

/// The poses a motion joins: consecutive (i = k, j = k + 1) or every pair i < j, ordered by j and
/// then i (k = j (j - 1) / 2 + i).
struct pose_pair {
    std::size_t i, j;
};

[[nodiscard]] constexpr pose_pair pair_at(std::size_t k, bool all_pairs) noexcept {
    if (!all_pairs) return {k, k + 1};
    // j from the root of 2k, corrected both ways for its rounding.
    auto j = static_cast<std::size_t>(sqrt(2.0 * static_cast<double>(k)));
    while (j > 0 && j * (j - 1) / 2 > k) --j;
    while ((j + 1) * j / 2 <= k) ++j;
    return {k - j * (j - 1) / 2, j};
}

[[nodiscard]] constexpr std::size_t pair_count(std::size_t poses, bool all_pairs) noexcept {
    if (poses < 2) return 0;
    return all_pairs ? poses * (poses - 1) / 2 : poses - 1;
}

/// The hand's motion A = H_j^-1 H_i of pair k, as hand_eye takes it.
template <class T, class P>
struct hand_motion_view {
    const P* poses;
    bool all_pairs;
    [[nodiscard]] constexpr dual_quaternion<T> operator[](std::size_t k) const noexcept {
        const pose_pair p = pair_at(k, all_pairs);
        return normalize(inverse(dual_quaternion<T>(poses[p.j])) * dual_quaternion<T>(poses[p.i]));
    }
};

/// The sensor's motion B = S_j S_i^-1 of pair k, as hand_eye takes it.
template <class T, class P>
struct target_motion_view {
    const P* poses;
    bool all_pairs;
    [[nodiscard]] constexpr dual_quaternion<T> operator[](std::size_t k) const noexcept {
        const pose_pair p = pair_at(k, all_pairs);
        return normalize(dual_quaternion<T>(poses[p.j]) * inverse(dual_quaternion<T>(poses[p.i])));
    }
};

/// The unknowns of the refinement: Y = X^-1 (the hand in the sensor's frame) and W (the target in
/// the base), translations divided by the data's power of two.
template <class T>
struct hand_eye_state {
    quaternion<T> y_rotation;
    vec3<T> y_translation;
    quaternion<T> w_rotation;
    vec3<T> w_translation;
};

/// Sums over the poses at one state: squared residual norms, and, when `normal` is given, adds
/// the Gauss-Newton normal equations J^T D J and J^T D (r, e) to it for D = diag(1, weight) (the
/// rotation rows weighted 1, the translation rows `weight` = sigma_r^2 / sigma_t^2). The 12
/// unknowns are the perturbations Y <- (exp(a) R_Y, t_Y + b), W <- (R_W exp(c), t_W + d). With
/// R_p = R_Y R_H^T R_W and t_p = R_Y u + t_Y, u = R_H^T (t_W - t_H), v = R_Y u:
///     d r = -Jr^-1(r) (a + R_p c),   d e = [v]x a - b - R_Y R_H^T d,
/// (log(E exp(-x)) = log(E) - Jr^-1(log E) x to first order: lie/so3.hpp's log Jacobian).
template <class T>
struct pose_sums {
    T rotation, translation;
};

/// J^T D J (upper triangle) and J^T D (r, e).
template <class T>
struct normal_equations {
    T matrix[12][12];
    T gradient[12];
};

template <class T, class H, class S>
constexpr pose_sums<T> accumulate_poses(const H* hands, const S* targets, std::size_t count, T p,
                                        const hand_eye_state<T>& x, T weight,
                                        type_identity_t<normal_equations<T>>* normal) noexcept {
    pose_sums<T> sums{T(0), T(0)};
    const matrix3<T> ry = to_matrix3(to_matrix(x.y_rotation));
    for (std::size_t j = 0; j < count; ++j) {
        const dual_quaternion<T> h(hands[j]), s(targets[j]);
        const quaternion<T> hr = rotation_of(h), sr = rotation_of(s);
        const vec3<T> ht = translation_of(h) / p, st = translation_of(s) / p;
        const quaternion<T> predicted = x.y_rotation * conjugate(hr) * x.w_rotation;
        const vec3<T> u = rotate(conjugate(hr), x.w_translation - ht);
        const vec3<T> v = rotate(x.y_rotation, u);
        matrix3<T> jr_inverse = matrix3<T>::identity();
        const vec3<T> r = so3::log(sr * conjugate(predicted), normal ? &jr_inverse : nullptr);
        const vec3<T> e = st - (v + x.y_translation);
        sums.rotation += dot(r, r);
        sums.translation += dot(e, e);
        if (normal == nullptr) continue;
        // Rows of J (rotation rows then translation rows) and the residual they act on.
        const matrix3<T> rp = to_matrix3(to_matrix(predicted));
        const matrix3<T> rc = -(jr_inverse * rp);
        const matrix3<T> rd = -(ry * transpose(to_matrix3(to_matrix(hr))));
        const matrix3<T> ea = so3::hat(v);
        T rows[6][12] = {};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) {
                rows[k][c] = -jr_inverse(k, c);
                rows[k][6 + c] = rc(k, c);
                rows[3 + k][c] = ea(k, c);
                rows[3 + k][9 + c] = rd(k, c);
            }
        for (int k = 0; k < 3; ++k) rows[3 + k][3 + k] = T(-1);
        const T residual[6] = {r.x, r.y, r.z, e.x, e.y, e.z};
        for (int k = 0; k < 6; ++k) {
            const T w = k < 3 ? T(1) : weight;
            for (int a = 0; a < 12; ++a) {
                if (rows[k][a] == T(0)) continue;
                const T wa = w * rows[k][a];
                normal->gradient[a] += wa * residual[k];
                for (int b = a; b < 12; ++b) normal->matrix[a][b] += wa * rows[k][b];
            }
        }
    }
    return sums;
}

/// Solves the symmetric positive definite n x n system m x = b (upper triangle of m given) by
/// Cholesky, in place in b. False where a pivot is not above 2^-40 of the largest diagonal
/// element (a direction the poses do not fix): the caller keeps what it had.
template <std::size_t N, class T>
constexpr bool cholesky_solve(T (&m)[N][N], T (&b)[N]) noexcept {
    T largest(0);
    for (std::size_t k = 0; k < N; ++k) largest = max(largest, m[k][k]);
    const T floor = largest * T(1) / T(1099511627776.0);
    if (!(largest > T(0))) return false;
    for (std::size_t k = 0; k < N; ++k) {  // m = L L^T, L^T stored in the upper triangle
        for (std::size_t s = 0; s < k; ++s)
            for (std::size_t c = k; c < N; ++c) m[k][c] -= m[s][k] * m[s][c];
        if (!(m[k][k] > floor)) return false;
        const T root = sqrt(m[k][k]);
        for (std::size_t c = k; c < N; ++c) m[k][c] = m[k][c] / root;
    }
    for (std::size_t k = 0; k < N; ++k) {  // L y = b
        for (std::size_t s = 0; s < k; ++s) b[k] -= m[s][k] * b[s];
        b[k] = b[k] / m[k][k];
    }
    for (std::size_t k = N; k-- > 0;) {  // L^T x = y
        for (std::size_t s = k + 1; s < N; ++s) b[k] -= m[k][s] * b[s];
        b[k] = b[k] / m[k][k];
    }
    return true;
}

/// The state moved by the perturbation (a, b, c, d) of accumulate_poses, scaled by `step`.
template <class T>
[[nodiscard]] constexpr hand_eye_state<T> moved(const hand_eye_state<T>& x, const T (&delta)[12],
                                                T step) noexcept {
    const vec3<T> a{delta[0], delta[1], delta[2]}, b{delta[3], delta[4], delta[5]};
    const vec3<T> c{delta[6], delta[7], delta[8]}, d{delta[9], delta[10], delta[11]};
    return {normalize(so3::exp(a * step) * x.y_rotation), x.y_translation + b * step,
            normalize(x.w_rotation * so3::exp(c * step)), x.w_translation + d * step};
}

/// The refined mount and the target's pose in the base, or the closed form's where the
/// refinement does not lower the likelihood's cost (then `refined` is false).
template <class T>
struct pose_refinement {
    dual_quaternion<T> mount, target;
    bool refined;
};

/// The noise's standard deviations per component that the residual sums imply, sigma_r (radians)
/// and sigma_t (in the data's power-of-two unit), each at least epsilon (rounding: exact poses
/// weigh rotation and translation alike in that unit).
template <class T>
struct noise_estimate {
    T rotation, translation;
};

template <class T>
[[nodiscard]] constexpr noise_estimate<T> noise_of(const pose_sums<T>& s, T components) noexcept {
    return {max(sqrt(s.rotation / components), epsilon<T>()),
            max(sqrt(s.translation / components), epsilon<T>())};
}

/// From the closed form's `mount` (translations in the data's unit), for count >= 1 poses: the
/// start W is the chordal mean of H_j X S_j. Where `iterate` (count >= 2 poses that fix X,
/// hand_eye's unique): two rounds, the first weighted by the closed form's residuals and the second
/// by the first's, of up to 8 Gauss-Newton steps each; a step that raises the round's cost is
/// halved up to 4 times (and ends the round where it is below sqrt(epsilon): the cost's rounding).
/// A round also ends at a step below 2^-10 of the estimated noise in every unknown (rotations
/// against sigma_r, translations against sigma_t): far below what the data can tell apart, and
/// measured in the data's own unit.
template <class T, class H, class S>
[[nodiscard]] constexpr pose_refinement<T> refine_hand_eye(const H* hands, const S* targets,
                                                           std::size_t count,
                                                           const dual_quaternion<T>& mount, T p,
                                                           bool iterate) noexcept {
    pose_refinement<T> fallback{mount, {}, false};
    // W = H_j X S_j for every j on exact data: the sign-aligned mean of the rotations, normalized,
    // and the mean translation.
    quaternion<T> w_sum{T(0), T(0), T(0), T(0)};
    vec3<T> t_sum{T(0), T(0), T(0)};
    for (std::size_t j = 0; j < count; ++j) {
        const dual_quaternion<T> w =
            dual_quaternion<T>(hands[j]) * mount * dual_quaternion<T>(targets[j]);
        const quaternion<T> r = rotation_of(w);
        w_sum += dot(r, w_sum) < T(0) ? -r : r;
        t_sum += translation_of(w) / p;
    }
    const T poses = static_cast<T>(count);
    const dual_quaternion<T> y = inverse(mount);
    hand_eye_state<T> x{rotation_of(y), translation_of(y) / p, normalize(w_sum), t_sum / poses};
    fallback.target = to_dual_quaternion(x.w_rotation, x.w_translation * p);
    if (!iterate) return fallback;

    const T components = T(3) * poses;
    const pose_sums<T> start = accumulate_poses(hands, targets, count, p, x, T(1), nullptr);
    pose_sums<T> sums = start;
    T weight(1);
    for (int round = 0; round < 2; ++round) {
        const noise_estimate<T> noise = noise_of(sums, components);
        weight = (noise.rotation / noise.translation) * (noise.rotation / noise.translation);
        normal_equations<T> normal{};
        sums = accumulate_poses(hands, targets, count, p, x, weight, &normal);
        for (int iteration = 0; iteration < 8; ++iteration) {
            T delta[12] = {};
            for (int k = 0; k < 12; ++k) delta[k] = -normal.gradient[k];
            if (!cholesky_solve<12>(normal.matrix, delta)) break;
            T largest(0), relative(0);
            for (int k = 0; k < 12; ++k) {
                largest = max(largest, abs(delta[k]));
                const bool turn = k < 3 || (k >= 6 && k < 9);
                relative =
                    max(relative, abs(delta[k]) / (turn ? noise.rotation : noise.translation));
            }
            if (relative * T(1024) <= T(1)) break;
            // The full step, with the normal equations at its end, which the next iteration
            // reuses; halved steps where it raises the cost.
            const T cost = sums.rotation + weight * sums.translation;
            hand_eye_state<T> next = moved(x, delta, T(1));
            normal = normal_equations<T>{};
            pose_sums<T> then = accumulate_poses(hands, targets, count, p, next, weight, &normal);
            if (then.rotation + weight * then.translation <= cost) {
                x = next;
                sums = then;
                continue;
            }
            // A step this small that does not lower the cost meets the cost's rounding: at the
            // minimum to within it.
            if (largest <= sqrt(epsilon<T>())) break;
            bool lowered = false;
            T step(1);
            for (int halving = 0; halving < 4 && !lowered; ++halving) {
                step = step / T(2);
                next = moved(x, delta, step);
                then = accumulate_poses(hands, targets, count, p, next, weight, nullptr);
                lowered = then.rotation + weight * then.translation <= cost;
            }
            if (!lowered) break;
            x = next;
            normal = normal_equations<T>{};
            sums = accumulate_poses(hands, targets, count, p, x, weight, &normal);
        }
    }
    // The closed form stays where the refined state does not beat it at the final weights.
    const T end_cost = sums.rotation + weight * sums.translation;
    if (!(end_cost <= start.rotation + weight * start.translation) || !is_finite(end_cost))
        return fallback;
    const dual_quaternion<T> refined_y = to_dual_quaternion(x.y_rotation, x.y_translation * p);
    return {normalize(inverse(refined_y)), to_dual_quaternion(x.w_rotation, x.w_translation * p),
            true};
}

}  // namespace detail
}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_REGISTRATION_DETAIL_HAND_EYE_POSES_HPP_INCLUDED
