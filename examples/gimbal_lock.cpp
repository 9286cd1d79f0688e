// gimbal_lock: with yaw-pitch-roll angles (intrinsic z-y-x, R = Rz(yaw) Ry(pitch) Rx(roll)) at
// pitch 90 degrees, changing yaw and changing roll turn the body about the same world axis: one
// degree of freedom is lost. extract_euler reports it with its gimbal_lock flag. Run:
// example_gimbal_lock [output directory] -> gimbal_lock.svg
#include <cmath>
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
using ypr = euler<double>;  // sequence::zyx, frame::intrinsic: {yaw, pitch, roll}

/// World axis and signed rate of the change in orientation when angle `which` of e grows a little.
v3 turn_axis(const ypr& e, int which) {
    ypr moved = e;
    moved[static_cast<std::size_t>(which)] += 1e-6;
    const axis_angle<double> step =
        to_axis_angle(to_quaternion(moved) * conjugate(to_quaternion(e)));
    return step.axis * (step.angle / 1e-6);
}

void panel(svg::document& doc, double x0, double pitch, const char* title) {
    const auto cam = view3d::camera::looking_from(0.75, 0.5, {x0 + 220, 250}, 150);
    view3d::draw_sphere(doc, cam, 1.0);
    const struct {
        int which;
        const char* colour;
        double width;
        const char* dash;
    } sweeps[2] = {{0, "#ff7f0e", 5.0, ""}, {2, "#6a3d9a", 2.0, "7 5"}};
    for (const auto& sweep : sweeps) {
        for (int body_axis : {1, 2}) {
            std::vector<v3> tip;
            for (int k = 0; k <= 120; ++k) {
                ypr e{{0.0, pitch, 0.0}};
                e[static_cast<std::size_t>(sweep.which)] = (-120.0 + 2.0 * k) * degree;
                const v3 axis = body_axis == 1 ? v3{0, 1, 0} : v3{0, 0, 1};
                tip.push_back(rotate(to_quaternion(e), axis));
            }
            view3d::draw_sphere_path(doc, cam, tip,
                                     {sweep.colour, sweep.width, "none", 1.0, sweep.dash});
        }
    }
    view3d::draw_box(doc, cam, to_quaternion(ypr{{0.0, pitch, 0.0}}), {0.45, 0.3, 0.08}, {0, 0, 0},
                     1.0);
    doc.text({x0 + 220, 60}, title, 15, "middle", "#222", true);
    // Rounded to 1e-9 so that -0.00 never appears in the picture.
    const auto tidy = [](v3 v) {
        for (double* c : {&v.x, &v.y, &v.z}) *c = std::abs(*c) < 1e-9 ? 0.0 : *c;
        return v;
    };
    const v3 a = tidy(turn_axis(ypr{{0.0, pitch, 0.0}}, 0)),
             c = tidy(turn_axis(ypr{{0.0, pitch, 0.0}}, 2));
    char line[120];
    std::snprintf(line, sizeof line, "increasing yaw turns about (%+.2f, %+.2f, %+.2f)", a.x, a.y,
                  a.z);
    doc.text({x0 + 220, 428}, line, 12, "middle");
    std::snprintf(line, sizeof line, "increasing roll turns about (%+.2f, %+.2f, %+.2f)", c.x, c.y,
                  c.z);
    doc.text({x0 + 220, 446}, line, 12, "middle");
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/gimbal_lock.svg";
    std::printf("gimbal_lock: yaw-pitch-roll (intrinsic z-y-x) at pitch = 90 deg\n");

    // At pitch pi/2, Ry(pi/2) Rx(roll) = Rz(-roll) Ry(pi/2): only yaw - roll matters.
    bool only_difference_matters = true;
    for (double yaw = -150; yaw <= 150; yaw += 30)
        for (double roll = -150; roll <= 150; roll += 30) {
            const quatd q = to_quaternion(ypr{{yaw * degree, numbers::pi / 2, roll * degree}});
            const quatd same = to_quaternion(ypr{{(yaw - roll) * degree, numbers::pi / 2, 0.0}});
            only_difference_matters = only_difference_matters && angle_between(q, same) < 1e-12;
        }
    expect(only_difference_matters, "(yaw, 90 deg, roll) is the rotation (yaw - roll, 90 deg, 0)");

    const v3 yaw_axis = turn_axis(ypr{{0.3, numbers::pi / 2, -0.4}}, 0),
             roll_axis = turn_axis(ypr{{0.3, numbers::pi / 2, -0.4}}, 2);
    std::printf("  d/dyaw turns about (%+.3f, %+.3f, %+.3f); d/droll about (%+.3f, %+.3f, %+.3f)\n",
                yaw_axis.x, yaw_axis.y, yaw_axis.z, roll_axis.x, roll_axis.y, roll_axis.z);
    expect(norm(cross(yaw_axis, roll_axis)) < 1e-6,
           "at pitch 90 deg yaw and roll turn about one axis (world z)");
    const v3 free_yaw = turn_axis(ypr{{0.3, numbers::pi / 4, -0.4}}, 0),
             free_roll = turn_axis(ypr{{0.3, numbers::pi / 4, -0.4}}, 2);
    expect(norm(cross(free_yaw, free_roll)) > 0.5,
           "at pitch 45 deg they turn about different axes");

    // The library reports the singularity and puts the whole turn into the first angle.
    const auto locked = extract_euler<sequence::zyx>(
        to_quaternion(ypr{{40 * degree, numbers::pi / 2, 25 * degree}}));
    std::printf("  extract_euler of (40, 90, 25) deg: (%.4f, %.4f, %.4f) deg, gimbal_lock = %s\n",
                locked.angles[0] / degree, locked.angles[1] / degree, locked.angles[2] / degree,
                locked.gimbal_lock ? "true" : "false");
    expect(locked.gimbal_lock, "extract_euler flags pitch = 90 deg as gimbal lock");
    expect(locked.angles[2] == 0.0 && std::abs(locked.angles[0] - 15 * degree) < 1e-9,
           "at the lock the third angle is 0 and the first carries yaw - roll = 15 deg");
    const auto free =
        extract_euler<sequence::zyx>(to_quaternion(ypr{{40 * degree, 60 * degree, 25 * degree}}));
    expect(!free.gimbal_lock && std::abs(free.angles[2] - 25 * degree) < 1e-12,
           "pitch 60 deg: no lock, angles recovered");

    svg::document doc(880, 500);
    doc.text({440, 28}, "Gimbal lock: yaw-pitch-roll, R = Rz(yaw) Ry(pitch) Rx(roll)", 17, "middle",
             "#222", true);
    panel(doc, 0, numbers::pi / 2, "pitch = 90 deg: yaw and roll paths coincide");
    panel(doc, 440, numbers::pi / 4, "pitch = 45 deg: two independent turns");
    doc.line({30, 478}, {60, 478}, {"#ff7f0e", 5.0});
    doc.text({66, 483}, "tips of the body y and z axes as yaw sweeps -120..120 deg", 12);
    doc.line({460, 478}, {490, 478}, {"#6a3d9a", 2.0, "none", 1.0, "7 5"});
    doc.text({496, 483}, "the same tips as roll sweeps -120..120 deg", 12);
    expect(doc.save(out), "gimbal_lock.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
