// interpolation: four ways to go from rotation a to rotation b.
//   slerp                      great-circle arc at constant angular velocity
//   nlerp                      the same arc, faster in the middle
//   lerp of yaw-pitch-roll     a different path altogether, at varying speed
//   lerp of matrices, repaired (1-t) Ma + t Mb is no rotation; nearest_rotation makes it one
// Run: example_interpolation [output directory]  -> interpolation.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <quat/quat.hpp>

#include "check.hpp"
#include "plot.hpp"
#include "svg.hpp"
#include "view3d.hpp"

using namespace quat;
using view3d::v3;

namespace {

constexpr double degree = numbers::pi / 180;
using ypr = euler<double>;  // intrinsic z-y-x {yaw, pitch, roll}

double rotation_angle(const quatd& from, const quatd& to) {
    return to_axis_angle(conjugate(from) * to).angle;
}

rotation_matrix<double> lerp(const rotation_matrix<double>& a, const rotation_matrix<double>& b,
                             double t) {
    rotation_matrix<double> m{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) m(i, j) = (1 - t) * a(i, j) + t * b(i, j);
    return m;
}

struct method {
    const char* name;
    std::function<quatd(double)> at;
    svg::style look;
};

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/interpolation.svg";

    const ypr from_angles{{-70 * degree, 10 * degree, 20 * degree}},
        to_angles{{70 * degree, -25 * degree, 60 * degree}};
    const quatd a = to_quaternion(from_angles), b = to_quaternion(to_angles);
    const rotation_matrix<double> ma = to_matrix(a), mb = to_matrix(b);
    const double total = rotation_angle(a, b);
    std::printf(
        "interpolation: from yaw-pitch-roll (-70, 10, 20) to (70, -25, 60) deg, %.2f deg apart\n",
        total / degree);

    const std::vector<method> methods = {
        {"slerp", [&](double t) { return slerp(a, b, t); }, {"#1f77b4", 4.0}},
        {"nlerp", [&](double t) { return nlerp(a, b, t); }, {"#ff7f0e", 2.0, "none", 1.0, "8 5"}},
        {"lerp of yaw-pitch-roll",
         [&](double t) {
             ypr e{};
             for (std::size_t k = 0; k < 3; ++k) e[k] = (1 - t) * from_angles[k] + t * to_angles[k];
             return to_quaternion(e);
         },
         {"#2ca02c", 2.5}},
        {"lerp of matrices + nearest_rotation",
         [&](double t) { return to_quaternion(nearest_rotation(lerp(ma, mb, t))); },
         {"#d62728", 2.0, "none", 1.0, "2 4"}},
    };

    // Angular velocity over t, in units of the slerp's constant rate (the total angle per unit t).
    constexpr int steps = 400;
    std::vector<plot::series> speed;
    double nlerp_fastest = 0, nlerp_slowest = 1e9, slerp_deviation = 0, euler_off_arc = 0;
    for (const method& m : methods) {
        plot::series s{m.name, {}, {}, m.look};
        for (int k = 0; k < steps; ++k) {
            const double t0 = double(k) / steps, t1 = double(k + 1) / steps;
            const double rate = rotation_angle(m.at(t0), m.at(t1)) / (t1 - t0) / total;
            s.x.push_back((t0 + t1) / 2);
            s.y.push_back(rate);
            if (std::string(m.name) == "slerp")
                slerp_deviation = std::max(slerp_deviation, std::abs(rate - 1));
            if (std::string(m.name) == "nlerp") {
                nlerp_fastest = std::max(nlerp_fastest, rate);
                nlerp_slowest = std::min(nlerp_slowest, rate);
            }
            if (m.name[0] == 'l' && m.name[8] == 'y')
                euler_off_arc = std::max(euler_off_arc, rotation_angle(m.at(t0), slerp(a, b, t0)));
        }
        speed.push_back(s);
        const double miss = rotation_angle(m.at(0), a) + rotation_angle(m.at(1), b);
        std::printf("  %-36s endpoints off by %.2e rad\n", m.name, miss);
        expect(miss < 1e-9, "starts at a and ends at b");
    }
    std::printf("  slerp rate deviates from constant by at most %.2e\n", slerp_deviation);
    std::printf("  nlerp rate ranges %.3f .. %.3f of the slerp rate\n", nlerp_slowest,
                nlerp_fastest);
    std::printf(
        "  lerp of yaw-pitch-roll strays up to %.1f deg from the slerp rotation at the same t\n",
        euler_off_arc / degree);
    expect(slerp_deviation < 1e-6, "slerp turns at constant angular velocity");
    expect(nlerp_fastest / nlerp_slowest > 1.2,
           "nlerp turns faster in the middle than at the ends");
    expect(euler_off_arc > 10 * degree, "lerp of Euler angles leaves the shortest path");
    const rotation_matrix<double> halfway = lerp(ma, mb, 0.5);
    std::printf("  halfway lerped matrix: orthogonality error %.3f, determinant %.3f\n",
                orthogonality_error(halfway), determinant(halfway));
    expect(orthogonality_error(halfway) > 0.1, "a lerped matrix is not a rotation");
    expect(orthogonality_error(nearest_rotation(halfway)) < 1e-12, "nearest_rotation repairs it");

    svg::document doc(1000, 500);
    char title[120];
    std::snprintf(title, sizeof title, "Interpolating between two rotations %.0f deg apart",
                  total / degree);
    doc.text({500, 28}, title, 17, "middle", "#222", true);
    // Look at the sphere from above the middle of the slerp path.
    const v3 middle = rotate(slerp(a, b, 0.5), v3{1, 0, 0});
    const auto cam = view3d::camera::looking_from(
        std::atan2(middle.y, middle.x) - 0.35,
        std::asin(std::clamp(middle.z, -1.0, 1.0)) * 0.5 + 0.35, {230, 275}, 170);
    view3d::draw_sphere(doc, cam, 1.0);
    view3d::draw_world_axes(doc, cam, 1.25);
    for (const method& m : methods) {
        std::vector<v3> path;
        for (int k = 0; k <= 200; ++k) path.push_back(rotate(m.at(k / 200.0), v3{1, 0, 0}));
        view3d::draw_sphere_path(doc, cam, path, m.look);
        // Dots at t = 0, 0.1, ..., 1 show the speed along the path.
        for (int k = 0; k <= 10; ++k) {
            const v3 p = rotate(m.at(k / 10.0), v3{1, 0, 0});
            doc.circle(cam.project(p), 3.2,
                       {m.look.stroke, 1.0, cam.depth(p) >= 0 ? m.look.stroke : "white"});
        }
    }
    const svg::point start = cam.project(rotate(a, v3{1, 0, 0})),
                     end = cam.project(rotate(b, v3{1, 0, 0}));
    doc.text({start.x + 8, start.y + 16}, "a", 15, "start", "#222", true);
    doc.text({end.x + 8, end.y - 8}, "b", 15, "start", "#222", true);
    doc.text({230, 480}, "path of the body x axis's tip; dots every 0.1 in t", 12, "middle");

    double fastest_rate = 2.0;
    for (const plot::series& s : speed)
        for (double rate : s.y)
            fastest_rate = std::max(fastest_rate, std::ceil(rate) + 1);  // room for the legend
    plot::chart chart{520,
                      85,
                      440,
                      330,
                      "Angular velocity over t",
                      "t",
                      "angular velocity / (total angle per unit t)",
                      0,
                      1,
                      0,
                      fastest_rate};
    chart.legend_top_left = false;
    plot::draw(doc, chart, speed);
    expect(doc.save(out), "interpolation.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
