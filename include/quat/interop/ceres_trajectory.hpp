// Opt-in Ceres residuals on the cumulative B-splines of trajectory/ (not included by quat.hpp or by
// interop/ceres.hpp; needs Ceres's headers and library): a pose, a gyroscope or an accelerometer
// reading at one time, with analytic Jacobians over the spline's control points, for fitting a
// continuous-time trajectory to camera and IMU measurements. The parameter blocks are those of
// interop/ceres.hpp's manifolds.
//
// Each cost function is one measurement at one time t. Its parameter blocks are the K control
// points of the segment that holds t, points first .. first + K - 1, in that order, passed to
// AddResidualBlock one pointer each: rotations as quaternion blocks (w, x, y, z:
// quaternion_manifold), SE(3) points as pose blocks (w, x, y, z, tx, ty, tz: pose_manifold),
// positions as 3 numbers, then a bias block of 3 where the sensor has one. The cost holds the
// offset t - t0 - first dt, in [0, dt], and the knot spacing dt; the spline's segment_at(t) gives
// first and offset. Jacobians are analytic (the spline's, trajectory/detail/lie_bspline.hpp) times
// the manifolds' MinusJacobian, exact along every change that keeps the quaternions unit, as
// relative_pose_cost's. Precondition: unit quaternions; a NaN or infinite number gives a
// non-finite residual.
#ifndef QUAT_INTEROP_CERES_TRAJECTORY_HPP_INCLUDED
#define QUAT_INTEROP_CERES_TRAJECTORY_HPP_INCLUDED

#include <array>
#include <cstddef>
#include <initializer_list>

#include <ceres/cost_function.h>

#include "../lie/se3.hpp"
#include "../lie/so3.hpp"
#include "../trajectory/se3_bspline.hpp"
#include "../trajectory/so3_bspline.hpp"
#include "../trajectory/split_bspline.hpp"
#include "ceres.hpp"

namespace quat {

#include "../detail/isa_namespace.inc"
namespace detail {

/// The base of the B-spline costs: `residuals` outputs, K blocks of each size in `point_sizes` in
/// turn (the segment's rotations or poses, then its positions where the spline has them), then
/// `extra` blocks of the given sizes; it holds the measurement's offset into its segment and the
/// knot spacing, and evaluates the spline over the point blocks there.
template <std::size_t K>
class bspline_cost_base : public ::ceres::CostFunction {
protected:
    bspline_cost_base(double offset, double dt, int residuals,
                      std::initializer_list<int> point_sizes, std::initializer_list<int> extra)
        : offset_(offset), dt_(dt) {
        set_num_residuals(residuals);
        for (const int size : point_sizes)
            for (std::size_t m = 0; m < K; ++m) mutable_parameter_block_sizes()->push_back(size);
        for (const int size : extra) mutable_parameter_block_sizes()->push_back(size);
    }
    /// so3_bspline's evaluate(offset, J...) over the K quaternion blocks.
    template <class... Jacobians>
    so3_bspline_sample<double> so3_sample(double const* const* parameters,
                                          Jacobians... J) const noexcept {
        std::array<quaternion<double>, K> q{};
        for (std::size_t m = 0; m < K; ++m) q[m] = quaternion_from_parameters(parameters[m]);
        return so3_bspline<double, K>(q.data(), K, 0.0, dt_).evaluate(offset_, J...);
    }
    /// se3_bspline's evaluate(offset, J...) over the K pose blocks.
    template <class... Jacobians>
    se3_bspline_sample<double> se3_sample(double const* const* parameters,
                                          Jacobians... J) const noexcept {
        std::array<dual_quaternion<double>, K> x{};
        for (std::size_t m = 0; m < K; ++m) x[m] = pose_from_parameters(parameters[m]);
        return se3_bspline<double, K>(x.data(), K, 0.0, dt_).evaluate(offset_, J...);
    }
    /// split_bspline's evaluate(offset, J...) over the K quaternion blocks and K position blocks.
    template <class... Jacobians>
    split_bspline_sample<double> split_sample(double const* const* parameters,
                                              Jacobians... J) const noexcept {
        std::array<quaternion<double>, K> q{};
        std::array<vec3<double>, K> p{};
        for (std::size_t m = 0; m < K; ++m) {
            q[m] = quaternion_from_parameters(parameters[m]);
            p[m] = vec3_from_parameters(parameters[K + m]);
        }
        return split_bspline<double, K>(q.data(), p.data(), K, 0.0, dt_).evaluate(offset_, J...);
    }
    static bool wants(double** jacobians, std::size_t block) noexcept {
        return jacobians != nullptr && jacobians[block] != nullptr;
    }

private:
    double offset_, dt_;
};

/// A 3-vector as a column.
[[nodiscard]] inline matrix<double, 3, 1> column_of(const vec3<double>& v) noexcept {
    return {{{v.x}, {v.y}, {v.z}}};
}

}  // namespace detail

/// A rotation measurement Z at one time on an so3_bspline<double, K>: the residual
/// S log(Z^-1 R(t)) (3), S a 3x3 weight such as the square root of the information; K quaternion
/// blocks (see above).
template <std::size_t K>
class so3_bspline_rotation_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    so3_bspline_rotation_cost(double offset, double dt, const quaternion<double>& measured,
                              const matrix3<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 3, {4}, {}),
          measured_(measured),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename so3_bspline<double, K>::jacobian_blocks J_q{};
        const so3_bspline_sample<double> s =
            this->so3_sample(parameters, jacobians != nullptr ? &J_q : nullptr);
        matrix3<double> J_e_r{};
        const vec3<double> e = so3::minus(s.rotation, measured_, &J_e_r);
        write_parameters(sqrt_information_ * e, residuals);
        for (std::size_t m = 0; m < K; ++m)
            if (this->wants(jacobians, m))
                detail::write_rotation_jacobian<3>(sqrt_information_ * J_e_r * J_q[m],
                                                   parameters[m], jacobians[m]);
        return true;
    }

private:
    quaternion<double> measured_;
    matrix3<double> sqrt_information_;
};

/// A pose measurement Z at one time on an se3_bspline<double, K>: the residual S log(Z^-1 X(t))
/// (6, linear first), S a 6x6 weight; K pose blocks.
template <std::size_t K>
class se3_bspline_pose_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    se3_bspline_pose_cost(double offset, double dt, const dual_quaternion<double>& measured,
                          const matrix6<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 6, {7}, {}),
          measured_(measured),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename se3_bspline<double, K>::jacobian_blocks J_x{};
        const se3_bspline_sample<double> s =
            this->se3_sample(parameters, jacobians != nullptr ? &J_x : nullptr);
        matrix6<double> J_e_x{};
        const matrix<double, 6, 1> e =
            sqrt_information_ * se3::to_vector(se3::minus(s.motion, measured_, &J_e_x));
        for (int k = 0; k < 6; ++k) residuals[k] = e(k, 0);
        for (std::size_t m = 0; m < K; ++m)
            if (this->wants(jacobians, m))
                detail::write_pose_jacobian<6>(sqrt_information_ * J_e_x * J_x[m], parameters[m],
                                               jacobians[m]);
        return true;
    }

private:
    dual_quaternion<double> measured_;
    matrix6<double> sqrt_information_;
};

/// A pose measurement Z at one time on a split_bspline<double, K>: the residual
/// S (p(t) - t_Z, log(R_Z^-1 R(t))) (6, position first), S a 6x6 weight; K quaternion blocks, then
/// K position blocks.
template <std::size_t K>
class split_bspline_pose_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    split_bspline_pose_cost(double offset, double dt, const dual_quaternion<double>& measured,
                            const matrix6<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 6, {4, 3}, {}),
          measured_rotation_(rotation_of(measured)),
          measured_position_(translation_of(measured)),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename split_bspline<double, K>::jacobian_blocks J_q{};
        typename split_bspline<double, K>::jacobian_weights W_p{};
        const bool any = jacobians != nullptr;
        const split_bspline_sample<double> s = this->split_sample(
            parameters, any ? &J_q : nullptr, nullptr, nullptr, nullptr, any ? &W_p : nullptr);
        matrix3<double> J_e_r{};
        const vec3<double> angle = so3::minus(s.rotation, measured_rotation_, &J_e_r);
        const vec3<double> shift = s.position - measured_position_;
        const matrix<double, 6, 1> e =
            sqrt_information_ *
            matrix<double, 6, 1>{
                {{shift.x}, {shift.y}, {shift.z}, {angle.x}, {angle.y}, {angle.z}}};
        for (int k = 0; k < 6; ++k) residuals[k] = e(k, 0);
        const matrix<double, 6, 3> S_angle = block<6, 3>(sqrt_information_, 0, 3);
        const matrix<double, 6, 3> S_shift = block<6, 3>(sqrt_information_, 0, 0);
        for (std::size_t m = 0; m < K; ++m) {
            if (this->wants(jacobians, m))
                detail::write_rotation_jacobian<6>(S_angle * J_e_r * J_q[m], parameters[m],
                                                   jacobians[m]);
            if (this->wants(jacobians, K + m))
                detail::write_plain_jacobian<6, 3>(S_shift * W_p[m], jacobians[K + m]);
        }
        return true;
    }

private:
    quaternion<double> measured_rotation_;
    vec3<double> measured_position_;
    matrix6<double> sqrt_information_;
};

/// A gyroscope reading at one time on an so3_bspline<double, K> (or a split_bspline's rotations):
/// the residual S (omega(t) + b - measured) (3), omega the body angular velocity and b the bias;
/// K quaternion blocks, then the bias block (3).
template <std::size_t K>
class so3_bspline_gyroscope_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    so3_bspline_gyroscope_cost(double offset, double dt, const vec3<double>& measured,
                               const matrix3<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 3, {4}, {3}),
          measured_(measured),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename so3_bspline<double, K>::jacobian_blocks J_w{};
        const so3_bspline_sample<double> s =
            this->so3_sample(parameters, nullptr, jacobians != nullptr ? &J_w : nullptr);
        write_parameters(sqrt_information_ *
                             (s.angular_velocity + vec3_from_parameters(parameters[K]) - measured_),
                         residuals);
        for (std::size_t m = 0; m < K; ++m)
            if (this->wants(jacobians, m))
                detail::write_rotation_jacobian<3>(sqrt_information_ * J_w[m], parameters[m],
                                                   jacobians[m]);
        if (this->wants(jacobians, K))
            detail::write_plain_jacobian<3, 3>(sqrt_information_, jacobians[K]);
        return true;
    }

private:
    vec3<double> measured_;
    matrix3<double> sqrt_information_;
};

/// A gyroscope reading at one time on an se3_bspline<double, K>: S (omega(t) + b - measured), omega
/// the angular part of the body twist; K pose blocks, then the bias block (3).
template <std::size_t K>
class se3_bspline_gyroscope_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    se3_bspline_gyroscope_cost(double offset, double dt, const vec3<double>& measured,
                               const matrix3<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 3, {7}, {3}),
          measured_(measured),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename se3_bspline<double, K>::jacobian_blocks J_v{};
        const se3_bspline_sample<double> s =
            this->se3_sample(parameters, nullptr, jacobians != nullptr ? &J_v : nullptr);
        write_parameters(sqrt_information_ *
                             (s.velocity.angular + vec3_from_parameters(parameters[K]) - measured_),
                         residuals);
        for (std::size_t m = 0; m < K; ++m)
            if (this->wants(jacobians, m))
                detail::write_pose_jacobian<3>(sqrt_information_ * block<3, 6>(J_v[m], 3, 0),
                                               parameters[m], jacobians[m]);
        if (this->wants(jacobians, K))
            detail::write_plain_jacobian<3, 3>(sqrt_information_, jacobians[K]);
        return true;
    }

private:
    vec3<double> measured_;
    matrix3<double> sqrt_information_;
};

/// An accelerometer reading at one time on a split_bspline<double, K>: the residual
/// S (R(t)^T (p''(t) - g) + b - measured) (3), p'' the world-frame acceleration, g gravity in the
/// world frame (such as (0, 0, -9.81)) and b the bias; K quaternion blocks, K position blocks, then
/// the bias block (3).
template <std::size_t K>
class split_bspline_accelerometer_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    split_bspline_accelerometer_cost(double offset, double dt, const vec3<double>& measured,
                                     const vec3<double>& gravity,
                                     const matrix3<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 3, {4, 3}, {3}),
          measured_(measured),
          gravity_(gravity),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename split_bspline<double, K>::jacobian_blocks J_q{};
        typename split_bspline<double, K>::jacobian_weights W_a{};
        const bool any = jacobians != nullptr;
        const split_bspline_sample<double> s =
            this->split_sample(parameters, any ? &J_q : nullptr, nullptr, nullptr, nullptr, nullptr,
                               nullptr, any ? &W_a : nullptr);
        const quaternion<double> inverse = conjugate(s.rotation);
        const vec3<double> body = rotate(inverse, s.linear_acceleration - gravity_);
        write_parameters(
            sqrt_information_ * (body + vec3_from_parameters(parameters[2 * K]) - measured_),
            residuals);
        // (R exp(theta))^T y = R^T y + [R^T y]x theta to first order.
        const matrix3<double> S_turn = sqrt_information_ * so3::hat(body);
        const matrix3<double> S_back = sqrt_information_ * to_matrix3(to_matrix(inverse));
        for (std::size_t m = 0; m < K; ++m) {
            if (this->wants(jacobians, m))
                detail::write_rotation_jacobian<3>(S_turn * J_q[m], parameters[m], jacobians[m]);
            if (this->wants(jacobians, K + m))
                detail::write_plain_jacobian<3, 3>(S_back * W_a[m], jacobians[K + m]);
        }
        if (this->wants(jacobians, 2 * K))
            detail::write_plain_jacobian<3, 3>(sqrt_information_, jacobians[2 * K]);
        return true;
    }

private:
    vec3<double> measured_, gravity_;
    matrix3<double> sqrt_information_;
};

/// An accelerometer reading at one time on an se3_bspline<double, K>: the residual
/// S (a - R(t)^T g + b - measured) (3), a = v' + omega x v the body-frame acceleration R^T p''
/// from the body twist (v, omega) and its derivative; K pose blocks, then the bias block (3).
template <std::size_t K>
class se3_bspline_accelerometer_cost final : public detail::bspline_cost_base<K> {
public:
    /// The measurement at `offset` into its segment, in [0, dt], on a spline of knot spacing dt,
    /// weighted by sqrt_information (S above).
    se3_bspline_accelerometer_cost(double offset, double dt, const vec3<double>& measured,
                                   const vec3<double>& gravity,
                                   const matrix3<double>& sqrt_information) noexcept
        : detail::bspline_cost_base<K>(offset, dt, 3, {7}, {3}),
          measured_(measured),
          gravity_(gravity),
          sqrt_information_(sqrt_information) {}

    /// The weighted residual from the blocks in parameters (the layout above); each jacobians[k]
    /// that is not null receives the row-major Jacobian with respect to block k. Always succeeds: a
    /// non-finite input shows as a non-finite residual.
    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        typename se3_bspline<double, K>::jacobian_blocks J_x{}, J_v{}, J_a{};
        const bool any = jacobians != nullptr;
        const se3_bspline_sample<double> s = this->se3_sample(
            parameters, any ? &J_x : nullptr, any ? &J_v : nullptr, any ? &J_a : nullptr);
        const vec3<double> v = s.velocity.linear, w = s.velocity.angular;
        const vec3<double> gravity_body = rotate(conjugate(rotation_of(s.motion)), gravity_);
        write_parameters(sqrt_information_ * (s.acceleration.linear + cross(w, v) - gravity_body +
                                              vec3_from_parameters(parameters[K]) - measured_),
                         residuals);
        // d(omega x v) = [omega]x dv - [v]x domega; d(-R^T g) = -[R^T g]x dtheta.
        for (std::size_t m = 0; m < K; ++m)
            if (this->wants(jacobians, m)) {
                const matrix<double, 3, 6> J = block<3, 6>(J_a[m], 0, 0) +
                                               so3::hat(w) * block<3, 6>(J_v[m], 0, 0) -
                                               so3::hat(v) * block<3, 6>(J_v[m], 3, 0) -
                                               so3::hat(gravity_body) * block<3, 6>(J_x[m], 3, 0);
                detail::write_pose_jacobian<3>(sqrt_information_ * J, parameters[m], jacobians[m]);
            }
        if (this->wants(jacobians, K))
            detail::write_plain_jacobian<3, 3>(sqrt_information_, jacobians[K]);
        return true;
    }

private:
    vec3<double> measured_, gravity_;
    matrix3<double> sqrt_information_;
};
}  // inline namespace isa_...

}  // namespace quat

#endif  // QUAT_INTEROP_CERES_TRAJECTORY_HPP_INCLUDED
