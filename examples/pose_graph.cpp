// pose_graph: a 3D pose graph from a g2o file solved with Ceres on quat's ready residuals
// (quat/interop/ceres.hpp's relative_pose_cost, lie/relative_pose.hpp's errors). Every edge
// measured the pose of one vertex seen from another; the solve starts from the file's vertex
// estimates, holds the first pose (the lowest id) fixed and fits all edges, once per residual form:
//   so3xr3: Ceres's pose_graph_3d error (R_a^T (p_b - p_a) - p_ab, 2 vec(q_ab (q_a^-1 q_b)^-1));
//   se3:    the SE(3) log, log(Z^-1 A^-1 B).
// Each with quat's analytic Jacobians and, for comparison, with ceres::Jet autodiff of the same
// quat function. Solver options are those of Ceres's pose_graph_3d: SPARSE_NORMAL_CHOLESKY, at
// most 200 iterations, default tolerances, one thread.
//
// Run: example_pose_graph <output directory> <file.g2o> [options]
//   --residual so3xr3|se3|both   which error to minimize (default both)
//   --weight lower|upper         the information's square root: lower = the Cholesky factor L
//                                (information = L L^T), as Ceres's pose_graph_3d weighs (default);
//                                upper = L^T, for which |L^T e|^2 = e^T information e
//   --manifold split|pose        split: ceres::QuaternionManifold x EuclideanManifold<3>, Ceres's
//                                parameterization (default); pose: quat's pose_manifold (SE(3))
//   --start file|odometry        the initial poses: the file's vertex estimates (default), or the
//                                first pose with the edges i -> i + 1 chained (a harder start)
//   --perturb SIGMA              turn every initial pose but the first by a random rotation
//                                vector, each component Gaussian with SIGMA radians (seeded: the
//                                same turns on every run), to probe where each residual converges
//   --no-autodiff                skip the Jet variants
//   --expect-so3xr3 COST         check the so3xr3 final cost against COST (1e-5 relative)
// Writes <output>/pose_graph.svg (top view, the data set's name in the title) and
// <output>/pose_graph_optimized.g2o (the so3xr3 solution, or se3's if only it ran).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/product_manifold.h>
#include <ceres/solver.h>
#include <quat/interop/ceres.hpp>
#include <quat/lie/relative_pose.hpp>
#include <quat/quat.hpp>

#include "check.hpp"
#include "g2o.hpp"
#include "svg.hpp"

using namespace quat;

namespace {

using g2o::edge;
using g2o::graph;

/// Replaces every vertex after the first by the previous one times the measurement of the edge
/// from it (ids in order): the odometry chained. False if such an edge is missing.
bool chain_odometry(graph& g) {
    std::map<int, const edge*> from;
    for (const edge& e : g.edges)
        if (std::next(g.vertices.find(e.i)) == g.vertices.find(e.j)) from[e.i] = &e;
    for (auto it = std::next(g.vertices.begin()); it != g.vertices.end(); ++it) {
        const auto previous = std::prev(it);
        if (from.count(previous->first) == 0) return false;
        it->second = normalize(previous->second * from.at(previous->first)->measured);
    }
    return true;
}

struct options {
    std::string output, input;
    bool so3xr3 = true, se3 = true, upper = false, pose_manifold = false, autodiff = true,
         odometry = false;
    double perturb = 0;
    double expect_so3xr3 = 0;  // 0: no check
};

/// The Jet variant: the same quat function, differentiated by Ceres.
struct autodiff_residual {
    relative_pose_form form;
    dual_quaternion<double> measured;
    matrix6<double> sqrt_information;

    template <class T>
    bool operator()(const T* a, const T* b, T* residuals) const {
        const dual_quaternion<T> pa = pose_from_parameters(a), pb = pose_from_parameters(b);
        const dual_quaternion<T> z(measured);
        const matrix<T, 6, 1> e = form == relative_pose_form::so3xr3
                                      ? so3xr3::relative_pose_error(pa, pb, z)
                                      : se3::relative_pose_error(pa, pb, z);
        for (int r = 0; r < 6; ++r) {
            T sum = T(0);
            for (int c = 0; c < 6; ++c) sum += sqrt_information(r, c) * e(c, 0);
            residuals[r] = sum;
        }
        return true;
    }
};

struct solve_result {
    std::vector<double> poses;  // 7 numbers a pose, in the order of the vertex ids
    double initial_cost = 0, final_cost = 0, seconds = 0, evaluation_seconds = 0;
    int iterations = 0;
    std::string termination;
};

matrix6<double> weight_of(const edge& e, bool upper) {
    const std::optional<matrix6<double>> u = information_square_root(e.information);
    if (!u) {
        std::fprintf(stderr,
                     "an edge %d -> %d has an information matrix that is not positive definite\n",
                     e.i, e.j);
        std::exit(1);
    }
    return upper ? *u : transpose(*u);
}

solve_result solve(const graph& g, const options& o, relative_pose_form form, bool analytic) {
    solve_result result;
    std::map<int, std::size_t> index;
    for (const auto& [id, x] : g.vertices) {
        index[id] = result.poses.size();
        result.poses.resize(result.poses.size() + 7);
        write_parameters(x, &result.poses[index[id]]);
    }
    ceres::Problem::Options problem_options;
    problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    for (const edge& e : g.edges) {
        const matrix6<double> s = weight_of(e, o.upper);
        ceres::CostFunction* cost =
            analytic
                ? static_cast<ceres::CostFunction*>(new relative_pose_cost(form, e.measured, s))
                : new ceres::AutoDiffCostFunction<autodiff_residual, 6, 7, 7>(
                      new autodiff_residual{form, e.measured, s});
        problem.AddResidualBlock(cost, nullptr, &result.poses[index.at(e.i)],
                                 &result.poses[index.at(e.j)]);
    }
    pose_manifold pose;
    ceres::ProductManifold<ceres::QuaternionManifold, ceres::EuclideanManifold<3>> split;
    ceres::Manifold* manifold = o.pose_manifold ? static_cast<ceres::Manifold*>(&pose) : &split;
    for (std::size_t k = 0; k < result.poses.size(); k += 7)
        if (problem.HasParameterBlock(&result.poses[k]))
            problem.SetManifold(&result.poses[k], manifold);
    // The measurements fix only relative poses: the first pose anchors the graph.
    if (problem.HasParameterBlock(result.poses.data()))
        problem.SetParameterBlockConstant(result.poses.data());

    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.max_num_iterations = 200;
    options.num_threads = 1;
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

/// The cost (1/2 the sum of squared weighted residuals) of the given form at the poses.
double cost_at(const graph& g, const options& o, relative_pose_form form,
               const std::vector<double>& poses) {
    std::map<int, std::size_t> index;
    std::size_t next = 0;
    for (const auto& entry : g.vertices) {
        index[entry.first] = next;
        next += 7;
    }
    double cost = 0;
    for (const edge& e : g.edges) {
        const relative_pose_cost c(form, e.measured, weight_of(e, o.upper));
        const double* parameters[2] = {&poses[index.at(e.i)], &poses[index.at(e.j)]};
        double r[6];
        (void)c.Evaluate(parameters, r, nullptr);
        for (const double v : r) cost += v * v / 2;
    }
    return cost;
}

bool parse(int argc, char** argv, options& o) {
    if (argc < 3) return false;
    o.output = argv[1];
    o.input = argv[2];
    for (int k = 3; k < argc; ++k) {
        const std::string a = argv[k];
        const std::string next = k + 1 < argc ? argv[k + 1] : "";
        if (a == "--residual" && (next == "so3xr3" || next == "se3" || next == "both")) {
            o.so3xr3 = next != "se3";
            o.se3 = next != "so3xr3";
            ++k;
        } else if (a == "--weight" && (next == "lower" || next == "upper")) {
            o.upper = next == "upper";
            ++k;
        } else if (a == "--manifold" && (next == "split" || next == "pose")) {
            o.pose_manifold = next == "pose";
            ++k;
        } else if (a == "--start" && (next == "file" || next == "odometry")) {
            o.odometry = next == "odometry";
            ++k;
        } else if (a == "--perturb" && !next.empty()) {
            o.perturb = std::atof(next.c_str());
            ++k;
        } else if (a == "--no-autodiff") {
            o.autodiff = false;
        } else if (a == "--expect-so3xr3" && !next.empty()) {
            o.expect_so3xr3 = std::atof(next.c_str());
            ++k;
        } else {
            return false;
        }
    }
    return true;
}

std::string file_name(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::map<int, dual_quaternion<double>> poses_of(const graph& g, const std::vector<double>& p) {
    std::map<int, dual_quaternion<double>> out;
    std::size_t k = 0;
    for (const auto& entry : g.vertices) {
        out[entry.first] = pose_from_parameters(&p[k]);
        k += 7;
    }
    return out;
}

/// Top view (x, y) of the initial and the optimized poses, every edge a line.
bool draw(const std::string& path, const std::string& title, const graph& g,
          const std::map<int, dual_quaternion<double>>& optimized, const std::string& caption) {
    svg::document doc(960, 520);
    doc.text({480, 28}, title, 17, "middle", "#222", true);
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const auto* poses : {&g.vertices, &optimized})
        for (const auto& entry : *poses) {
            const vec3<double> p = translation_of(entry.second);
            lo_x = std::min(lo_x, p.x);
            hi_x = std::max(hi_x, p.x);
            lo_y = std::min(lo_y, p.y);
            hi_y = std::max(hi_y, p.y);
        }
    const double scale =
        std::min(440.0 / std::max(hi_x - lo_x, 1e-9), 400.0 / std::max(hi_y - lo_y, 1e-9));
    const auto panel = [&](double left, const std::string& name,
                           const std::map<int, dual_quaternion<double>>& poses,
                           const char* colour) {
        const auto map = [&](int id) {
            const vec3<double> p = translation_of(poses.at(id));
            return svg::point{left + (p.x - lo_x) * scale, 475 - (p.y - lo_y) * scale};
        };
        doc.text({left + 220, 56}, name, 14, "middle", "#222", true);
        for (const edge& e : g.edges) doc.line(map(e.i), map(e.j), {colour, 0.6, "none", 0.6});
    };
    panel(30, "initial: the file's vertex estimates", g.vertices, "#d62728");
    panel(500, "optimized", optimized, "#1f77b4");
    doc.text({480, 508}, caption, 12, "middle", "#444");
    return doc.save(path);
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    options o;
    if (!parse(argc, argv, o)) {
        std::fprintf(stderr,
                     "usage: example_pose_graph <output directory> <file.g2o> [--residual "
                     "so3xr3|se3|both] [--weight lower|upper] [--manifold split|pose] "
                     "[--no-autodiff] [--expect-so3xr3 COST]\n");
        return 2;
    }
    graph g;
    if (!g2o::read_g2o(o.input, g)) {
        std::fprintf(stderr, "cannot read %s as a g2o 3D pose graph\n", o.input.c_str());
        return 1;
    }
    if (o.odometry && !chain_odometry(g)) {
        std::fprintf(stderr, "%s: no edge i -> i + 1 for every pose to chain\n", o.input.c_str());
        return 1;
    }
    if (o.perturb > 0) {
        std::mt19937_64 engine(20190501);
        std::normal_distribution<double> gauss(0.0, o.perturb);
        for (auto it = std::next(g.vertices.begin()); it != g.vertices.end(); ++it) {
            const double x = gauss(engine), y = gauss(engine), z = gauss(engine);
            it->second =
                to_dual_quaternion(it->second.real * from_rotation_vector(vec3<double>{x, y, z}),
                                   translation_of(it->second));
        }
    }
    const std::string name = file_name(o.input);
    std::printf("pose_graph: %s, %d poses, %d edges; start %s, weight %s, manifold %s\n",
                name.c_str(), static_cast<int>(g.vertices.size()), static_cast<int>(g.edges.size()),
                o.odometry ? "odometry" : "file",
                o.upper ? "upper (L^T)" : "lower (L, as Ceres's pose_graph_3d)",
                o.pose_manifold ? "pose_manifold" : "QuaternionManifold x R^3");
    std::printf("  %-26s %13s %13s %5s %8s %8s  %s\n", "", "initial cost", "final cost", "iter",
                "solve s", "eval s", "termination");
    const auto row = [](const char* label, const solve_result& s) {
        std::printf("  %-26s %13.6f %13.7f %5d %8.3f %8.3f  %s\n", label, s.initial_cost,
                    s.final_cost, s.iterations, s.seconds, s.evaluation_seconds,
                    s.termination.c_str());
    };
    std::map<relative_pose_form, solve_result> solved;
    for (const relative_pose_form form : {relative_pose_form::so3xr3, relative_pose_form::se3}) {
        const bool split = form == relative_pose_form::so3xr3;
        if (split ? !o.so3xr3 : !o.se3) continue;
        const solve_result analytic = solve(g, o, form, true);
        row(split ? "so3xr3, analytic" : "se3 log, analytic", analytic);
        expect(analytic.final_cost < analytic.initial_cost, "the solve lowers the cost");
        if (o.autodiff) {
            const solve_result jet = solve(g, o, form, false);
            row(split ? "so3xr3, autodiff (Jet)" : "se3 log, autodiff (Jet)", jet);
            expect(
                std::abs(jet.initial_cost - analytic.initial_cost) <= 1e-12 * analytic.initial_cost,
                "analytic and autodiff Jacobians: the same initial cost");
            expect(std::abs(jet.final_cost - analytic.final_cost) <= 1e-7 * analytic.final_cost,
                   "and the same final cost (1e-7 relative)");
        }
        solved[form] = analytic;
    }
    if (o.so3xr3 && o.expect_so3xr3 > 0) {
        const double final_cost = solved[relative_pose_form::so3xr3].final_cost;
        std::printf("  so3xr3 final cost %.7f, reference %.7f: relative difference %.1e\n",
                    final_cost, o.expect_so3xr3,
                    std::abs(final_cost - o.expect_so3xr3) / o.expect_so3xr3);
        expect(std::abs(final_cost - o.expect_so3xr3) <= 1e-5 * o.expect_so3xr3,
               "the so3xr3 final cost is the reference's (Ceres's pose_graph_3d), 1e-5 relative");
    }
    if (o.so3xr3 && o.se3) {
        // The two minima: each solution under the other's cost, and how far apart the poses are.
        const std::vector<double>& a = solved[relative_pose_form::so3xr3].poses;
        const std::vector<double>& b = solved[relative_pose_form::se3].poses;
        double position = 0, angle = 0;
        for (std::size_t k = 0; k < a.size(); k += 7) {
            const dual_quaternion<double> x = pose_from_parameters(&a[k]),
                                          y = pose_from_parameters(&b[k]);
            position = std::max(position, norm(translation_of(x) - translation_of(y)));
            angle = std::max(angle, angle_between(x.real, y.real));
        }
        std::printf(
            "  so3xr3 cost at the se3 solution %.7f; se3 cost at the so3xr3 solution %.7f\n",
            cost_at(g, o, relative_pose_form::so3xr3, b),
            cost_at(g, o, relative_pose_form::se3, a));
        std::printf("  the two solutions differ by up to %.3g (position) and %.3g rad\n", position,
                    angle);
    }
    const solve_result& shown =
        o.so3xr3 ? solved[relative_pose_form::so3xr3] : solved[relative_pose_form::se3];
    const std::map<int, dual_quaternion<double>> optimized = poses_of(g, shown.poses);
    expect(g2o::write_g2o(o.output + "/pose_graph_optimized.g2o", optimized),
           "pose_graph_optimized.g2o written");
    char title[200], caption[200];
    std::snprintf(title, sizeof title, "Pose graph %s: %d poses, %d edges", name.c_str(),
                  static_cast<int>(g.vertices.size()), static_cast<int>(g.edges.size()));
    std::snprintf(
        caption, sizeof caption,
        "top view; %s residual, cost %.1f from %.1f in %d iterations (Ceres, first pose fixed)",
        o.so3xr3 ? "SO(3)xR3" : "SE(3) log", shown.final_cost, shown.initial_cost,
        shown.iterations);
    expect(draw(o.output + "/pose_graph.svg", title, g, optimized, caption),
           "pose_graph.svg written");
    return example::failures() == 0 ? 0 : 1;
}
