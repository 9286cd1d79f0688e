// orientation_tracking: integrate a gyroscope's body-frame angular velocity into an orientation,
// with quaternions and with matrices, and watch the drift. First-order steps (q += dt/2 q (0, w), R
// += dt R [w]x) inflate the quaternion's norm and the matrix's columns; renormalizing each step
// (normalize, nearest_rotation) keeps them rotations; exact steps (the exponential map) also remove
// the truncation error. The gyro turns at a constant body rate, so the exact answer is exp(w t /
// 2). Run: example_orientation_tracking [output directory] -> orientation_tracking.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <quat/quat.hpp>

#include "check.hpp"
#include "plot.hpp"
#include "svg.hpp"

using namespace quat;
using v3 = vec3<double>;

namespace {

double rotation_angle(const quatd& from, const quatd& to) {
    return to_axis_angle(conjugate(from) * to).angle;
}

/// R + dt R [w]x: the first-order matrix step for a body-frame rate w.
rotation_matrix<double> first_order_step(const rotation_matrix<double>& r, const v3& w, double dt) {
    const rotation_matrix<double> skew{{{0, -w.z, w.y}, {w.z, 0, -w.x}, {-w.y, w.x, 0}}};
    const rotation_matrix<double> change = r * skew;
    rotation_matrix<double> next = r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) next(i, j) += dt * change(i, j);
    return next;
}

/// q + dt/2 q (0, w): the first-order quaternion step for a body-frame rate w.
quatd first_order_step(const quatd& q, const v3& w, double dt) {
    return q + q * quatd{0, w.x, w.y, w.z} * (dt / 2);
}

struct tracker {
    const char* name;
    svg::style look;
    bool is_matrix;
    quatd q;
    rotation_matrix<double> m;
    plot::series drift, error;
};

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/orientation_tracking.svg";
    const v3 rate{0.6, -0.9, 1.3};  // rad/s in the body frame
    const double dt = 0.01, duration = 60;
    const int steps = static_cast<int>(duration / dt);
    std::printf(
        "orientation_tracking: gyro rate (0.6, -0.9, 1.3) rad/s at 100 Hz for 60 s, doubles\n");

    const quatd one = quatd::identity();
    const rotation_matrix<double> eye = rotation_matrix<double>::identity();
    std::vector<tracker> trackers = {
        {"quaternion, first order", {"#ff7f0e", 2.5}, false, one, eye, {}, {}},
        {"quaternion, first order + normalize",
         {"#ff7f0e", 2.0, "none", 1.0, "7 4"},
         false,
         one,
         eye,
         {},
         {}},
        {"quaternion, exact step + normalize", {"#1f77b4", 2.5}, false, one, eye, {}, {}},
        {"matrix, first order", {"#d62728", 2.5}, true, one, eye, {}, {}},
        {"matrix, first order + nearest_rotation",
         {"#d62728", 2.0, "none", 1.0, "7 4"},
         true,
         one,
         eye,
         {},
         {}},
        {"matrix, exact step", {"#2ca02c", 2.0, "none", 1.0, "2 4"}, true, one, eye, {}, {}},
    };
    const quatd exact_step = from_rotation_vector(rate * dt);
    const rotation_matrix<double> exact_step_matrix = to_matrix(exact_step);
    constexpr double floor = 1e-17;  // log plots show exact zeros here
    for (int n = 1; n <= steps; ++n) {
        const quatd truth = from_rotation_vector(rate * (n * dt));
        for (std::size_t k = 0; k < trackers.size(); ++k) {
            tracker& t = trackers[k];
            switch (k) {
                case 0:
                    t.q = first_order_step(t.q, rate, dt);
                    break;
                case 1:
                    t.q = normalize(first_order_step(t.q, rate, dt));
                    break;
                case 2:
                    t.q = normalize(t.q * exact_step);
                    break;
                case 3:
                    t.m = first_order_step(t.m, rate, dt);
                    break;
                case 4:
                    t.m = nearest_rotation(first_order_step(t.m, rate, dt));
                    break;
                default:
                    t.m = t.m * exact_step_matrix;
                    break;
            }
            if (n % 20 != 0) continue;
            // Drift: how far the state is from a rotation. Error: angle to the truth of the nearest
            // rotation.
            const double drift = t.is_matrix ? orthogonality_error(t.m) : std::abs(norm(t.q) - 1);
            const quatd estimate =
                t.is_matrix ? to_quaternion(nearest_rotation(t.m)) : normalize(t.q);
            t.drift.x.push_back(n * dt);
            t.drift.y.push_back(std::max(drift, floor));
            t.error.x.push_back(n * dt);
            t.error.y.push_back(std::max(rotation_angle(estimate, truth), floor));
        }
    }
    std::printf("  %-40s %14s %14s\n", "after 60 s", "norm/orth err", "angle err rad");
    for (const tracker& t : trackers) {
        std::printf("  %-40s %14.3e %14.3e\n", t.name, t.drift.y.back(), t.error.y.back());
    }
    expect(trackers[0].drift.y.back() > 0.1, "first-order quaternion steps inflate |q|");
    expect(trackers[1].drift.y.back() < 1e-14, "normalizing each step keeps |q| = 1");
    expect(trackers[1].error.y.back() > 1e-4,
           "normalizing does not remove the first-order truncation error");
    expect(trackers[2].error.y.back() < 1e-10,
           "exact steps (exponential map) track the truth to rounding");
    expect(trackers[3].drift.y.back() > 0.1, "first-order matrix steps lose orthogonality");
    expect(trackers[4].drift.y.back() < 1e-14,
           "nearest_rotation each step keeps the matrix a rotation");
    expect(trackers[5].error.y.back() < 1e-10, "exact matrix steps track the truth to rounding");

    std::vector<plot::series> drift, error;
    for (tracker& t : trackers) {
        t.drift.label = t.error.label = t.name;
        t.drift.look = t.error.look = t.look;
        drift.push_back(t.drift);
        error.push_back(t.error);
    }
    svg::document doc(1000, 470);
    doc.text({500, 26}, "Integrating a gyroscope: 100 Hz, constant body rate 1.69 rad/s, 60 s", 17,
             "middle", "#222", true);
    plot::chart left{80,
                     80,
                     380,
                     320,
                     "Distance from a rotation",
                     "time (s)",
                     "| |q| - 1 |  or  max |(R^T R - I)ij|",
                     0,
                     duration,
                     1e-17,
                     10,
                     true};
    left.legend_top_left = false;
    left.legend_down = 0.36;
    plot::chart right{580,
                      80,
                      380,
                      320,
                      "Orientation error",
                      "time (s)",
                      "angle to the exact orientation (rad)",
                      0,
                      duration,
                      1e-17,
                      10,
                      true};
    right.legend_top_left = false;
    right.legend_down = 0.33;
    plot::draw(doc, left, drift);
    plot::draw(doc, right, error);
    doc.text({500, 458},
             "first order: q += dt/2 q (0, w), R += dt R [w]x;  exact step: q = q exp(w dt / 2), R "
             "= R exp([w]x dt)",
             12, "middle", "#444");
    expect(doc.save(out), "orientation_tracking.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
