// complex_plane (thesis Fig. 2.3): multiplying by the unit complex number e^{i alpha} turns the
// plane counter-clockwise by alpha; doing it again with e^{i beta} adds the angles. The quaternion
// (cos(alpha/2), sin(alpha/2) k) does the same to the xy-plane in 3D -- with the half angle. Run:
// example_complex_plane [output directory] -> complex_plane.svg
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <vector>

#include <quat/quat.hpp>

#include "check.hpp"
#include "svg.hpp"
#include "view3d.hpp"

using namespace quat;
using view3d::v3;

namespace {

constexpr double degree = numbers::pi / 180;

/// Arc of radius r (pixels) about c from angle a0 to a1 (radians, counter-clockwise on screen).
std::vector<svg::point> arc(svg::point c, double r, double a0, double a1) {
    std::vector<svg::point> points;
    for (int k = 0; k <= 60; ++k) {
        const double a = a0 + (a1 - a0) * k / 60;
        points.push_back({c.x + r * std::cos(a), c.y - r * std::sin(a)});
    }
    return points;
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/complex_plane.svg";
    const double alpha = 50 * degree, beta = 70 * degree;
    const std::complex<double> one{1, 0};
    const std::complex<double> z1 = std::polar(1.0, alpha) * one, z2 = std::polar(1.0, beta) * z1;
    std::printf("complex_plane: e^{i beta} e^{i alpha} 1 = (%.4f, %.4f) = e^{i (alpha + beta)}\n",
                z2.real(), z2.imag());
    expect(std::abs(z2 - std::polar(1.0, alpha + beta)) < 1e-15,
           "the angles of unit complex numbers add");

    // The quaternion version: rotating (1, 0, 0) about z.
    const quatd q_alpha = to_quaternion(axis_angle<double>{{0, 0, 1}, alpha});
    const quatd q_beta = to_quaternion(axis_angle<double>{{0, 0, 1}, beta});
    const v3 p1 = rotate(q_alpha, v3{1, 0, 0}), p2 = rotate(q_beta * q_alpha, v3{1, 0, 0});
    expect(std::abs(p1.x - z1.real()) + std::abs(p1.y - z1.imag()) + std::abs(p1.z) < 1e-15,
           "(cos(a/2), sin(a/2) k) turns (1,0,0) to (cos a, sin a, 0), like e^{ia}");
    expect(std::abs(p2.x - z2.real()) + std::abs(p2.y - z2.imag()) < 1e-15,
           "q_beta * q_alpha adds the angles too");
    // The thesis's q = (cos a, sin a k) (definition 2.26) turns by 2a: the half angle is needed.
    const quatd thesis_q{std::cos(alpha), 0, 0, std::sin(alpha)};
    const v3 doubled = rotate(thesis_q, v3{1, 0, 0});
    std::printf(
        "  the thesis's (cos a, sin a k) takes (1,0,0) to (%.4f, %.4f, %.4f): angle %.1f deg, not "
        "%.1f\n",
        doubled.x, doubled.y, doubled.z, std::atan2(doubled.y, doubled.x) / degree, alpha / degree);
    expect(std::abs(std::atan2(doubled.y, doubled.x) - 2 * alpha) < 1e-12,
           "the thesis's q turns by twice the angle");

    svg::document doc(960, 470);
    doc.text({480, 28}, "Rotation by multiplication (thesis Fig. 2.3)", 17, "middle", "#222", true);

    // Left: the complex plane.
    const svg::point o{250, 265};
    const double r = 160;
    const auto at = [&](std::complex<double> z) {
        return svg::point{o.x + r * z.real(), o.y - r * z.imag()};
    };
    doc.arrow({o.x - r * 1.25, o.y}, {o.x + r * 1.3, o.y}, {"#555", 1.2});
    doc.arrow({o.x, o.y + r * 1.08}, {o.x, o.y - r * 1.3}, {"#555", 1.2});
    doc.text({o.x + r * 1.3, o.y + 18}, "Re", 13, "end");
    doc.text({o.x + 8, o.y - r * 1.25}, "Im", 13, "start");
    doc.circle(o, r, {"#999", 1.2, "none", 1.0, "5 4"});
    doc.polyline(arc(o, 55, 0, alpha), {"#ff7f0e", 2.5});
    doc.polyline(arc(o, 75, alpha, alpha + beta), {"#6a3d9a", 2.5});
    const std::complex<double> mid_alpha = std::polar(1.0, alpha / 2),
                               mid_beta = std::polar(1.0, alpha + beta / 2);
    doc.text({o.x + 68 * mid_alpha.real(), o.y - 68 * mid_alpha.imag() + 5}, "\u03b1", 16, "middle",
             "#ff7f0e", true);
    doc.text({o.x + 90 * mid_beta.real(), o.y - 90 * mid_beta.imag() + 5}, "\u03b2", 16, "middle",
             "#6a3d9a", true);
    doc.arrow(o, at(one), {"#222", 2.5});
    doc.arrow(o, at(z1), {"#ff7f0e", 2.5});
    doc.arrow(o, at(z2), {"#6a3d9a", 2.5});
    doc.text({at(one).x + 6, at(one).y - 8}, "1", 15, "start", "#222", true);
    doc.text({at(z1).x + 8, at(z1).y}, "e^(i\u03b1) \u00b7 1", 14, "start", "#ff7f0e");
    doc.text({at(z2).x + 20, at(z2).y - 20},
             "e^(i\u03b2) e^(i\u03b1) \u00b7 1 = e^(i(\u03b1+\u03b2))", 14, "middle", "#6a3d9a");
    doc.text({o.x, 455},
             "\u03b1 = 50\u00b0, \u03b2 = 70\u00b0: multiplying turns counter-clockwise", 12,
             "middle");

    // Right: the same turns of the xy-plane by quaternions, seen in 3D.
    const auto cam =
        view3d::camera::looking_from(-numbers::pi / 2 + 0.45, 0.5, {720, 250}, 165, 7.0);
    std::vector<v3> circle;
    for (int k = 0; k <= 120; ++k)
        circle.push_back(
            {std::cos(2 * numbers::pi * k / 120), std::sin(2 * numbers::pi * k / 120), 0});
    doc.polyline(
        [&] {
            std::vector<svg::point> p;
            for (const v3& c : circle) p.push_back(cam.project(c));
            return p;
        }(),
        {"#999", 1.2, "#f4f4f4", 1.0, "5 4"});
    view3d::draw_world_axes(doc, cam, 1.3);
    const v3 origin{0, 0, 0};
    doc.arrow(cam.project(origin), cam.project({1, 0, 0}), {"#222", 2.5});
    doc.arrow(cam.project(origin), cam.project(p1), {"#ff7f0e", 2.5});
    doc.arrow(cam.project(origin), cam.project(p2), {"#6a3d9a", 2.5});
    doc.arrow(cam.project(origin), cam.project(doubled), {"#d62728", 1.5, "none", 1.0, "4 3"});
    const svg::point t1 = cam.project(p1 * 1.08), t2 = cam.project(p2 * 1.08),
                     t3 = cam.project(doubled * 1.1);
    doc.text({t1.x, t1.y + 4}, "q_\u03b1", 14, "start", "#ff7f0e");
    doc.text({t2.x, t2.y - 4}, "q_\u03b2 q_\u03b1", 14, "end", "#6a3d9a");
    doc.text({t3.x + 6, t3.y}, "2\u03b1", 14, "start", "#d62728");
    doc.text({720, 430},
             "quaternions turn (1,0,0) in the xy-plane: v -> q v q*, q_\u03b1 = (cos(\u03b1/2), "
             "sin(\u03b1/2) k)",
             11, "middle");
    doc.text({720, 455}, "(the thesis's q = (cos \u03b1, sin \u03b1 k) turns by 2\u03b1, dashed)",
             11, "middle");
    expect(doc.save(out), "complex_plane.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
