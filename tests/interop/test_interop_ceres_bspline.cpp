// interop/ceres.hpp's residuals on cumulative B-splines (rotation or pose at a time, gyroscope,
// accelerometer): residuals and analytic Jacobians against ceres::Jet automatic differentiation of
// the same residual written from its formula here, the spline evaluated on Jets. Jacobians are
// compared along the manifolds (times quaternion_manifold's or pose_manifold's PlusJacobian), where
// the derivative is unique, relative to the largest entry, within 1e-13.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <ceres/dynamic_autodiff_cost_function.h>
#include <quat/interop/ceres_trajectory.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

using quat::dual_quaternion;
using quat::matrix;
using quat::matrix3;
using quat::matrix6;
using quat::quaternion;
using quat::vec3;

namespace {

constexpr double tolerance = 1e-13;
double worst_relative = 0;  // printed at the end
const vec3<double> gravity{0.1, -0.2, -9.81};

template <class T>
vec3<T> lift(const vec3<double>& v) {
    return {T(v.x), T(v.y), T(v.z)};
}
template <class T, int R, int C>
matrix<T, R, C> lift(const matrix<double, R, C>& m) {
    matrix<T, R, C> out{};
    for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) out(r, c) = T(m(r, c));
    return out;
}
template <class T>
void write(const matrix<T, 3, 3>& S, const vec3<T>& e, T* residuals) {
    const vec3<T> r = S * e;
    residuals[0] = r.x;
    residuals[1] = r.y;
    residuals[2] = r.z;
}

/// The reference residuals, on Jets: `kind` picks which; blocks as the cost functions take them.
template <std::size_t K>
struct reference {
    enum kind_t { rotation, pose, split_pose, gyro, se3_gyro, accel, se3_accel } kind;
    double offset, dt;
    dual_quaternion<double> measured_pose;
    vec3<double> measured;
    matrix6<double> S6;
    matrix3<double> S3;

    template <class T>
    bool operator()(T const* const* p, T* residuals) const {
        std::array<quaternion<T>, K> q{};
        std::array<vec3<T>, K> x{};
        std::array<dual_quaternion<T>, K> X{};
        for (int m = 0; m < static_cast<int>(K); ++m) {
            q[m] = quat::quaternion_from_parameters(p[m]);
            X[m] = quat::pose_from_parameters(p[m]);
            if (kind == split_pose || kind == accel) x[m] = quat::vec3_from_parameters(p[K + m]);
        }
        const T t(offset), step(dt), zero(0);
        const matrix3<T> S3j = lift<T>(S3);
        if (kind == rotation) {
            const auto s = quat::so3_bspline<T, K>(q.data(), K, zero, step).evaluate(t);
            write(S3j, quat::so3::minus(s.rotation, quaternion<T>(measured_pose.real)), residuals);
        } else if (kind == pose) {
            const auto s = quat::se3_bspline<T, K>(X.data(), K, zero, step).evaluate(t);
            const auto e = lift<T>(S6) * quat::se3::to_vector(quat::se3::minus(
                                             s.motion, dual_quaternion<T>(measured_pose)));
            for (int k = 0; k < 6; ++k) residuals[k] = e(k, 0);
        } else if (kind == split_pose) {
            const auto s = quat::split_bspline<T, K>(q.data(), x.data(), K, zero, step).evaluate(t);
            const vec3<T> d = s.position - lift<T>(quat::translation_of(measured_pose));
            const vec3<T> a =
                quat::so3::minus(s.rotation, quaternion<T>(quat::rotation_of(measured_pose)));
            const matrix<T, 6, 1> e =
                lift<T>(S6) * matrix<T, 6, 1>{{{d.x}, {d.y}, {d.z}, {a.x}, {a.y}, {a.z}}};
            for (int k = 0; k < 6; ++k) residuals[k] = e(k, 0);
        } else if (kind == gyro) {
            const auto s = quat::so3_bspline<T, K>(q.data(), K, zero, step).evaluate(t);
            write(S3j, s.angular_velocity + quat::vec3_from_parameters(p[K]) - lift<T>(measured),
                  residuals);
        } else if (kind == se3_gyro) {
            const auto s = quat::se3_bspline<T, K>(X.data(), K, zero, step).evaluate(t);
            write(S3j, s.velocity.angular + quat::vec3_from_parameters(p[K]) - lift<T>(measured),
                  residuals);
        } else if (kind == accel) {
            // R^T (p'' - g) from the spline's world-frame acceleration.
            const auto s = quat::split_bspline<T, K>(q.data(), x.data(), K, zero, step).evaluate(t);
            const vec3<T> body =
                quat::rotate(quat::conjugate(s.rotation), s.linear_acceleration - lift<T>(gravity));
            write(S3j, body + quat::vec3_from_parameters(p[2 * K]) - lift<T>(measured), residuals);
        } else {
            // From the twist: v' + omega x v - R^T g.
            const auto s = quat::se3_bspline<T, K>(X.data(), K, zero, step).evaluate(t);
            const vec3<T> a = s.acceleration.linear +
                              quat::cross(s.velocity.angular, s.velocity.linear) -
                              quat::rotate(quat::conjugate(s.motion.real), lift<T>(gravity));
            write(S3j, a + quat::vec3_from_parameters(p[K]) - lift<T>(measured), residuals);
        }
        return true;
    }
};

/// Evaluates `cost` and the Jet reference at `blocks`; compares the residuals and, block by
/// block, both Jacobians times the block's manifold PlusJacobian (identity for plain numbers).
template <std::size_t K>
void compare(const ceres::CostFunction& cost, const reference<K>& functor,
             std::vector<std::vector<double>>& blocks) {
    ceres::DynamicAutoDiffCostFunction<reference<K>, 4> jet(new reference<K>(functor));
    for (const auto& b : blocks) jet.AddParameterBlock(static_cast<int>(b.size()));
    const int n = cost.num_residuals();
    jet.SetNumResiduals(n);
    REQUIRE(cost.parameter_block_sizes() == jet.parameter_block_sizes());
    std::vector<const double*> parameters;
    for (const auto& b : blocks) parameters.push_back(b.data());
    std::vector<std::vector<double>> Ja, Jj;
    std::vector<double*> pa, pj;
    for (const auto& b : blocks) {
        Ja.emplace_back(static_cast<std::size_t>(n) * b.size());
        Jj.emplace_back(static_cast<std::size_t>(n) * b.size());
        pa.push_back(Ja.back().data());
        pj.push_back(Jj.back().data());
    }
    std::vector<double> ra(static_cast<std::size_t>(n)), rj(static_cast<std::size_t>(n));
    REQUIRE(cost.Evaluate(parameters.data(), ra.data(), pa.data()));
    REQUIRE(jet.Evaluate(parameters.data(), rj.data(), pj.data()));
    double worst = 0, scale = 0;
    for (int k = 0; k < n; ++k) {
        worst = std::max(worst, std::abs(ra[k] - rj[k]));
        scale = std::max(scale, std::abs(rj[k]));
    }
    CHECK(worst <= tolerance * std::max(1.0, scale));
    const quat::quaternion_manifold rotation_manifold;
    const quat::pose_manifold pose_manifold;
    double difference = 0, largest = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const int size = static_cast<int>(blocks[b].size());
        const int tangent = size == 4 ? 3 : size == 7 ? 6 : size;
        std::vector<double> plus(static_cast<std::size_t>(size * tangent), 0.0);
        if (size == 4) REQUIRE(rotation_manifold.PlusJacobian(blocks[b].data(), plus.data()));
        else if (size == 7) REQUIRE(pose_manifold.PlusJacobian(blocks[b].data(), plus.data()));
        else
            for (int i = 0; i < size; ++i) plus[static_cast<std::size_t>(i * tangent + i)] = 1;
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < tangent; ++c) {
                double a = 0, j = 0;
                for (int k = 0; k < size; ++k) {
                    const double weight = plus[static_cast<std::size_t>(k * tangent + c)];
                    a += Ja[b][static_cast<std::size_t>(r * size + k)] * weight;
                    j += Jj[b][static_cast<std::size_t>(r * size + k)] * weight;
                }
                difference = std::max(difference, std::abs(a - j));
                largest = std::max(largest, std::abs(j));
            }
    }
    // Relative to the largest entry of the whole Jacobian (all blocks): a block far from t has
    // entries many orders smaller, where the same rounding is a larger fraction.
    INFO("largest entry " << largest << ", largest difference " << difference);
    CHECK(difference <= tolerance * largest);
    worst_relative = std::max(worst_relative, difference / largest);
}

template <std::size_t K>
void check_all(quat::test::random_rotations& random) {
    using ref = reference<K>;
    for (int trial = 0; trial < 20; ++trial) {
        // K control points a turn of up to 1 rad apart, positions a unit apart; a time in the
        // segment with dt = 0.5; random measurements and weights.
        std::vector<quaternion<double>> q{random.unit_quaternion<double>()};
        std::vector<vec3<double>> x{random.vector<double>()};
        for (int m = 1; m < static_cast<int>(K); ++m) {
            q.push_back(q.back() * quat::from_rotation_vector(random.vector<double>() * 0.5));
            x.push_back(x.back() + random.vector<double>());
        }
        ref f{};
        f.offset = random.uniform<double>(0, 0.5);
        f.dt = 0.5;
        f.measured_pose =
            quat::to_dual_quaternion(random.unit_quaternion<double>(), random.vector<double>());
        f.measured = random.vector<double>();
        for (int r = 0; r < 6; ++r)
            for (int c = r; c < 6; ++c)
                f.S6(r, c) = (r == c ? 1.0 : 0.0) + 0.1 * random.uniform<double>(-1, 1);
        for (int r = 0; r < 3; ++r)
            for (int c = r; c < 3; ++c)
                f.S3(r, c) = (r == c ? 1.0 : 0.0) + 0.1 * random.uniform<double>(-1, 1);
        std::vector<std::vector<double>> rotations, poses, positions;
        for (int m = 0; m < static_cast<int>(K); ++m) {
            rotations.push_back({q[m].w, q[m].x, q[m].y, q[m].z});
            poses.push_back({q[m].w, q[m].x, q[m].y, q[m].z, x[m].x, x[m].y, x[m].z});
            positions.push_back({x[m].x, x[m].y, x[m].z});
        }
        const std::vector<double> bias{0.01, -0.02, 0.03};
        const auto join = [](std::vector<std::vector<double>> a,
                             const std::vector<std::vector<double>>& b) {
            a.insert(a.end(), b.begin(), b.end());
            return a;
        };
        auto blocks = rotations;
        f.kind = ref::rotation;
        compare<K>(quat::so3_bspline_rotation_cost<K>(f.offset, f.dt, f.measured_pose.real, f.S3),
                   f, blocks);
        blocks = poses;
        f.kind = ref::pose;
        compare<K>(quat::se3_bspline_pose_cost<K>(f.offset, f.dt, f.measured_pose, f.S6), f,
                   blocks);
        blocks = join(rotations, positions);
        f.kind = ref::split_pose;
        compare<K>(quat::split_bspline_pose_cost<K>(f.offset, f.dt, f.measured_pose, f.S6), f,
                   blocks);
        blocks = join(rotations, {bias});
        f.kind = ref::gyro;
        compare<K>(quat::so3_bspline_gyroscope_cost<K>(f.offset, f.dt, f.measured, f.S3), f,
                   blocks);
        blocks = join(poses, {bias});
        f.kind = ref::se3_gyro;
        compare<K>(quat::se3_bspline_gyroscope_cost<K>(f.offset, f.dt, f.measured, f.S3), f,
                   blocks);
        blocks = join(join(rotations, positions), {bias});
        f.kind = ref::accel;
        compare<K>(
            quat::split_bspline_accelerometer_cost<K>(f.offset, f.dt, f.measured, gravity, f.S3), f,
            blocks);
        blocks = join(poses, {bias});
        f.kind = ref::se3_accel;
        compare<K>(
            quat::se3_bspline_accelerometer_cost<K>(f.offset, f.dt, f.measured, gravity, f.S3), f,
            blocks);
    }
}

}  // namespace

TEST_CASE(
    "B-spline costs of interop/ceres.hpp: residuals and Jacobians as Jet autodiff of the "
    "same residual, along the manifolds, within 1e-13",
    "[interop][ceres]") {
    quat::test::random_rotations random(20261127);
    check_all<4>(random);
    check_all<5>(random);
    check_all<6>(random);
    std::printf("B-spline costs: largest Jacobian difference %.3g of the largest entry\n",
                worst_relative);
}
