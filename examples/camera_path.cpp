// camera_path: a virtual camera (the thesis's camera moves) keyframed every 2 s in two shots, and
// the same keyframes interpolated two ways:
//   split_keyframe_path   orientation by rotation_spline, position by a C2 cubic spline of its own
//   se3_keyframe_path     coupled: C2 twist cubics in se(3), rotation and translation as one screw
// Both share the orientation (rotation_spline's), so they differ only in where the camera is.
//   Orbit: the camera circles a subject at 3 m, 40 deg/s, always looking at it. That is a rotation
//   about the subject's vertical axis, a screw of constant twist: the coupled path follows it
//   exactly; the split path's cubic cuts inside the arc and its view axis misses the subject.
//   Dolly: the camera tracks along a straight rail at 2 m/s while the operator pans at a steady
//   30 deg/s. The position is a line on its own: the split path keeps to the rail; the coupled
//   path turns each segment into a screw about an axis beside the rail and bows off it.
// Picture: top, the two shots in 3D with camera frusta every 0.5 s (keyframes black); bottom, how
// far each path strays from the intended arc and rail over time.
// Run: example_camera_path [output directory]  -> camera_path.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <quat/quat.hpp>
#include <quat/trajectory.hpp>

#include "check.hpp"
#include "plot.hpp"
#include "svg.hpp"
#include "view3d.hpp"

using namespace quat;
using view3d::v3;
using pose = dual_quaternion<double>;

namespace {

constexpr double degree = numbers::pi / 180;
// Keyframes every 2 s, four per shot; the paths are sampled every 10 ms.
constexpr double key_step = 2, duration = 6;
constexpr int key_count = 4, samples = 600;
// World z is up; the subject's centre is 1 m above the ground, the camera 1.6 m (eye level).
const v3 world_up{0, 0, 1}, subject{0, 0, 1};
constexpr double camera_height = 1.6;
// The orbit: 3 m round the subject's axis, from in front of it (azimuth -90 deg), 40 deg/s.
constexpr double orbit_radius = 3, orbit_start = -90 * degree, orbit_rate = 40 * degree;
// The dolly: along the rail y = -3 m, x from -6 m at 2 m/s, panning at 30 deg/s from looking ahead
// down the rail to looking back along it, past the subject, tilted down toward its height.
constexpr double rail_y = -3, rail_start = -6, rail_speed = 2, pan_start = 0,
                 pan_rate = 30 * degree;
const double tilt = std::atan2(subject.z - camera_height, -rail_y);
// In the camera's own axes (OpenGL, as look_rotation): x right, y up, and it looks along -z.
const v3 camera_right{1, 0, 0}, camera_up{0, 1, 0}, camera_look{0, 0, -1};
// Tolerance of the exactness checks, quoted in the picture (the errors themselves are rounding
// noise that differs between compilers, so they stay out of the SVG).
constexpr double tolerance = 2e-14;
const char* const tolerance_text = "2e-14";

pose orbit(double t) {
    const double a = orbit_start + orbit_rate * t;
    const v3 p{orbit_radius * std::cos(a), orbit_radius * std::sin(a), camera_height};
    return to_dual_quaternion(look_rotation(subject - p, world_up), p);
}

pose dolly(double t) {
    const double pan = pan_start + pan_rate * t;
    const v3 look{std::cos(pan) * std::cos(tilt), std::sin(pan) * std::cos(tilt), std::sin(tilt)};
    return to_dual_quaternion(look_rotation(look, world_up),
                              v3{rail_start + rail_speed * t, rail_y, camera_height});
}

/// How far a camera at p is from the intended arc (the orbit's circle) or rail (the dolly's line).
double off_arc(const v3& p) {
    return std::hypot(std::hypot(p.x, p.y) - orbit_radius, p.z - camera_height);
}
double off_rail(const v3& p) { return std::hypot(p.y - rail_y, p.z - camera_height); }

/// Angle between two non-zero vectors; atan2 stays accurate for tiny angles, where acos would not.
double angle(const v3& a, const v3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); }

double sample_time(int k) { return duration * k / samples; }

/// What one interpolation does to one shot, worst over the samples.
struct measured {
    double at_keyframes = 0;            // rad or m: the path against its keyframes at their times
    double rotation = 0;                // rad: orientation against the intended one
    double pose_error = 0;              // m: position against the intended one at the same time
    double off_path = 0;                // m: distance from the intended arc or rail
    double aim_miss = 0;                // rad: view axis against the direction to the subject
    double closest = 1e9;               // m: nearest approach to the subject's vertical axis
    double slowest = 1e9, fastest = 0;  // m/s
    std::vector<double> off;            // distance from the arc or rail at every sample
    std::vector<v3> positions;
};

template <class Path, class Intended, class Off>
measured measure(const Path& path, const std::vector<double>& times, const std::vector<pose>& keys,
                 Intended intended, Off off) {
    measured m;
    for (std::size_t i = 0; i < times.size(); ++i) {
        const pose x = path(times[i]);
        m.at_keyframes = std::max({m.at_keyframes, angle_between(x.real, keys[i].real),
                                   norm(translation_of(x) - translation_of(keys[i]))});
    }
    for (int k = 0; k <= samples; ++k) {
        const double t = sample_time(k);
        const keyframe_path_state<double> s = path.state(t);
        const pose truth = intended(t);
        const v3 p = translation_of(s.pose);
        m.rotation = std::max(m.rotation, angle_between(s.pose.real, truth.real));
        m.pose_error = std::max(m.pose_error, norm(p - translation_of(truth)));
        m.off.push_back(off(p));
        m.off_path = std::max(m.off_path, m.off.back());
        m.aim_miss = std::max(m.aim_miss, angle(rotate(s.pose.real, camera_look), subject - p));
        m.closest = std::min(m.closest, std::hypot(p.x, p.y));
        m.slowest = std::min(m.slowest, norm(s.velocity));
        m.fastest = std::max(m.fastest, norm(s.velocity));
        m.positions.push_back(p);
    }
    return m;
}

/// A camera frustum at pose x: lines from the eye to a 0.5 m by 0.34 m picture 0.45 m ahead.
void draw_frustum(svg::document& doc, const view3d::camera& view, const pose& x,
                  const svg::style& look) {
    const v3 eye = translation_of(x);
    const v3 centre = eye + rotate(x.real, camera_look) * 0.45;
    const v3 right = rotate(x.real, camera_right) * 0.25, up = rotate(x.real, camera_up) * 0.17;
    const v3 corner[4] = {centre - right - up, centre + right - up, centre + right + up,
                          centre - right + up};
    std::vector<svg::point> picture;
    for (const v3& c : corner) {
        picture.push_back(view.project(c));
        doc.line(view.project(eye), picture.back(), look);
    }
    doc.polygon(picture, look);
    doc.line(view.project(centre + up), view.project(centre + up * 1.6), look);  // which way is up
}

/// How one shot is drawn: its view and the extent of its ground grid.
struct shot_drawing {
    const char* title;
    view3d::camera view;
    double x_min, x_max, y_min, y_max;
};

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/camera_path.svg";
    std::printf("camera_path: a virtual camera keyframed every %.0f s, split against coupled\n",
                key_step);

    std::vector<double> times;
    std::vector<pose> orbit_keys, dolly_keys;
    for (int i = 0; i < key_count; ++i) {
        times.push_back(i * key_step);
        orbit_keys.push_back(orbit(times.back()));
        dolly_keys.push_back(dolly(times.back()));
    }
    const split_keyframe_path<double> split_orbit_path(times, orbit_keys),
        split_dolly_path(times, dolly_keys);
    const se3_keyframe_path<double> coupled_orbit_path(times, orbit_keys),
        coupled_dolly_path(times, dolly_keys);
    const measured split_orbit = measure(split_orbit_path, times, orbit_keys, orbit, off_arc),
                   coupled_orbit = measure(coupled_orbit_path, times, orbit_keys, orbit, off_arc),
                   split_dolly = measure(split_dolly_path, times, dolly_keys, dolly, off_rail),
                   coupled_dolly = measure(coupled_dolly_path, times, dolly_keys, dolly, off_rail);
    const measured* all[4] = {&split_orbit, &coupled_orbit, &split_dolly, &coupled_dolly};
    const char* names[4] = {"orbit, split", "orbit, coupled", "dolly, split", "dolly, coupled"};
    for (int i = 0; i < 4; ++i) {
        std::printf(
            "  %-15s at keyframes %.1e, orientation off %.1e rad, position off %.3g m,\n"
            "  %-15s off the %s by %.3g m, speed %.3f to %.3f m/s",
            names[i], all[i]->at_keyframes, all[i]->rotation, all[i]->pose_error, "",
            i < 2 ? "arc" : "rail", all[i]->off_path, all[i]->slowest, all[i]->fastest);
        // Only the orbit aims at the subject; the dolly pans past it.
        if (i < 2) std::printf(", aim off the subject %.3g deg", all[i]->aim_miss / degree);
        std::printf("\n");
    }

    bool keyframes = true, rotations = true;
    for (const measured* m : all) {
        keyframes = keyframes && m->at_keyframes < tolerance;
        rotations = rotations && m->rotation < tolerance;
    }
    expect(keyframes, "all four paths pass through their keyframes at the keyframes' times");
    expect(rotations, "split and coupled share the orientation, the intended one in both shots");
    expect(coupled_orbit.pose_error < tolerance && coupled_orbit.aim_miss < tolerance,
           "orbit: the coupled path is the orbit itself, looking at the subject all the way");
    expect(std::abs(coupled_orbit.slowest - orbit_rate * orbit_radius) < tolerance &&
               std::abs(coupled_orbit.fastest - orbit_rate * orbit_radius) < tolerance,
           "orbit: ... at a constant 2.09 m/s");
    expect(split_orbit.off_path > 0.45 && split_orbit.off_path < 0.5 &&
               std::abs(orbit_radius - split_orbit.closest - split_orbit.off_path) < tolerance,
           "orbit: the split path cuts inside the arc, by 0.45-0.5 m at most");
    expect(split_orbit.aim_miss > 3.3 * degree && split_orbit.aim_miss < 3.7 * degree,
           "orbit: ... and its view axis misses the subject by 3.3-3.7 deg");
    expect(split_dolly.pose_error < tolerance && split_dolly.slowest > rail_speed - tolerance &&
               split_dolly.fastest < rail_speed + tolerance,
           "dolly: the split path is the dolly itself, on the rail at a constant 2 m/s");
    expect(coupled_dolly.off_path > 0.35 && coupled_dolly.off_path < 0.4,
           "dolly: the coupled path bows off the rail, by 0.35-0.4 m at most");

    // ---- The picture ---------------------------------------------------------------------------
    svg::document doc(1000, 820);
    doc.text({500, 28}, "A virtual camera through keyframes: split against coupled interpolation",
             17, "middle", "#222", true);
    const svg::style split_look{"#ff7f0e", 2.0}, coupled_look{"#1f77b4", 2.0};
    doc.line({250, 50}, {280, 50}, split_look);
    doc.text({286, 54}, "split_keyframe_path (rotation_spline, cubic position)", 12);
    doc.line({620, 50}, {650, 50}, coupled_look);
    doc.text({656, 54}, "se3_keyframe_path (coupled, twist cubics)", 12);

    // The orbit seen from in front of the subject and above; the dolly from beyond the rail's
    // end, so that the rail runs into the picture and what bows off it shows across.
    const shot_drawing shots[2] = {
        {"Orbit: 40 deg/s round the subject, looking at it",
         view3d::camera::looking_from(-90 * degree, 55 * degree, {250, 285}, 46), -4, 4, -4, 4},
        {"Dolly: 2 m/s along a rail, steady 30 deg/s pan",
         view3d::camera::looking_from(-12 * degree, 35 * degree, {770, 270}, 40), -7, 7, -5, 1}};
    const measured* split_of[2] = {&split_orbit, &split_dolly};
    const measured* coupled_of[2] = {&coupled_orbit, &coupled_dolly};
    const std::vector<pose>* keys_of[2] = {&orbit_keys, &dolly_keys};
    for (int s = 0; s < 2; ++s) {
        const shot_drawing& shot = shots[s];
        const view3d::camera& view = shot.view;
        doc.text({s == 0 ? 250.0 : 750.0, 84}, shot.title, 14, "middle", "#222", true);
        for (double x = shot.x_min; x <= shot.x_max; ++x)  // ground grid, 1 m squares
            doc.line(view.project({x, shot.y_min, 0}), view.project({x, shot.y_max, 0}),
                     {"#eee", 1.0});
        for (double y = shot.y_min; y <= shot.y_max; ++y)
            doc.line(view.project({shot.x_min, y, 0}), view.project({shot.x_max, y, 0}),
                     {"#eee", 1.0});
        doc.line(view.project({0, 0, 0}), view.project(subject), {"#555", 3.0});
        doc.circle(view.project(subject), 7, {"#222", 1.0, "#ffd700"});
        const svg::point label = view.project(subject);
        doc.text({label.x + 10, label.y - 8}, "subject", 12, "start", "#222", true);
        for (const measured* m : {split_of[s], coupled_of[s]}) {
            std::vector<svg::point> points;
            for (const v3& p : m->positions) points.push_back(view.project(p));
            doc.polyline(points, m == split_of[s] ? split_look : coupled_look);
        }
        // Frusta every 0.5 s between the keyframes, for each path; the keyframes' own in black.
        for (int k = 1; k < 12; ++k) {
            if (k % 4 == 0) continue;
            const double t = 0.5 * k;
            draw_frustum(doc, view, s == 0 ? split_orbit_path(t) : split_dolly_path(t),
                         {"#ff7f0e", 1.0, "none", 0.9});
            draw_frustum(doc, view, s == 0 ? coupled_orbit_path(t) : coupled_dolly_path(t),
                         {"#1f77b4", 1.0, "none", 0.9});
        }
        for (int i = 0; i < key_count; ++i) {
            const pose& key = (*keys_of[s])[static_cast<std::size_t>(i)];
            draw_frustum(doc, view, key, {"#222", 1.4});
            const v3 at = translation_of(key);
            const svg::point p = view.project(at);
            doc.circle(p, 4, {"#222", 1.0, "#222"});
            // Labels outside the orbit, on the far side of the rail from the subject.
            const v3 outward = s == 0 ? v3{at.x, at.y, 0} * 0.25 : v3{0, -1.2, 0};
            const svg::point q = view.project(at + outward);
            char text[16];
            std::snprintf(text, sizeof text, "t = %.0f s", times[static_cast<std::size_t>(i)]);
            doc.text({q.x, q.y + 12}, text, 11, "middle", "#222");
        }
    }

    // Bottom: distance from the intended arc and rail over time.
    plot::chart left{80,
                     500,
                     360,
                     200,
                     "Orbit: distance off the arc",
                     "time (s)",
                     "metres (keyframes every 2 s)",
                     0,
                     duration,
                     0,
                     0.6};
    plot::chart right{580,
                      500,
                      360,
                      200,
                      "Dolly: distance off the rail",
                      "time (s)",
                      "metres (keyframes every 2 s)",
                      0,
                      duration,
                      0,
                      0.5};
    std::vector<double> axis;
    for (int k = 0; k <= samples; ++k) axis.push_back(sample_time(k));
    plot::draw(doc, left,
               {{"split", axis, split_orbit.off, split_look},
                {"coupled", axis, coupled_orbit.off, coupled_look}});
    plot::draw(doc, right,
               {{"split", axis, split_dolly.off, split_look},
                {"coupled", axis, coupled_dolly.off, coupled_look}});
    char line[160];
    std::snprintf(line, sizeof line,
                  "split cuts inside by up to %.2f m (view axis %.1f deg off the subject);",
                  split_orbit.off_path, split_orbit.aim_miss / degree);
    doc.text({260, 760}, line, 12, "middle", "#444");
    std::snprintf(line, sizeof line, "coupled is the orbit, within %s m, at %.2f m/s",
                  tolerance_text, orbit_rate * orbit_radius);
    doc.text({260, 776}, line, 12, "middle", "#444");
    std::snprintf(line, sizeof line, "coupled bows off by up to %.2f m (speed %.2f to %.2f m/s);",
                  coupled_dolly.off_path, coupled_dolly.slowest, coupled_dolly.fastest);
    doc.text({760, 760}, line, 12, "middle", "#444");
    std::snprintf(line, sizeof line, "split is the dolly, within %s m, at %.0f m/s", tolerance_text,
                  rail_speed);
    doc.text({760, 776}, line, 12, "middle", "#444");
    doc.text(
        {500, 804},
        "Both share the orientation (rotation_spline) and pass through every keyframe (black); "
        "frusta every 0.5 s.",
        12, "middle", "#444");
    expect(doc.save(out), "camera_path.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
