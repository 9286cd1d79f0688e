// camera_follow: a camera on the ground follows a drone flying a figure-eight, aiming every frame
// with look_rotation(drone - camera, world_up), world z up. look_rotation uses OpenGL's camera
// convention: the camera looks down its -z axis, y is up in the picture and x to the right. A fixed
// world up is a pan-tilt mount: the camera never rolls, but when the drone passes over it the pan
// has to swing through 180 degrees, the faster the nearer the zenith. Exactly overhead, forward is
// parallel to up and no side is "up": look_rotation falls back to rotation_between((0, 0, -1),
// forward) and try_look_rotation returns nothing.
// Picture: left, the scene and the camera's picture frame at every second; right, how fast the
// camera turns, for three camera positions nearer and nearer the drone's path.
// Run: example_camera_follow [output directory]  -> camera_follow.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
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

constexpr int frame_count = 1200;  // one 12 s lap of the figure-eight, filmed at 100 frames/s
constexpr double dt = 0.01, period = frame_count * dt, omega = 2 * numbers::pi / period;
// World z is up. In the camera's own axes (OpenGL): x right, y up, and it looks along -z.
const v3 world_up{0, 0, 1}, camera_right{1, 0, 0}, camera_up{0, 1, 0}, camera_look{0, 0, -1};
// Tolerances of the checks, also quoted in the picture (the errors themselves are rounding noise,
// different from compiler to compiler, so they stay out of the SVG).
constexpr double tolerance = 1e-14;
const char* const tolerance_text = "1e-14";

/// The drone at time t: a figure-eight 2 to 3 m high that crosses itself above the origin at t = 3
/// s (3 m up) and t = 9 s (2 m up), heading diagonally across the y axis each time.
v3 drone(double t) {
    const double a = omega * (t - 3);
    return {3 * std::sin(a), 1.5 * std::sin(2 * a), 2.5 + 0.5 * std::cos(a)};
}

/// Angle between two non-zero vectors; atan2 stays accurate for tiny angles, where acos would not.
double angle(const v3& a, const v3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

/// The camera's frame built by hand from its columns (right, up, back): the images of x, y and z.
rotation_matrix<double> by_hand(const v3& forward) {
    const v3 back = -normalize(forward), right = normalize(cross(forward, world_up));
    return rotation_matrix<double>::from_columns(right, cross(back, right), back);
}

/// The same camera as a pan-tilt mount: from looking straight down, tilt up about x by 90 degrees
/// plus the elevation, then pan about world z. Intrinsic z-y-x angles {pan, 0, tilt}: no roll.
quatd pan_tilt(const v3& forward) {
    const double pan = std::atan2(forward.y, forward.x) - numbers::pi / 2;
    const double tilt = numbers::pi / 2 + std::atan2(forward.z, std::hypot(forward.x, forward.y));
    return to_quaternion(euler<double>{pan, 0.0, tilt});
}

double max_difference(const rotation_matrix<double>& a, const rotation_matrix<double>& b) {
    double d = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(a(i, j) - b(i, j)));
    return d;
}

/// The camera's orientation at every frame, from a camera standing at `camera` on the ground.
std::vector<quatd> follow(const v3& camera) {
    std::vector<quatd> frames;
    frames.reserve(frame_count);
    // Frames at (k + 1/2) dt: none falls exactly on a crossing, so none is exactly overhead.
    for (int k = 0; k < frame_count; ++k)
        frames.push_back(look_rotation(drone((k + 0.5) * dt) - camera, world_up));
    return frames;
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/camera_follow.svg";
    std::printf(
        "camera_follow: drone on a figure-eight (12 s lap), camera on the ground, 100 Hz\n");

    // Three camera positions: 0.4 m and 0.1 m from the point under the crossing, and right on it.
    const double offsets[3] = {0.4, 0.1, 0.0};
    const svg::style looks[3] = {
        {"#1f77b4", 2.0}, {"#ff7f0e", 2.0, "none", 1.0, "7 4"}, {"#d62728", 1.5}};
    std::vector<plot::series> speed;
    double view_error = 0, roll = 0, hand_error = 0, pan_tilt_error = 0, unit_error = 0,
           peak[3] = {0, 0, 0};
    bool up_above = true;
    for (int c = 0; c < 3; ++c) {
        const v3 camera{0, -offsets[c], 0};
        const std::vector<quatd> frames = follow(camera);
        char label[64];
        if (offsets[c] > 0)
            std::snprintf(label, sizeof label, "camera %.1f m off the crossing", offsets[c]);
        else std::snprintf(label, sizeof label, "camera right under the crossing");
        plot::series s{label, {}, {}, looks[c]};
        for (std::size_t k = 0; k < frames.size(); ++k) {
            const quatd& r = frames[k];
            const v3 forward = drone((static_cast<double>(k) + 0.5) * dt) - camera;
            view_error = std::max(view_error, angle(rotate(r, camera_look), forward));
            roll = std::max(roll, std::abs(rotate(r, camera_right).z));  // right stays horizontal
            up_above = up_above && rotate(r, camera_up).z > 0;
            hand_error = std::max(hand_error, max_difference(to_matrix(r), by_hand(forward)));
            pan_tilt_error = std::max(pan_tilt_error, angle_between(r, pan_tilt(forward)));
            unit_error = std::max(unit_error, std::abs(norm(r) - 1));
            if (k == 0) continue;
            // The rate a motorized mount must turn at between consecutive frames.
            const double rate = norm(body_angular_velocity(frames[k - 1], r, dt));
            peak[c] = std::max(peak[c], rate);
            s.x.push_back(static_cast<double>(k) * dt);
            s.y.push_back(rate);
        }
        speed.push_back(s);
        std::printf("  %-34s peak angular speed %8.2f rad/s\n", label, peak[c]);
    }
    std::printf(
        "  over all frames: view axis off the drone by at most %.1e rad, right axis out of\n"
        "  the horizontal by %.1e, |q| - 1 by %.1e; matrix by hand off by %.1e, pan-tilt\n"
        "  angles off by %.1e rad\n",
        view_error, roll, unit_error, hand_error, pan_tilt_error);
    expect(view_error < tolerance, "the view axis R (0, 0, -1) points at the drone every frame");
    expect(roll < tolerance, "the right axis R (1, 0, 0) stays horizontal: the camera never rolls");
    expect(up_above, "the up axis R (0, 1, 0) points above the horizon");
    expect(unit_error < tolerance, "look_rotation returns unit quaternions");
    expect(hand_error < tolerance, "to_matrix(R) has columns right, up, back as built by hand");
    expect(pan_tilt_error < tolerance, "R is the pan-tilt rotation Rz(pan) Rx(90 deg + elevation)");
    expect(peak[1] > 3 * peak[0], "4 times nearer the zenith, the pan swings over 3 times faster");
    expect(peak[2] > 0.99 * numbers::pi / dt,
           "right below the crossing, the camera flips 180 deg in a frame");

    // Straight overhead, forward is parallel to up: the documented fallback.
    const v3 overhead{0, 0, 2.5};
    const quatd fallback = look_rotation(overhead, world_up);
    expect(fallback == rotation_between(camera_look, overhead),
           "exactly overhead, look_rotation is rotation_between((0, 0, -1), forward)");
    expect(!try_look_rotation(overhead, world_up).has_value(),
           "exactly overhead, try_look_rotation returns nothing");
    expect(angle(rotate(fallback, camera_look), overhead) < tolerance,
           "the fallback still looks at the drone");
    expect(!try_look_rotation(v3{1e-17, 0, 1}, world_up).has_value(),
           "within eps of parallel counts as parallel");
    // A nanoradian to either side of the zenith the answer is well defined, and a half turn apart:
    // no choice exactly overhead could be continuous with both.
    const v3 east{2.5e-9, 0, 2.5}, west{-2.5e-9, 0, 2.5};
    const std::optional<quatd> to_east = try_look_rotation(east, world_up),
                               to_west = try_look_rotation(west, world_up);
    expect(to_east && to_west, "a nanoradian off the zenith, try_look_rotation succeeds");
    const double apart = to_east && to_west ? angle_between(*to_east, *to_west) : 0;
    std::printf("  1e-9 rad east and west of the zenith: cameras %.6f deg apart\n",
                apart * 180 / numbers::pi);
    expect(std::abs(apart - numbers::pi) < 1e-6, "... and the two cameras are a half turn apart");
    expect(angle(rotate(*to_east, camera_look), east) < tolerance, "... and look at the drone");

    svg::document doc(1000, 540);
    doc.text({500, 28}, "A camera following a drone: look_rotation(drone - camera, up = +z)", 17,
             "middle", "#222", true);
    // Left: the scene with the camera 0.4 m off the crossing, seen from the south-east.
    const v3 camera{0, -offsets[0], 0};
    const auto view = view3d::camera::looking_from(-0.42 * numbers::pi, 0.5, {250, 330}, 72);
    for (int g = -3; g <= 3; ++g) {  // a ground grid, 1 m squares
        doc.line(view.project({g * 1.0, -3, 0}), view.project({g * 1.0, 3, 0}), {"#e3e3e3", 1.0});
        doc.line(view.project({-3, g * 1.0, 0}), view.project({3, g * 1.0, 0}), {"#e3e3e3", 1.0});
    }
    std::vector<svg::point> path, shadow;
    for (int k = 0; k <= 240; ++k) {
        const v3 p = drone(period * k / 240);
        path.push_back(view.project(p));
        shadow.push_back(view.project({p.x, p.y, 0}));
    }
    doc.polyline(shadow, {"#bbb", 1.5, "none", 1.0, "4 4"});
    doc.polyline(path, {"#444", 2.0});
    const std::vector<quatd> frames = follow(camera);
    // Every second: the sight line, and the camera's picture frame drawn across it 70% of the way
    // to the drone (red edges along the camera's x, green along its y, a tick above the top edge).
    for (std::size_t k = 50; k < frames.size(); k += 100) {
        const v3 target = drone((static_cast<double>(k) + 0.5) * dt);
        const v3 centre = camera + (target - camera) * 0.7;
        const v3 x = rotate(frames[k], camera_right) * 0.24,
                 y = rotate(frames[k], camera_up) * 0.16;
        doc.line(view.project(camera), view.project(target), {"#1f77b4", 1.0, "none", 0.6, "3 3"});
        const v3 corner[4] = {centre - x - y, centre + x - y, centre + x + y, centre - x + y};
        std::vector<svg::point> outline;
        for (const v3& p : corner) outline.push_back(view.project(p));
        doc.polygon(outline, {"none", 0.0, "white", 0.8});
        for (std::size_t e = 0; e < 4; ++e)
            doc.line(outline[e], outline[(e + 1) % 4],
                     {view3d::axis_colour[e % 2 == 0 ? 0 : 1], 2.0});
        doc.line(view.project(centre + y), view.project(centre + y * 1.7),
                 {view3d::axis_colour[1], 2.0});
        doc.circle(view.project(target), 4, {"#222", 1.0, "#ffd700"});
    }
    doc.arrow(view.project(camera), view.project(camera + world_up * 0.7), {"#888", 1.5});
    doc.circle(view.project(camera), 5, {"#222", 1.0, "#222"});
    const svg::point at_camera = view.project(camera);
    doc.text({at_camera.x + 8, at_camera.y + 16}, "camera", 12, "start", "#222", true);
    doc.text({at_camera.x - 6, at_camera.y - 38}, "+z", 12, "end", "#888");
    for (const double t : {3.0, 9.0}) {  // the crossings, where the pan swings round
        const svg::point p = view.project(drone(t));
        doc.circle(p, 3, {"#222", 1.0, "#222"});
        if (t < 5) doc.text({p.x - 8, p.y + 4}, "t = 3 s", 12, "end", "#222", true);
        else doc.text({p.x + 9, p.y + 4}, "t = 9 s", 12, "start", "#222", true);
    }
    doc.text({250, 484}, "camera 0.4 m off the point under the crossing; drone path (dashed:", 12,
             "middle");
    doc.text({250, 500}, "its shadow), sight lines every second, and the camera's picture frame",
             12, "middle");
    doc.text({250, 516}, "on each: red edges along camera x (right), green along camera y (up)", 12,
             "middle");

    // Right: how fast the camera turns, on a log scale (the flip reaches pi / dt).
    plot::chart chart{580,
                      95,
                      380,
                      330,
                      "Angular speed of the camera",
                      "time (s)",
                      "|body_angular_velocity| between frames (rad/s)",
                      0,
                      period,
                      0.1,
                      1e4,  // the top decade holds the legend
                      true};
    chart.legend_top_left = false;
    plot::draw(doc, chart, speed);
    doc.text({858, 190}, "180 deg flip in one frame", 11, "end", "#d62728");
    const std::string checked =
        std::string("Checked every frame: view axis on the drone, no roll, within ") +
        tolerance_text + " rad.";
    doc.text({770, 484}, checked, 12, "middle", "#444");
    doc.text({770, 500}, "Exactly overhead, look_rotation falls back to", 12, "middle", "#444");
    doc.text({770, 516}, "rotation_between((0, 0, -1), forward); try_look_rotation: none.", 12,
             "middle", "#444");
    expect(doc.save(out), "camera_follow.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
