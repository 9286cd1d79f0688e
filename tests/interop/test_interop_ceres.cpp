// quat/interop/ceres.hpp: quaternion_manifold and pose_manifold are manifolds in Ceres's sense
// (Plus and Minus invert each other, the Jacobians are the derivatives of Plus and Minus at zero
// and invert each other), quaternion_manifold is ceres::QuaternionManifold in other tangent
// coordinates, and a solve with either manifold finds the same, right, answer.
// Needs libceres: built as its own executable (tests/interop/CMakeLists.txt).
#include <algorithm>
#include <cmath>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <quat/fitting/align_vectors.hpp>
#include <quat/interop/ceres.hpp>
#include <quat/quat.hpp>
#include <quat/registration/align_points.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;

namespace {

/// The largest |a[i] - b[i]| over n numbers.
double max_difference(const double* a, const double* b, int n) {
    double worst = 0;
    for (int i = 0; i < n; ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    return worst;
}

/// A random pose block w, x, y, z, tx, ty, tz.
std::vector<double> random_pose(quat::test::random_rotations& random) {
    std::vector<double> p(7);
    quat::write_parameters(random.rigid_motion<double>(), p.data());
    return p;
}

/// A random tangent of n numbers with components in [-scale, scale] (angles below pi for n = 3
/// and scale <= 1.5).
std::vector<double> random_tangent(quat::test::random_rotations& random, int n, double scale) {
    std::vector<double> d(static_cast<std::size_t>(n));
    for (double& v : d) v = random.uniform<double>(-scale, scale);
    return d;
}

/// The derivative of f: R^m -> R^n at x by central differences with step h, n x m row-major.
template <class F>
std::vector<double> central_differences(F f, std::vector<double> x, int n, double h) {
    const int m = static_cast<int>(x.size());
    std::vector<double> j(static_cast<std::size_t>(n * m)), up(static_cast<std::size_t>(n)),
        down(static_cast<std::size_t>(n));
    for (int c = 0; c < m; ++c) {
        const double keep = x[static_cast<std::size_t>(c)];
        x[static_cast<std::size_t>(c)] = keep + h;
        f(x.data(), up.data());
        x[static_cast<std::size_t>(c)] = keep - h;
        f(x.data(), down.data());
        x[static_cast<std::size_t>(c)] = keep;
        for (int r = 0; r < n; ++r)
            j[static_cast<std::size_t>(r * m + c)] =
                (up[static_cast<std::size_t>(r)] - down[static_cast<std::size_t>(r)]) / (2 * h);
    }
    return j;
}

/// Checks a manifold against its own Plus and Minus at random points: round trips, Jacobians
/// against central differences, MinusJacobian * PlusJacobian = I.
void check_manifold(const ceres::Manifold& manifold, quat::test::random_rotations& random,
                    bool pose) {
    const int a = manifold.AmbientSize(), t = manifold.TangentSize();
    const auto point = [&] {
        if (pose) return random_pose(random);
        std::vector<double> q(4);
        quat::write_parameters(random.unit_quaternion<double>(), q.data());
        return q;
    };
    double worst_round_trip = 0, worst_plus_jacobian = 0, worst_minus_jacobian = 0,
           worst_product = 0;
    for (int n = 0; n < 200; ++n) {
        const std::vector<double> x = point();
        const std::vector<double> d = random_tangent(random, t, 1.5);
        // Minus undoes Plus: the tangent comes back.
        std::vector<double> y(static_cast<std::size_t>(a)), back(static_cast<std::size_t>(t));
        REQUIRE(manifold.Plus(x.data(), d.data(), y.data()));
        REQUIRE(manifold.Minus(y.data(), x.data(), back.data()));
        worst_round_trip = std::max(worst_round_trip, max_difference(back.data(), d.data(), t));
        // Plus undoes Minus: y comes back (the same quaternion, not its negative, as the angle of
        // x^-1 y is below pi).
        std::vector<double> again(static_cast<std::size_t>(a));
        REQUIRE(manifold.Plus(x.data(), back.data(), again.data()));
        worst_round_trip = std::max(worst_round_trip, max_difference(again.data(), y.data(), a));

        // PlusJacobian is d Plus(x, d) / dd at d = 0.
        std::vector<double> plus_jacobian(static_cast<std::size_t>(a * t));
        REQUIRE(manifold.PlusJacobian(x.data(), plus_jacobian.data()));
        const std::vector<double> plus_numeric = central_differences(
            [&](const double* delta, double* out) { (void)manifold.Plus(x.data(), delta, out); },
            std::vector<double>(static_cast<std::size_t>(t), 0.0), a, 1e-5);
        worst_plus_jacobian = std::max(
            worst_plus_jacobian, max_difference(plus_jacobian.data(), plus_numeric.data(), a * t));

        // MinusJacobian is d Minus(y, x) / dy at y = x, in every ambient direction (also off the
        // manifold: Minus ignores the quaternion's norm, and at y = x the translation is zero).
        std::vector<double> minus_jacobian(static_cast<std::size_t>(t * a));
        REQUIRE(manifold.MinusJacobian(x.data(), minus_jacobian.data()));
        const std::vector<double> minus_numeric = central_differences(
            [&](const double* yy, double* out) { (void)manifold.Minus(yy, x.data(), out); }, x, t,
            1e-5);
        worst_minus_jacobian =
            std::max(worst_minus_jacobian,
                     max_difference(minus_jacobian.data(), minus_numeric.data(), t * a));

        // MinusJacobian * PlusJacobian = I.
        for (int r = 0; r < t; ++r)
            for (int c = 0; c < t; ++c) {
                double sum = 0;
                for (int k = 0; k < a; ++k)
                    sum += minus_jacobian[static_cast<std::size_t>(r * a + k)] *
                           plus_jacobian[static_cast<std::size_t>(k * t + c)];
                worst_product = std::max(worst_product, std::abs(sum - (r == c ? 1.0 : 0.0)));
            }
    }
    INFO("round trip " << worst_round_trip << ", PlusJacobian " << worst_plus_jacobian
                       << ", MinusJacobian " << worst_minus_jacobian << ", product "
                       << worst_product);
    CHECK(worst_round_trip <= 1e-13);
    CHECK(worst_plus_jacobian <= 1e-9);
    CHECK(worst_minus_jacobian <= 1e-8);
    CHECK(worst_product <= 1e-14);
}

}  // namespace

TEST_CASE("Parameter blocks read and write quat types in the documented layouts",
          "[interop][ceres]") {
    const double rotation[4] = {0.5, 0.5, -0.5, 0.5};  // w first
    const quaternion<double> q = quat::quaternion_from_parameters(rotation);
    CHECK(q == quaternion<double>{0.5, 0.5, -0.5, 0.5});
    const double pose[7] = {0.5, 0.5, -0.5, 0.5, 1, 2, 3};
    const dual_quaternion<double> x = quat::pose_from_parameters(pose);
    CHECK(x.real == q);
    CHECK(quat::test::max_difference(quat::translation_of(x), vec3<double>{1, 2, 3}) <= 1e-15);
    double written[7] = {};
    quat::write_parameters(x, written);
    CHECK(max_difference(written, pose, 7) <= 1e-15);
    const double tangent[6] = {1, 2, 3, 4, 5, 6};
    const quat::se3::twist<double> v = quat::twist_from_parameters(tangent);
    CHECK(v.linear == vec3<double>{1, 2, 3});  // linear part first
    CHECK(v.angular == vec3<double>{4, 5, 6});
    double tangent_written[6] = {};
    quat::write_parameters(v, tangent_written);
    CHECK(max_difference(tangent_written, tangent, 6) == 0);
}

TEST_CASE("quaternion_manifold: x exp(d) with rotation vectors, analytic Jacobians",
          "[interop][ceres]") {
    quat::test::random_rotations random;
    const quat::quaternion_manifold manifold;
    CHECK(manifold.AmbientSize() == 4);
    CHECK(manifold.TangentSize() == 3);
    check_manifold(manifold, random, false);

    // Plus turns x about an axis of its own frame: x exp(d), not exp(d) x.
    const double x[4] = {std::sqrt(0.5), 0, 0, std::sqrt(0.5)};  // 90 degrees about z
    const double d[3] = {0.25, 0, 0};                            // about x (of x's frame)
    double y[4];
    REQUIRE(manifold.Plus(x, d, y));
    const quaternion<double> expected =
        quat::quaternion_from_parameters(x) * quat::from_rotation_vector(vec3<double>{0.25, 0, 0});
    CHECK(quat::test::max_difference(quat::quaternion_from_parameters(y), expected) <= 1e-16);
    CHECK(quat::test::max_difference(
              quat::rotate(quat::quaternion_from_parameters(y), vec3<double>{0, 0, 1}),
              vec3<double>{0, 0, 1}) > 0.2);  // the z axis moved: not about z
}

TEST_CASE("pose_manifold: X exp(tau) on SE(3), analytic Jacobians", "[interop][ceres]") {
    quat::test::random_rotations random;
    const quat::pose_manifold manifold;
    CHECK(manifold.AmbientSize() == 7);
    CHECK(manifold.TangentSize() == 6);
    check_manifold(manifold, random, true);

    // A step is a screw motion in the frame of X, not a rotation plus a world translation: a pure
    // linear step moves along X's axes, and a turn with a linear part moves on an arc.
    const double x[7] = {std::sqrt(0.5), 0, 0, std::sqrt(0.5), 1, 2, 3};  // 90 deg about z
    const double forward[6] = {1, 0, 0, 0, 0, 0};
    double y[7];
    REQUIRE(manifold.Plus(x, forward, y));
    CHECK(std::abs(y[4] - 1) <= 1e-15);  // x's own x axis is the world's y axis
    CHECK(std::abs(y[5] - 3) <= 1e-15);
    const double arc[6] = {quat::numbers::pi / 2, 0, 0, 0, 0, quat::numbers::pi / 2};
    REQUIRE(manifold.Plus(x, arc, y));
    // A quarter circle of length pi/2 (radius 1) in X's frame ends at (1, 1, 0) there: world
    // (1 - 1, 2 + 1, 3).
    CHECK(std::abs(y[4] - 0) <= 1e-15);
    CHECK(std::abs(y[5] - 3) <= 1e-15);
    CHECK(std::abs(y[6] - 3) <= 1e-15);
}

TEST_CASE("quaternion_manifold is ceres::QuaternionManifold with tangent d_ceres = R(x) d / 2",
          "[interop][ceres]") {
    quat::test::random_rotations random;
    const quat::quaternion_manifold ours;
    const ceres::QuaternionManifold theirs;
    double worst_plus = 0, worst_minus = 0, worst_plus_jacobian = 0, worst_minus_jacobian = 0;
    for (int n = 0; n < 500; ++n) {
        double x[4];
        quat::write_parameters(random.unit_quaternion<double>(), x);
        const quat::rotation_matrix<double> r =
            quat::to_matrix(quat::quaternion_from_parameters(x));
        const std::vector<double> d = random_tangent(random, 3, 1.5);
        // The same point: Plus(x, d) = Ceres's Plus(x, R(x) d / 2).
        const vec3<double> d_ceres = quat::rotate(r, quat::vec3_from_parameters(d.data())) * 0.5;
        double dc[3], y_ours[4], y_theirs[4];
        quat::write_parameters(d_ceres, dc);
        REQUIRE(ours.Plus(x, d.data(), y_ours));
        REQUIRE(theirs.Plus(x, dc, y_theirs));
        worst_plus = std::max(worst_plus, max_difference(y_ours, y_theirs, 4));
        // The same difference: Ceres's Minus(y, x) = R(x) Minus(y, x) / 2.
        double m_ours[3], m_theirs[3];
        REQUIRE(ours.Minus(y_ours, x, m_ours));
        REQUIRE(theirs.Minus(y_ours, x, m_theirs));
        const vec3<double> mapped = quat::rotate(r, quat::vec3_from_parameters(m_ours)) * 0.5;
        worst_minus = std::max(
            worst_minus, quat::test::max_difference(mapped, quat::vec3_from_parameters(m_theirs)));
        // Jacobians by the chain rule: P_ours = P_ceres R / 2, M_ceres = R M_ours / 2.
        double p_ours[12], p_theirs[12], q_ours[12], q_theirs[12];
        REQUIRE(ours.PlusJacobian(x, p_ours));
        REQUIRE(theirs.PlusJacobian(x, p_theirs));
        REQUIRE(ours.MinusJacobian(x, q_ours));
        REQUIRE(theirs.MinusJacobian(x, q_theirs));
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 3; ++j) {
                double p = 0, m = 0;
                for (int k = 0; k < 3; ++k) {
                    p += p_theirs[i * 3 + k] * r(k, j) / 2;
                    m += r(j, k) * q_ours[k * 4 + i] / 2;
                }
                worst_plus_jacobian =
                    std::max(worst_plus_jacobian, std::abs(p - p_ours[i * 3 + j]));
                worst_minus_jacobian =
                    std::max(worst_minus_jacobian, std::abs(m - q_theirs[j * 4 + i]));
            }
    }
    CHECK(worst_plus <= 1e-15);
    CHECK(worst_minus <= 1e-15);
    CHECK(worst_plus_jacobian <= 1e-15);
    CHECK(worst_minus_jacobian <= 1e-15);
}

namespace {

/// Residual rotate(q, a) - b of one pair of directions (Wahba's problem), q a rotation block.
struct direction_residual {
    vec3<double> a, b;
    template <class T>
    bool operator()(const T* rotation, T* residual) const {
        const quaternion<T> q = quat::quaternion_from_parameters(rotation);
        const vec3<T> a_t{T(a.x), T(a.y), T(a.z)}, b_t{T(b.x), T(b.y), T(b.z)};
        quat::write_parameters(quat::rotate(q, a_t) - b_t, residual);
        return true;
    }
};

/// Residual X p - target of one point pair, X a pose block.
struct point_residual {
    vec3<double> p, target;
    template <class T>
    bool operator()(const T* pose, T* residual) const {
        const vec3<T> p_t{T(p.x), T(p.y), T(p.z)}, target_t{T(target.x), T(target.y), T(target.z)};
        quat::write_parameters(quat::transform(quat::pose_from_parameters(pose), p_t) - target_t,
                               residual);
        return true;
    }
};

ceres::Solver::Options quiet_options() {
    ceres::Solver::Options options;
    options.num_threads = 1;
    options.function_tolerance = 0;
    options.gradient_tolerance = 1e-14;
    options.parameter_tolerance = 1e-15;
    options.max_num_iterations = 100;
    return options;
}

}  // namespace

TEST_CASE("A rotation solved with quaternion_manifold or ceres::QuaternionManifold is the same",
          "[interop][ceres]") {
    // Noisy directions b_i = R a_i + noise: both manifolds minimize the same cost from the same
    // start, so they must stop at the same rotation, the closed-form least-squares one.
    quat::test::random_rotations random;
    const quaternion<double> truth = random.unit_quaternion<double>();
    std::vector<vec3<double>> sources, targets;
    for (int i = 0; i < 20; ++i) {
        const vec3<double> a = random.unit_vector<double>();
        sources.push_back(a);
        targets.push_back(quat::rotate(truth, a) + random.vector<double>(0.05));
    }
    quaternion<double> solutions[2];
    double final_costs[2];
    for (int which = 0; which < 2; ++which) {
        double q[4] = {1, 0, 0, 0};  // start at the identity, far from the answer
        ceres::Problem problem;
        for (std::size_t i = 0; i < sources.size(); ++i)
            problem.AddResidualBlock(new ceres::AutoDiffCostFunction<direction_residual, 3, 4>(
                                         new direction_residual{sources[i], targets[i]}),
                                     nullptr, q);
        if (which == 0) problem.SetManifold(q, new quat::quaternion_manifold);
        else problem.SetManifold(q, new ceres::QuaternionManifold);
        ceres::Solver::Summary summary;
        ceres::Solve(quiet_options(), &problem, &summary);
        CHECK(summary.IsSolutionUsable());
        solutions[which] = quat::quaternion_from_parameters(q);
        final_costs[which] = summary.final_cost;
    }
    CHECK(std::abs(quat::norm(solutions[0]) - 1) <= 1e-14);
    // A minimum is found to about sqrt(epsilon) radians at worst: closer, the cost changes by less
    // than its rounding and the solver stops (here quaternion_manifold ends 8e-13 rad from the
    // closed form after 17 iterations, ceres::QuaternionManifold 1.6e-9 rad after 8: the trust
    // region measures steps in each manifold's own tangent, so the paths differ).
    const quaternion<double> closed_form = quat::align_vectors(targets, sources).rotation;
    INFO("angles to the closed form: " << quat::angle_between(solutions[0], closed_form) << ", "
                                       << quat::angle_between(solutions[1], closed_form));
    CHECK(quat::angle_between(solutions[0], solutions[1]) <= 1e-8);
    CHECK(std::abs(final_costs[0] - final_costs[1]) <= 1e-12 * final_costs[0]);
    // The minimum of sum |R a - b|^2 is Wahba's, which align_vectors solves in closed form.
    CHECK(quat::angle_between(solutions[0], closed_form) <= 1e-8);
    CHECK(quat::angle_between(solutions[1], closed_form) <= 1e-8);
    CHECK(quat::angle_between(solutions[0], truth) <= 0.05);
}

TEST_CASE("A pose solved on pose_manifold matches the closed-form point registration",
          "[interop][ceres]") {
    quat::test::random_rotations random;
    const dual_quaternion<double> truth = random.rigid_motion<double>(2.0);
    std::vector<vec3<double>> sources, targets;
    for (int i = 0; i < 30; ++i) {
        const vec3<double> p = random.vector<double>(1.0);
        sources.push_back(p);
        targets.push_back(quat::transform(truth, p) + random.vector<double>(0.01));
    }
    double pose[7] = {1, 0, 0, 0, 0, 0, 0};
    ceres::Problem problem;
    for (std::size_t i = 0; i < sources.size(); ++i)
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<point_residual, 3, 7>(
                                     new point_residual{sources[i], targets[i]}),
                                 nullptr, pose);
    problem.SetManifold(pose, new quat::pose_manifold);
    ceres::Solver::Summary summary;
    ceres::Solve(quiet_options(), &problem, &summary);
    CHECK(summary.IsSolutionUsable());
    const dual_quaternion<double> solved = quat::pose_from_parameters(pose);
    const quat::point_alignment<double> kabsch = quat::align_points(targets, sources);
    CHECK(std::abs(quat::norm(solved.real) - 1) <= 1e-14);
    CHECK(quat::angle_between(solved.real, kabsch.motion.real) <= 1e-9);
    CHECK(quat::test::max_difference(quat::translation_of(solved),
                                     quat::translation_of(kabsch.motion)) <= 1e-9);
}
