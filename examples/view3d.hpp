// 3D drawing for quat's examples (not part of the library): a camera with orthographic or
// perspective projection, a shaded box with its body axes, world axes, a wire sphere and paths on
// it. World convention of the pictures: right-handed, z up.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <quat/quat.hpp>

#include "svg.hpp"

namespace view3d {

using v3 = quat::vec3<double>;

inline const std::string axis_colour[3] = {"#d62728", "#2ca02c",
                                           "#1f77b4"};  // x red, y green, z blue
inline const char* const axis_name[3] = {"x", "y", "z"};

/// Looks at the origin from direction `toward_viewer`; distance 0 means orthographic projection.
struct camera {
    v3 toward_viewer, right, up;
    double distance;
    svg::point centre;
    double scale;  // pixels per unit at the origin

    /// Camera on the ray of the given azimuth (from +x toward +y) and elevation (radians) above the
    /// xy-plane.
    static camera looking_from(double azimuth, double elevation, svg::point centre, double scale,
                               double distance = 0.0) {
        const v3 d{std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                   std::sin(elevation)};
        const v3 r = quat::normalize(quat::cross(v3{0, 0, 1}, d));
        return {d, r, quat::cross(d, r), distance, centre, scale};
    }

    /// Larger is nearer to the viewer.
    [[nodiscard]] double depth(const v3& p) const { return quat::dot(p, toward_viewer); }

    [[nodiscard]] svg::point project(const v3& p) const {
        const double f = distance > 0 ? distance / (distance - depth(p)) : 1.0;
        return {centre.x + scale * f * quat::dot(p, right),
                centre.y - scale * f * quat::dot(p, up)};
    }

    /// Unit vector from p toward the eye (constant for orthographic projection).
    [[nodiscard]] v3 to_eye(const v3& p) const {
        return distance > 0 ? quat::normalize(toward_viewer * distance - p) : toward_viewer;
    }
};

/// "#rrggbb" of an axis colour mixed with white (tint in [0, 1]) and darkened by light in [0, 1].
inline std::string shade(int axis, double tint, double light) {
    static const int rgb[3][3] = {{214, 39, 40}, {44, 160, 44}, {31, 119, 180}};
    char out[8];
    int c[3];
    for (int k = 0; k < 3; ++k) {
        const double mixed = rgb[axis][k] + (255 - rgb[axis][k]) * tint;
        c[k] = std::clamp(static_cast<int>(mixed * (0.55 + 0.45 * light)), 0, 255);
    }
    std::snprintf(out, sizeof out, "#%02x%02x%02x", c[0], c[1], c[2]);
    return out;
}

/// Thin dashed world axes from the origin, labelled.
inline void draw_world_axes(svg::document& doc, const camera& cam, double length) {
    for (int a = 0; a < 3; ++a) {
        v3 tip{0, 0, 0};
        (a == 0 ? tip.x : a == 1 ? tip.y : tip.z) = length;
        doc.arrow(cam.project({0, 0, 0}), cam.project(tip), {"#888", 1.0, "none", 1.0, "4 3"}, 7);
        const svg::point p = cam.project(tip * 1.1);
        doc.text({p.x, p.y + 4}, axis_name[a], 12, "middle", "#888");
    }
}

/// A box with half sizes `half` turned by the unit quaternion q and moved to `at`, faces tinted by
/// the body axis they face (x red, y green, z blue), with its body axes drawn as arrows of
/// `axis_length`.
inline void draw_box(svg::document& doc, const camera& cam, const quat::quatd& q, const v3& half,
                     const v3& at, double axis_length) {
    const double h[3] = {half.x, half.y, half.z};
    v3 axis[3];
    for (int a = 0; a < 3; ++a) {
        v3 e{0, 0, 0};
        (a == 0 ? e.x : a == 1 ? e.y : e.z) = 1.0;
        axis[a] = quat::rotate(q, e);
    }
    const v3 light = quat::normalize(v3{0.3, -0.5, 1.0} + cam.toward_viewer);
    struct arrow_part {
        svg::point from, to;
        int axis;
        bool front;
    };
    std::vector<arrow_part> outer;
    // Inner halves of the axes, hidden by the faces drawn over them.
    for (int a = 0; a < 3; ++a) {
        doc.line(cam.project(at), cam.project(at + axis[a] * h[a]), {axis_colour[a], 2.0});
        const bool front = quat::dot(axis[a], cam.to_eye(at + axis[a] * h[a])) > 0;
        outer.push_back(
            {cam.project(at + axis[a] * h[a]), cam.project(at + axis[a] * axis_length), a, front});
    }
    for (const arrow_part& part : outer)
        if (!part.front) doc.arrow(part.from, part.to, {axis_colour[part.axis], 2.0});
    // Front faces only: the box is convex, so no sorting is needed.
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (double sign : {1.0, -1.0}) {
            const v3 normal = axis[a] * sign;
            const v3 face_centre = at + normal * h[a];
            if (quat::dot(normal, cam.to_eye(face_centre)) <= 0) continue;
            std::vector<svg::point> corners;
            for (auto [u, v] : {std::pair{1, 1}, {1, -1}, {-1, -1}, {-1, 1}})
                corners.push_back(
                    cam.project(face_centre + axis[b] * (u * h[b]) + axis[c] * (v * h[c])));
            const double lit = std::max(0.0, quat::dot(normal, light));
            doc.polygon(corners, {"#333", 1.0, shade(a, sign > 0 ? 0.45 : 0.75, lit), 0.92});
        }
    }
    for (const arrow_part& part : outer) {
        if (!part.front) continue;
        doc.arrow(part.from, part.to, {axis_colour[part.axis], 2.0});
    }
    for (int a = 0; a < 3; ++a) {
        const svg::point p = cam.project(at + axis[a] * (axis_length * 1.13));
        doc.text({p.x, p.y + 5}, axis_name[a], 14, "middle", axis_colour[a], true);
    }
}

/// Points p0..p1 split into runs on the near (front) and far side of the origin's depth plane.
inline void draw_sphere_path(svg::document& doc, const camera& cam, const std::vector<v3>& path,
                             const svg::style& front) {
    std::vector<svg::point> run;
    bool run_front = true;
    auto flush = [&] {
        if (run.size() > 1) {
            svg::style s = front;
            if (!run_front) {
                s.dash = "3 4";
                s.opacity = 0.5;
            }
            doc.polyline(run, s);
        }
        run.clear();
    };
    for (const v3& p : path) {
        const bool is_front = cam.depth(p) >= 0;
        if (!run.empty() && is_front != run_front) {
            const svg::point last = run.back();
            flush();
            run.push_back(last);
        }
        run_front = is_front;
        run.push_back(cam.project(p));
    }
    flush();
}

/// Wire-frame unit sphere of radius r: outline, equator and meridians every 30 degrees.
inline void draw_sphere(svg::document& doc, const camera& cam, double r) {
    const double pi = quat::numbers::pi;
    doc.circle(cam.project({0, 0, 0}), r * cam.scale, {"#999", 1.0, "#f7f7f7"});
    const svg::style grid{"#bbb", 0.8};
    for (int latitude = -60; latitude <= 60; latitude += 30) {
        std::vector<v3> ring;
        const double phi = latitude * pi / 180;
        for (int k = 0; k <= 120; ++k) {
            const double t = 2 * pi * k / 120;
            ring.push_back(
                v3{std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)} * r);
        }
        draw_sphere_path(doc, cam, ring, grid);
    }
    for (int longitude = 0; longitude < 180; longitude += 30) {
        std::vector<v3> ring;
        const double lambda = longitude * pi / 180;
        for (int k = 0; k <= 120; ++k) {
            const double t = 2 * pi * k / 120;
            ring.push_back(
                v3{std::cos(t) * std::cos(lambda), std::cos(t) * std::sin(lambda), std::sin(t)} *
                r);
        }
        draw_sphere_path(doc, cam, ring, grid);
    }
}

}  // namespace view3d
