// pose_graph: a 3D pose graph solved with Ceres on quat's SE(3) (quat/interop/ceres.hpp). A vehicle
// spirals over a sphere (300 poses) measuring its motion from pose to pose (odometry) and, once a
// lap, its pose relative to the one a lap earlier (loop closures), all with noise
// (tools/pose_graph_data.py). Chaining the odometry drifts; a least-squares fit of every
// measurement on SE(3) pulls the trajectory back. Solved twice: with analytic Jacobians from
// quat::se3 and with automatic differentiation (ceres::Jet through the same quat functions).
// Run: example_pose_graph [output directory] [data directory]
//   reads  <data>/pose_graph.g2o, <data>/pose_graph_truth.g2o (default data: examples/data)
//   writes <output>/pose_graph.svg, <output>/pose_graph_optimized.g2o
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/problem.h>
#include <ceres/sized_cost_function.h>
#include <ceres/solver.h>
#include <quat/interop/ceres.hpp>
#include <quat/lie/se3.hpp>
#include <quat/quat.hpp>

#include "check.hpp"
#include "svg.hpp"

using namespace quat;

namespace {

/// One measurement: the pose of j seen from i, z = X_i^-1 X_j, with the information matrix (inverse
/// covariance) of the error log(z^-1 X_i^-1 X_j), a twist, linear part first. That is how
/// tools/pose_graph_data.py writes it and how Ceres's pose_graph_3d example reads g2o files; g2o's
/// own EDGE_SE3:QUAT weighs the quaternion's vector part (half the rotation vector) instead, so
/// its rotation block is 4 times this one.
struct edge {
    int i, j;
    dual_quaternion<double> z;
    matrix6<double> information;
};

struct graph {
    std::map<int, dual_quaternion<double>> vertices;
    std::vector<edge> edges;
};

/// g2o writes x, y, z, qx, qy, qz, qw: the quaternion's scalar LAST. Reads those seven numbers as
/// a unit dual quaternion (normalized: the file keeps 12 digits).
dual_quaternion<double> read_g2o_pose(std::istream& in) {
    double t[3], q[4];
    in >> t[0] >> t[1] >> t[2] >> q[0] >> q[1] >> q[2] >> q[3];
    return to_dual_quaternion(normalize(quaternion<double>{q[3], q[0], q[1], q[2]}),
                              vec3<double>{t[0], t[1], t[2]});
}

void write_g2o_pose(std::ostream& out, const dual_quaternion<double>& x) {
    const quaternion<double> q = x.real;
    const vec3<double> t = translation_of(x);
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "%.9f %.9f %.9f %.12f %.12f %.12f %.12f", t.x, t.y, t.z,
                  q.x, q.y, q.z, q.w);
    out << buffer;
}

/// Reads VERTEX_SE3:QUAT and EDGE_SE3:QUAT lines (others are skipped); false if the file cannot be
/// read or a line is malformed.
bool read_g2o(const std::string& path, graph& g) {
    std::ifstream file(path);
    if (!file) return false;
    std::string line;
    while (std::getline(file, line)) {
        std::istringstream in(line);
        std::string tag;
        if (!(in >> tag)) continue;  // a blank line
        if (tag == "VERTEX_SE3:QUAT") {
            int id = 0;
            in >> id;
            g.vertices[id] = read_g2o_pose(in);
        } else if (tag == "EDGE_SE3:QUAT") {
            edge e{};
            in >> e.i >> e.j;
            e.z = read_g2o_pose(in);
            for (int r = 0; r < 6; ++r)
                for (int c = r; c < 6; ++c) {
                    in >> e.information(r, c);
                    e.information(c, r) = e.information(r, c);
                }
            g.edges.push_back(e);
        }
        if (!in) return false;
    }
    return true;
}

bool write_g2o(const std::string& path, const graph& g) {
    std::ofstream out(path);
    out.precision(10);
    for (const auto& [id, x] : g.vertices) {
        out << "VERTEX_SE3:QUAT " << id << ' ';
        write_g2o_pose(out, x);
        out << '\n';
    }
    for (const edge& e : g.edges) {
        out << "EDGE_SE3:QUAT " << e.i << ' ' << e.j << ' ';
        write_g2o_pose(out, e.z);
        for (int r = 0; r < 6; ++r)
            for (int c = r; c < 6; ++c) out << ' ' << e.information(r, c);
        out << '\n';
    }
    return static_cast<bool>(out);
}

/// The upper-triangular U with U^T U = a (a symmetric positive definite): the residual U e has
/// the squared norm e^T a e.
matrix6<double> square_root(const matrix6<double>& a) {
    matrix6<double> u = matrix6<double>::zero();
    for (int r = 0; r < 6; ++r) {
        double d = a(r, r);
        for (int k = 0; k < r; ++k) d -= u(k, r) * u(k, r);
        u(r, r) = std::sqrt(d);
        for (int c = r + 1; c < 6; ++c) {
            double s = a(r, c);
            for (int k = 0; k < r; ++k) s -= u(k, r) * u(k, c);
            u(r, c) = s / u(r, r);
        }
    }
    return u;
}

/// (a) Analytic: r = U log(z^-1 X_i^-1 X_j) with its 6x6 tangent Jacobians from quat::se3, turned
/// into the 6x7 ambient ones Ceres asks for by pose_manifold's MinusJacobian (Ceres multiplies them
/// by PlusJacobian, and MinusJacobian * PlusJacobian = I).
class relative_pose_cost final : public ceres::SizedCostFunction<6, 7, 7> {
public:
    explicit relative_pose_cost(const edge& e)
        : z_inverse_(inverse(e.z)), sqrt_information_(square_root(e.information)) {}

    bool Evaluate(double const* const* parameters, double* residuals,
                  double** jacobians) const override {
        const dual_quaternion<double> xi = pose_from_parameters(parameters[0]);
        const dual_quaternion<double> xj = pose_from_parameters(parameters[1]);
        // Jacobians only when Ceres asks (it evaluates residuals alone to try a step).
        const bool derive = jacobians != nullptr;
        matrix6<double> d_xi, d_xj, d_log;
        const dual_quaternion<double> seen =
            se3::between(xi, xj, derive ? &d_xi : nullptr, derive ? &d_xj : nullptr);
        // z^-1 seen: its right Jacobian with respect to seen is the identity.
        const se3::twist<double> error = se3::log(z_inverse_ * seen, derive ? &d_log : nullptr);
        const matrix<double, 6, 1> r = sqrt_information_ * se3::to_vector(error);
        for (int k = 0; k < 6; ++k) residuals[k] = r(k, 0);
        if (!derive) return true;
        const matrix6<double> weighted_log = sqrt_information_ * d_log;
        const matrix6<double>* tangent[2] = {&d_xi, &d_xj};
        for (int b = 0; b < 2; ++b) {
            if (jacobians[b] == nullptr) continue;
            const matrix6<double> j = weighted_log * *tangent[b];
            double minus[6 * 7];
            (void)manifold_.MinusJacobian(parameters[b], minus);
            for (int row = 0; row < 6; ++row)
                for (int col = 0; col < 7; ++col) {
                    double sum = 0;
                    for (int k = 0; k < 6; ++k) sum += j(row, k) * minus[k * 7 + col];
                    jacobians[b][row * 7 + col] = sum;
                }
        }
        return true;
    }

private:
    dual_quaternion<double> z_inverse_;
    matrix6<double> sqrt_information_;
    pose_manifold manifold_;
};

/// (b) Automatic differentiation: the same residual, templated on the scalar, through the same quat
/// functions; Ceres evaluates it with ceres::Jet.
struct relative_pose_functor {
    dual_quaternion<double> z_inverse;
    matrix6<double> sqrt_information;

    template <class T>
    bool operator()(const T* pose_i, const T* pose_j, T* residuals) const {
        const dual_quaternion<T> seen =
            se3::between(pose_from_parameters(pose_i), pose_from_parameters(pose_j));
        const se3::twist<T> error = se3::log(dual_quaternion<T>(z_inverse) * seen);
        const matrix<T, 6, 1> e = se3::to_vector(error);
        for (int row = 0; row < 6; ++row) {
            T sum = T(0);
            for (int k = row; k < 6; ++k) sum += sqrt_information(row, k) * e(k, 0);
            residuals[row] = sum;
        }
        return true;
    }
};

struct solve_result {
    std::vector<double> poses;  // 7 numbers a pose
    double initial_cost, final_cost, seconds, evaluation_seconds;
    int iterations;
    std::string termination;
};

solve_result solve(const graph& g, const std::vector<double>& initial, bool analytic) {
    solve_result result{initial, 0, 0, 0, 0, 0, ""};
    ceres::Problem::Options problem_options;
    problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    pose_manifold manifold;
    for (const edge& e : g.edges) {
        ceres::CostFunction* cost =
            analytic ? static_cast<ceres::CostFunction*>(new relative_pose_cost(e))
                     : new ceres::AutoDiffCostFunction<relative_pose_functor, 6, 7, 7>(
                           new relative_pose_functor{inverse(e.z), square_root(e.information)});
        problem.AddResidualBlock(cost, nullptr, &result.poses[static_cast<std::size_t>(7 * e.i)],
                                 &result.poses[static_cast<std::size_t>(7 * e.j)]);
    }
    const int count = static_cast<int>(initial.size() / 7);
    for (int k = 0; k < count; ++k)
        problem.SetManifold(&result.poses[static_cast<std::size_t>(7 * k)], &manifold);
    // The first pose anchors the graph (the measurements fix only relative poses).
    problem.SetParameterBlockConstant(result.poses.data());

    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.num_threads = 1;  // deterministic: the same steps on every run
    options.max_num_iterations = 100;
    options.function_tolerance = 1e-12;
    options.gradient_tolerance = 1e-12;
    options.parameter_tolerance = 1e-12;
    ceres::Solver::Summary summary;
    const auto start = std::chrono::steady_clock::now();
    ceres::Solve(options, &problem, &summary);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.initial_cost = summary.initial_cost;
    result.final_cost = summary.final_cost;
    result.evaluation_seconds =
        summary.residual_evaluation_time_in_seconds + summary.jacobian_evaluation_time_in_seconds;
    result.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
    result.termination = ceres::TerminationTypeToString(summary.termination_type);
    return result;
}

dual_quaternion<double> pose_at(const std::vector<double>& poses, int k) {
    return pose_from_parameters(&poses[static_cast<std::size_t>(7 * k)]);
}

struct trajectory_error {
    double position_rms, rotation_rms_degrees;
};

/// RMS errors against the truth after moving the estimate so that its first pose is the true one.
trajectory_error error_of(const std::vector<double>& poses,
                          const std::vector<dual_quaternion<double>>& truth) {
    const dual_quaternion<double> align = truth[0] * inverse(pose_at(poses, 0));
    double p = 0, r = 0;
    for (std::size_t k = 0; k < truth.size(); ++k) {
        const dual_quaternion<double> x = align * pose_at(poses, static_cast<int>(k));
        p += squared_norm(translation_of(x) - translation_of(truth[k]));
        const double a = angle_between(x.real, truth[k].real);
        r += a * a;
    }
    const double n = static_cast<double>(truth.size());
    return {std::sqrt(p / n), std::sqrt(r / n) * 180 / numbers::pi};
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out_dir = argc > 1 ? std::string(argv[1]) : std::string(".");
    const std::string data_dir = argc > 2 ? std::string(argv[2]) : std::string("examples/data");
    std::printf("pose_graph: 3D pose-graph optimization with Ceres on quat's SE(3)\n");

    graph g, truth_graph;
    if (!read_g2o(data_dir + "/pose_graph.g2o", g) ||
        !read_g2o(data_dir + "/pose_graph_truth.g2o", truth_graph)) {
        std::printf("  cannot read %s/pose_graph.g2o and pose_graph_truth.g2o\n", data_dir.c_str());
        return 1;
    }
    const int count = static_cast<int>(g.vertices.size());
    std::vector<dual_quaternion<double>> truth;
    for (const auto& [id, x] : truth_graph.vertices) truth.push_back(x);
    int odometry = 0;
    for (const edge& e : g.edges) odometry += e.j == e.i + 1 ? 1 : 0;
    std::printf("  %d poses, %d odometry edges, %d loop closures\n", count, odometry,
                static_cast<int>(g.edges.size()) - odometry);
    expect(count == static_cast<int>(truth.size()) && count > 1 && g.vertices.begin()->first == 0 &&
               g.vertices.rbegin()->first == count - 1,
           "poses 0 .. n-1, as many as the true ones");

    // The initial estimate: the first pose, then the odometry chained, X_(i+1) = X_i z.
    std::vector<dual_quaternion<double>> chained(static_cast<std::size_t>(count));
    chained[0] = g.vertices.at(0);
    std::map<int, const edge*> odometry_from;
    for (const edge& e : g.edges)
        if (e.j == e.i + 1) odometry_from[e.i] = &e;
    for (int k = 1; k < count; ++k)
        chained[static_cast<std::size_t>(k)] =
            normalize(chained[static_cast<std::size_t>(k - 1)] * odometry_from.at(k - 1)->z);
    std::vector<double> initial(static_cast<std::size_t>(7 * count));
    for (int k = 0; k < count; ++k)
        write_parameters(chained[static_cast<std::size_t>(k)],
                         &initial[static_cast<std::size_t>(7 * k)]);

    const trajectory_error before = error_of(initial, truth);
    const solve_result analytic = solve(g, initial, true);
    const solve_result autodiff = solve(g, initial, false);
    const trajectory_error after_analytic = error_of(analytic.poses, truth);
    const trajectory_error after_autodiff = error_of(autodiff.poses, truth);

    // Times vary from run to run (and are not drawn): the whole solve, and the part spent
    // evaluating residuals and Jacobians, where the two variants differ.
    std::printf("  %-22s %11s %11s %10s %11s %5s %8s %8s\n", "", "cost before", "cost after",
                "RMS pos m", "RMS rot deg", "iter", "solve s", "eval s");
    std::printf("  %-22s %11s %11s %10.4f %11.4f\n", "odometry chained", "", "",
                before.position_rms, before.rotation_rms_degrees);
    const auto row = [](const char* name, const solve_result& s, const trajectory_error& e) {
        std::printf("  %-22s %11.1f %11.3f %10.4f %11.4f %5d %8.3f %8.3f  %s\n", name,
                    s.initial_cost, s.final_cost, e.position_rms, e.rotation_rms_degrees,
                    s.iterations, s.seconds, s.evaluation_seconds, s.termination.c_str());
    };
    row("analytic Jacobians", analytic, after_analytic);
    row("autodiff (ceres::Jet)", autodiff, after_autodiff);

    // The two solutions, pose by pose.
    double position_gap = 0, rotation_gap = 0;
    for (int k = 0; k < count; ++k) {
        const dual_quaternion<double> a = pose_at(analytic.poses, k),
                                      b = pose_at(autodiff.poses, k);
        position_gap = std::max(position_gap, norm(translation_of(a) - translation_of(b)));
        rotation_gap = std::max(rotation_gap, angle_between(a.real, b.real));
    }
    std::printf("  analytic vs autodiff: largest difference %.1e m, %.1e rad\n", position_gap,
                rotation_gap);

    expect(analytic.final_cost < analytic.initial_cost / 100,
           "the solve lowers the cost a hundredfold at least");
    expect(std::abs(analytic.initial_cost - autodiff.initial_cost) <= 1e-12 * analytic.initial_cost,
           "both variants evaluate the same initial cost");
    expect(std::abs(analytic.final_cost - autodiff.final_cost) <= 1e-9 * analytic.final_cost,
           "both variants reach the same final cost");
    expect(position_gap < 1e-9 && rotation_gap < 1e-10,
           "both variants reach the same poses (within 1e-9 m and 1e-10 rad)");
    expect(after_analytic.position_rms < before.position_rms / 10,
           "the optimized trajectory is ten times closer to the truth than the chained odometry");
    expect(after_analytic.rotation_rms_degrees < before.rotation_rms_degrees / 4,
           "and its rotations four times closer");
    // The noise the data were drawn with, seen in the costs (chi-square statistics): at the true
    // poses the cost is about half the number of residuals, 6 * edges / 2; at the optimum, about
    // half the residuals less the unknowns, 6 * (edges - (poses - 1)) / 2.
    std::vector<double> true_parameters(static_cast<std::size_t>(7 * count));
    for (int k = 0; k < count; ++k)
        write_parameters(truth[static_cast<std::size_t>(k)],
                         &true_parameters[static_cast<std::size_t>(7 * k)]);
    double true_cost = 0;
    for (const edge& e : g.edges) {
        double r[6];
        (void)relative_pose_functor{inverse(e.z), square_root(e.information)}(
            &true_parameters[static_cast<std::size_t>(7 * e.i)],
            &true_parameters[static_cast<std::size_t>(7 * e.j)], r);
        for (const double v : r) true_cost += v * v / 2;
    }
    const double edges = static_cast<double>(g.edges.size());
    const double expected_true = 3 * edges, expected_final = 3 * (edges - (count - 1));
    std::printf(
        "  cost at the true poses %.1f (expected about %.0f), at the optimum %.1f "
        "(expected about %.0f)\n",
        true_cost, expected_true, analytic.final_cost, expected_final);
    expect(std::abs(true_cost - expected_true) < 0.1 * expected_true,
           "the cost at the true poses is that of the stated noise (within 10%)");
    expect(std::abs(analytic.final_cost - expected_final) < 0.25 * expected_final,
           "the final cost is that of the stated noise, less the unknowns fitted (within 25%)");
    expect(analytic.final_cost < true_cost, "the optimum fits the data better than the truth does");

    graph optimized = g;
    for (int k = 0; k < count; ++k) optimized.vertices[k] = pose_at(analytic.poses, k);
    expect(write_g2o(out_dir + "/pose_graph_optimized.g2o", optimized),
           "pose_graph_optimized.g2o written");

    // Top view (x, y): truth, chained odometry, optimized.
    svg::document doc(960, 520);
    doc.text({480, 28}, "Pose graph on SE(3): 300 poses, 299 odometry edges, 120 loop closures", 17,
             "middle", "#222", true);
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    const auto extend = [&](const vec3<double>& p) {
        lo_x = std::min(lo_x, p.x);
        hi_x = std::max(hi_x, p.x);
        lo_y = std::min(lo_y, p.y);
        hi_y = std::max(hi_y, p.y);
    };
    for (int k = 0; k < count; ++k) {
        extend(translation_of(truth[static_cast<std::size_t>(k)]));
        extend(translation_of(chained[static_cast<std::size_t>(k)]));
    }
    const double scale = std::min(440.0 / (hi_x - lo_x), 400.0 / (hi_y - lo_y));
    const auto panel = [&](double left, const std::string& title,
                           const std::vector<dual_quaternion<double>>& estimate,
                           const svg::style& look) {
        const auto map = [&](const vec3<double>& p) {
            return svg::point{left + (p.x - lo_x) * scale, 475 - (p.y - lo_y) * scale};
        };
        std::vector<svg::point> t, e;
        for (int k = 0; k < count; ++k) {
            t.push_back(map(translation_of(truth[static_cast<std::size_t>(k)])));
            e.push_back(map(translation_of(estimate[static_cast<std::size_t>(k)])));
        }
        doc.text({left + 220, 56}, title, 14, "middle", "#222", true);
        doc.polyline(t, {"#999", 3.0});
        // The loop closures, between the estimated poses they join.
        for (const edge& c : g.edges)
            if (c.j != c.i + 1)
                doc.line(e[static_cast<std::size_t>(c.i)], e[static_cast<std::size_t>(c.j)],
                         {"#2ca02c", 0.8, "none", 0.7});
        doc.polyline(e, look);
    };
    std::vector<dual_quaternion<double>> solved(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k)
        solved[static_cast<std::size_t>(k)] = pose_at(analytic.poses, k);
    panel(30, "odometry chained (initial)", chained, {"#d62728", 1.2});
    panel(500, "optimized (Ceres, pose_manifold)", solved, {"#1f77b4", 1.2});
    char caption[200];
    std::snprintf(caption, sizeof caption,
                  "top view; grey: truth, green: loop closures. RMS position error %.2f m before, "
                  "%.3f m after",
                  before.position_rms, after_analytic.position_rms);
    doc.text({480, 508}, caption, 12, "middle", "#444");
    const std::string svg_path = out_dir + "/pose_graph.svg";
    expect(doc.save(svg_path), "pose_graph.svg written");
    std::printf("  wrote %s\n", svg_path.c_str());
    return example::failures() == 0 ? 0 : 1;
}
