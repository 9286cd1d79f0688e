// lie/relative_pose.hpp and interop/ceres.hpp's relative_pose_cost: the residuals and analytic
// Jacobians of both relative-pose errors against ceres::Jet automatic differentiation of the same
// residual. The SO(3) x R^3 reference is written here from its formula with ceres/rotation.h, not
// with quat; the SE(3) reference is Jet through quat's se3::between and se3::log (whose Jet
// derivatives tests/test_se3.cpp checks). Ambient Jacobians are compared along the unit sphere
// (times a manifold's PlusJacobian): there the derivative is unique, while its component along the
// quaternion itself depends on how a formula treats a quaternion that is not unit.
// QUAT_LIE_REPORT=1 in the environment prints the worst differences.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/product_manifold.h>
#include <ceres/rotation.h>
#include <ceres/solver.h>
#include <quat/interop/ceres.hpp>
#include <quat/lie/relative_pose.hpp>
#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"

using quat::dual_quaternion;
using quat::matrix6;
using quat::quaternion;
using quat::vec3;

namespace {

/// Jet derivatives agree with the analytic ones to this, relative to the largest entry.
constexpr double jacobian_tolerance = 1e-12;

/// Ceres's pose_graph_3d error from its formula, w, x, y, z quaternions (ceres/rotation.h's
/// order): (R_a^T (p_b - p_a) - p_ab, 2 vec(q_ab (q_a^* q_b)^*)), weighted by s (row-major).
struct split_reference {
    double measured_q[4], measured_p[3], s[36];

    template <class T>
    bool operator()(const T* a, const T* b, T* residuals) const {
        const T a_inverse[4] = {a[0], -a[1], -a[2], -a[3]};
        T estimated[4], moved[3], seen[3], d[4];
        ceres::QuaternionProduct(a_inverse, b, estimated);
        for (int k = 0; k < 3; ++k) moved[k] = b[4 + k] - a[4 + k];
        ceres::UnitQuaternionRotatePoint(a_inverse, moved, seen);
        const T estimated_inverse[4] = {estimated[0], -estimated[1], -estimated[2], -estimated[3]};
        const T measured[4] = {T(measured_q[0]), T(measured_q[1]), T(measured_q[2]),
                               T(measured_q[3])};
        ceres::QuaternionProduct(measured, estimated_inverse, d);
        const T e[6] = {seen[0] - measured_p[0],
                        seen[1] - measured_p[1],
                        seen[2] - measured_p[2],
                        T(2) * d[1],
                        T(2) * d[2],
                        T(2) * d[3]};
        for (int r = 0; r < 6; ++r) {
            residuals[r] = T(0);
            for (int c = 0; c < 6; ++c) residuals[r] += s[r * 6 + c] * e[c];
        }
        return true;
    }
};

/// log(Z^-1 A^-1 B) by Jet through quat's SE(3) functions, weighted by s.
struct log_reference {
    dual_quaternion<double> measured;
    double s[36];

    template <class T>
    bool operator()(const T* a, const T* b, T* residuals) const {
        const dual_quaternion<T> d =
            quat::se3::between(quat::pose_from_parameters(a), quat::pose_from_parameters(b));
        const quat::matrix<T, 6, 1> e =
            quat::se3::to_vector(quat::se3::minus(d, dual_quaternion<T>(measured)));
        for (int r = 0; r < 6; ++r) {
            residuals[r] = T(0);
            for (int c = 0; c < 6; ++c) residuals[r] += s[r * 6 + c] * e(c, 0);
        }
        return true;
    }
};

/// Prints a measured worst difference under QUAT_LIE_REPORT=1.
void report(const char* name, double value) {
    if (std::getenv("QUAT_LIE_REPORT") != nullptr) std::printf("  %-52s %.3g\n", name, value);
}

/// A random symmetric positive definite 6x6 information matrix with off-diagonal terms.
matrix6<double> random_information(quat::test::random_rotations& random) {
    matrix6<double> g{}, information{};
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) g(r, c) = random.uniform<double>(-1, 1);
    information = transpose(g) * g;
    for (int k = 0; k < 6; ++k) information(k, k) += 0.5;
    return information;
}

/// The 6x6 product (6x7 row-major j) times (7x6 row-major p).
std::vector<double> times(const double* j, const double* p) {
    std::vector<double> out(36, 0.0);
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c)
            for (int k = 0; k < 7; ++k)
                out[static_cast<std::size_t>(r * 6 + c)] += j[r * 7 + k] * p[k * 6 + c];
    return out;
}

/// max |a - b| / max |b| over two 6x6 matrices.
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0, scale = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
        worst = std::max(worst, std::abs(a[k] - b[k]));
        scale = std::max(scale, std::abs(b[k]));
    }
    return worst / scale;
}

/// A test case: two poses and a measurement, close to their relative pose or not.
struct edge_case {
    std::vector<double> a, b;
    dual_quaternion<double> measured;
};

std::vector<edge_case> edge_cases() {
    quat::test::random_rotations random(quat::test::seed + 7);
    std::vector<edge_case> cases;
    for (int k = 0; k < 60; ++k) {
        edge_case c{std::vector<double>(7), std::vector<double>(7), {}};
        dual_quaternion<double> a = random.rigid_motion<double>(3.0);
        dual_quaternion<double> b = random.rigid_motion<double>(3.0);
        if (k % 3 == 0) b = a;   // coincident poses: the identity error
        if (k % 4 == 1) b = -b;  // the same motion with the other quaternion sign
        const dual_quaternion<double> between = quat::se3::between(a, b);
        // Measurements: exact, slightly off, or unrelated (errors up to nearly pi).
        if (k % 5 == 0) {
            c.measured = between;
        } else if (k % 5 < 3) {
            const quat::se3::twist<double> noise{random.vector<double>(0.05),
                                                 random.vector<double>(0.05)};
            c.measured = quat::se3::plus(between, noise);
        } else {
            c.measured = random.rigid_motion<double>(3.0);
        }
        quat::write_parameters(a.real, c.a.data());
        quat::write_parameters(quat::translation_of(a), c.a.data() + 4);
        quat::write_parameters(b.real, c.b.data());
        quat::write_parameters(quat::translation_of(b), c.b.data() + 4);
        cases.push_back(c);
    }
    return cases;
}

/// Runs the analytic cost and the autodiff reference on every case; returns the worst relative
/// differences of the residuals and of the Jacobians along the sphere (times pose_manifold's and
/// times Ceres's split product manifold's PlusJacobian), and of the Jacobian along the quaternion.
struct comparison {
    double residual = 0, along_pose_manifold = 0, along_ceres_manifold = 0, along_quaternion = 0;
};

template <class Reference, class Make>
comparison compare(quat::relative_pose_form form, Make make_reference) {
    comparison worst;
    quat::test::random_rotations random(quat::test::seed + 11);
    const quat::pose_manifold pose;
    const ceres::ProductManifold<ceres::QuaternionManifold, ceres::EuclideanManifold<3>> split;
    for (const edge_case& c : edge_cases()) {
        const matrix6<double> s = *quat::information_square_root(random_information(random));
        Reference* functor = new Reference(make_reference(c.measured, s));
        const ceres::AutoDiffCostFunction<Reference, 6, 7, 7> reference(functor);
        const quat::relative_pose_cost analytic(form, c.measured, s);
        const double* parameters[2] = {c.a.data(), c.b.data()};
        double r_analytic[6], r_reference[6], j_analytic[2][42], j_reference[2][42];
        double* jacobians_analytic[2] = {j_analytic[0], j_analytic[1]};
        double* jacobians_reference[2] = {j_reference[0], j_reference[1]};
        REQUIRE(analytic.Evaluate(parameters, r_analytic, jacobians_analytic));
        REQUIRE(reference.Evaluate(parameters, r_reference, jacobians_reference));
        double r_scale = 1;
        for (double v : r_reference) r_scale = std::max(r_scale, std::abs(v));
        for (int k = 0; k < 6; ++k)
            worst.residual =
                std::max(worst.residual, std::abs(r_analytic[k] - r_reference[k]) / r_scale);
        for (int block = 0; block < 2; ++block) {
            double p[42], q[42];
            REQUIRE(pose.PlusJacobian(parameters[block], p));
            REQUIRE(split.PlusJacobian(parameters[block], q));
            worst.along_pose_manifold = std::max(
                worst.along_pose_manifold,
                relative_difference(times(j_analytic[block], p), times(j_reference[block], p)));
            worst.along_ceres_manifold = std::max(
                worst.along_ceres_manifold,
                relative_difference(times(j_analytic[block], q), times(j_reference[block], q)));
            // Along the quaternion itself (a change of its norm) the analytic Jacobian is zero.
            for (int r = 0; r < 6; ++r) {
                double along = 0, scale = 0;
                for (int k = 0; k < 4; ++k) {
                    along += j_analytic[block][r * 7 + k] * parameters[block][k];
                    scale = std::max(scale, std::abs(j_analytic[block][r * 7 + k]));
                }
                worst.along_quaternion = std::max(worst.along_quaternion, std::abs(along) / scale);
            }
        }
    }
    return worst;
}

/// Reports the worst differences from Jet autodiff and holds them to the tolerances.
void check(const char* form, const comparison& worst) {
    const std::string f(form);
    report((f + ": residual").c_str(), worst.residual);
    report((f + ": Jacobian times pose_manifold PlusJacobian").c_str(), worst.along_pose_manifold);
    report((f + ": Jacobian times Ceres split PlusJacobian").c_str(), worst.along_ceres_manifold);
    report((f + ": Jacobian along the quaternion").c_str(), worst.along_quaternion);
    CAPTURE(worst.residual, worst.along_pose_manifold, worst.along_ceres_manifold,
            worst.along_quaternion);
    CHECK(worst.residual < 1e-14);
    CHECK(worst.along_pose_manifold < jacobian_tolerance);
    CHECK(worst.along_ceres_manifold < jacobian_tolerance);
    CHECK(worst.along_quaternion < 1e-15);
}

}  // namespace

TEST_CASE("relative_pose_cost, SO(3) x R^3: Ceres's pose_graph_3d error, Jacobians as Jet autodiff",
          "[interop][ceres][relative_pose]") {
    const comparison worst =
        compare<split_reference>(quat::relative_pose_form::so3xr3,
                                 [](const dual_quaternion<double>& z, const matrix6<double>& s) {
                                     split_reference r{};
                                     quat::write_parameters(z.real, r.measured_q);
                                     quat::write_parameters(quat::translation_of(z), r.measured_p);
                                     for (int k = 0; k < 36; ++k) r.s[k] = s(k / 6, k % 6);
                                     return r;
                                 });
    check("so3xr3", worst);
}

TEST_CASE("relative_pose_cost, SE(3) log: Jacobians as Jet autodiff",
          "[interop][ceres][relative_pose]") {
    const comparison worst =
        compare<log_reference>(quat::relative_pose_form::se3,
                               [](const dual_quaternion<double>& z, const matrix6<double>& s) {
                                   log_reference r{z, {}};
                                   for (int k = 0; k < 36; ++k) r.s[k] = s(k / 6, k % 6);
                                   return r;
                               });
    check("se3", worst);
}

TEST_CASE("relative_pose_error: the tangent Jacobians are those of the pose manifold's tangent",
          "[lie][relative_pose]") {
    // d e(A exp(tau), B) / d tau by Jet through se3::plus, for both forms: the functions' own
    // Jacobians, without the ambient chain.
    quat::test::random_rotations random(quat::test::seed + 13);
    using jet = ceres::Jet<double, 6>;
    double worst[2] = {0, 0};
    for (int k = 0; k < 40; ++k) {
        const dual_quaternion<double> a = random.rigid_motion<double>(3.0);
        const dual_quaternion<double> b = random.rigid_motion<double>(3.0);
        const dual_quaternion<double> z =
            k % 2 == 0 ? quat::se3::plus(quat::se3::between(a, b),
                                         quat::se3::twist<double>{random.vector<double>(0.1),
                                                                  random.vector<double>(0.1)})
                       : random.rigid_motion<double>(3.0);
        for (int form = 0; form < 2; ++form) {
            for (int which = 0; which < 2; ++which) {
                matrix6<double> analytic{};
                (void)(form == 0 ? quat::so3xr3::relative_pose_error(
                                       a, b, z, which == 0 ? &analytic : nullptr,
                                       which == 1 ? &analytic : nullptr)
                                 : quat::se3::relative_pose_error(
                                       a, b, z, which == 0 ? &analytic : nullptr,
                                       which == 1 ? &analytic : nullptr));
                quat::se3::twist<jet> tau{};
                tau.linear = {jet(0.0, 0), jet(0.0, 1), jet(0.0, 2)};
                tau.angular = {jet(0.0, 3), jet(0.0, 4), jet(0.0, 5)};
                dual_quaternion<jet> ja(a), jb(b);
                const dual_quaternion<jet> jz(z);
                if (which == 0) ja = quat::se3::plus(ja, tau);
                else jb = quat::se3::plus(jb, tau);
                const quat::matrix<jet, 6, 1> e =
                    form == 0 ? quat::so3xr3::relative_pose_error(ja, jb, jz)
                              : quat::se3::relative_pose_error(ja, jb, jz);
                double difference = 0, scale = 0;
                for (int r = 0; r < 6; ++r)
                    for (int c = 0; c < 6; ++c) {
                        difference = std::max(difference, std::abs(e(r, 0).v[c] - analytic(r, c)));
                        scale = std::max(scale, std::abs(analytic(r, c)));
                    }
                worst[form] = std::max(worst[form], difference / scale);
            }
        }
    }
    report("so3xr3: tangent Jacobians vs Jet through se3::plus", worst[0]);
    report("se3: tangent Jacobians vs Jet through se3::plus", worst[1]);
    CAPTURE(worst[0], worst[1]);
    CHECK(worst[0] < jacobian_tolerance);
    CHECK(worst[1] < jacobian_tolerance);
}

TEST_CASE("information_square_root: U^T U is the information; empty unless positive definite",
          "[interop][ceres][relative_pose]") {
    quat::test::random_rotations random(quat::test::seed + 17);
    for (int k = 0; k < 20; ++k) {
        const matrix6<double> information = random_information(random);
        const std::optional<matrix6<double>> u = quat::information_square_root(information);
        REQUIRE(u.has_value());
        const matrix6<double> back = transpose(*u) * *u;
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c) {
                CHECK(std::abs(back(r, c) - information(r, c)) <= 1e-14 * 8);
                if (c < r) CHECK((*u)(r, c) == 0);
            }
    }
    matrix6<double> singular = matrix6<double>::identity();
    singular(3, 3) = 0;
    CHECK_FALSE(quat::information_square_root(singular).has_value());
    matrix6<double> indefinite = matrix6<double>::identity();
    indefinite(0, 1) = indefinite(1, 0) = 2;
    CHECK_FALSE(quat::information_square_root(indefinite).has_value());
    matrix6<double> not_a_number = matrix6<double>::identity();
    not_a_number(2, 2) = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(quat::information_square_root(not_a_number).has_value());
}

namespace {

// docs/lie-groups.md's pose-graph example, as written there (the Markdown block is not compiled by
// docs_code_blocks, which does not link Ceres): four poses round a unit square, measured by four
// edges, solved from a rough guess.
struct square_solution {
    double poses[4][7];
    double final_cost;
};

square_solution solve_square() {
    using namespace quat;
    // Each edge: one step forward along x, then a quarter turn to the left.
    const dual_quaternion<double> step =
        to_dual_quaternion(rotation_z(numbers::pi / 2), vec3<double>{1, 0, 0});
    const matrix6<double> sqrt_information =
        *information_square_root(100.0 * matrix6<double>::identity());  // sigma 0.1

    square_solution s{};
    double(&poses)[4][7] = s.poses;  // w, x, y, z, tx, ty, tz each
    // A rough first guess: x, y and heading of each pose.
    const double guess[4][3] = {{0, 0, 0}, {1.2, 0.1, 1.3}, {0.9, 1.2, 3.4}, {-0.2, 0.8, 4.5}};
    for (int k = 0; k < 4; ++k)
        write_parameters(
            to_dual_quaternion(rotation_z(guess[k][2]), vec3<double>{guess[k][0], guess[k][1], 0}),
            poses[k]);
    ceres::Problem problem;
    for (int i = 0; i < 4; ++i)
        problem.AddResidualBlock(
            new relative_pose_cost(relative_pose_form::so3xr3, step, sqrt_information), nullptr,
            poses[i], poses[(i + 1) % 4]);
    for (auto& pose : poses) problem.SetManifold(pose, new pose_manifold);
    problem.SetParameterBlockConstant(poses[0]);  // the measurements fix only relative poses

    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    // poses[k] is step^k: at (0, 0), (1, 0), (1, 1), (0, 1), turned k quarter turns.
    s.final_cost = summary.final_cost;
    return s;
}

}  // namespace

TEST_CASE("docs/lie-groups.md's pose-graph example solves the square",
          "[interop][ceres][relative_pose]") {
    const square_solution s = solve_square();
    CHECK(s.final_cost < 1e-20);
    const double corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 4; ++k) {
        const dual_quaternion<double> x = quat::pose_from_parameters(s.poses[k]);
        const vec3<double> t = quat::translation_of(x);
        CHECK(std::abs(t.x - corners[k][0]) < 1e-9);
        CHECK(std::abs(t.y - corners[k][1]) < 1e-9);
        CHECK(std::abs(t.z) < 1e-9);
        CHECK(quat::angle_between(x.real, quat::rotation_z(k * quat::numbers::pi / 2)) < 1e-9);
    }
}

TEST_CASE("relative_pose_cost gives a non-finite residual for a NaN or infinite parameter",
          "[interop][ceres][relative_pose]") {
    const double bad[2] = {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()};
    for (const quat::relative_pose_form form :
         {quat::relative_pose_form::so3xr3, quat::relative_pose_form::se3}) {
        for (const double value : bad) {
            for (int component = 0; component < 7; ++component) {
                double a[7] = {1, 0, 0, 0, 1, 2, 3}, b[7] = {0, 1, 0, 0, -1, 0, 2};
                a[component] = value;
                const quat::relative_pose_cost cost(form, dual_quaternion<double>::identity(),
                                                    matrix6<double>::identity());
                const double* parameters[2] = {a, b};
                double r[6], ja[42], jb[42];
                double* jacobians[2] = {ja, jb};
                REQUIRE(cost.Evaluate(parameters, r, jacobians));
                bool finite = true;
                for (const double v : r) finite = finite && std::isfinite(v);
                CHECK_FALSE(finite);
            }
        }
    }
}
