// rigid_skinning: blending and interpolating rigid motions with dual quaternions.
//   Skinning: a tube skinned to two bones, the second bent 90 degrees and twisted 180 degrees about
//   the tube's axis at the elbow. Linear blend skinning averages the bones' 4x4 matrices, and the
//   average of two rotations is no rotation: half way through the elbow the identity and the half
//   turn average to a projection, and the tube collapses to a line ("candy wrapper"). quat::blend
//   (Kavan et al. 2007) averages the dual quaternions and normalizes: every vertex still moves
//   rigidly, and every ring keeps its radius.
//   ScLERP: quat::sclerp moves a body from pose a to pose b by one constant screw motion: a turn
//   about one axis line and a slide along it, both linear in t, so every point of the body moves on
//   a helix about that axis. Interpolating the translation linearly and the rotation by slerp gives
//   the same orientations, but the body cuts across the axis.
// Pictures: the two skinned tubes side by side; the screw motion beside the lerp + slerp motion.
// Run: example_rigid_skinning [output directory]  -> rigid_skinning.svg, sclerp_helix.svg
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
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

// ---- Skinning -------------------------------------------------------------------------------

// The tube: radius 0.25 from x = 0 to x = 2 along the x axis, in rings every 0.1 of 16 vertices;
// ring 10 (x = 1) is the middle ring, at the joint.
constexpr double tube_radius = 0.25;
constexpr int ring_count = 21, ring_vertices = 16, middle_ring = 10;
const v3 joint{1, 0, 0};

double ring_x(int ring) { return ring / 10.0; }

/// Bone 1's weight: smoothstep from 0 at x = 0.5 to 1 at x = 1.5 (0.5 at the joint); bone 0's is
/// 1 minus it.
double weight_1(double x) {
    const double s = std::clamp(x - 0.5, 0.0, 1.0);
    return s * s * (3 - 2 * s);
}

/// Vertex k of ring i in the rest pose; vertex 0 is on top (+z).
v3 rest_vertex(int ring, int k) {
    const double phi = 2 * numbers::pi * k / ring_vertices;
    return {ring_x(ring), -tube_radius * std::sin(phi), tube_radius * std::cos(phi)};
}

using mesh = std::vector<std::vector<v3>>;  // rings of vertices

/// The tube with every vertex moved to moved(rest vertex, bone 1's weight).
mesh skin(const std::function<v3(const v3&, double)>& moved) {
    mesh rings(ring_count);
    for (int i = 0; i < ring_count; ++i)
        for (int k = 0; k < ring_vertices; ++k)
            rings[static_cast<std::size_t>(i)].push_back(
                moved(rest_vertex(i, k), weight_1(ring_x(i))));
    return rings;
}

v3 centroid(const std::vector<v3>& points) {
    v3 sum{0, 0, 0};
    for (const v3& p : points) sum = sum + p;
    return sum / static_cast<double>(points.size());
}

/// The smallest and largest distance of a ring's vertices from the ring's centroid.
std::array<double, 2> radius_range(const std::vector<v3>& ring) {
    const v3 c = centroid(ring);
    std::array<double, 2> range{norm(ring[0] - c), norm(ring[0] - c)};
    for (const v3& p : ring) {
        range[0] = std::min(range[0], norm(p - c));
        range[1] = std::max(range[1], norm(p - c));
    }
    return range;
}

/// "#rrggbb" of rgb (0..255 each) darkened by light in [0, 1], as view3d::shade darkens.
std::string lit_colour(const double (&rgb)[3], double light) {
    char out[8];
    int c[3];
    for (int k = 0; k < 3; ++k)
        c[k] = std::clamp(static_cast<int>(rgb[k] * (0.55 + 0.45 * light)), 0, 255);
    std::snprintf(out, sizeof out, "#%02x%02x%02x", c[0], c[1], c[2]);
    return out;
}

/// The tube as shaded quads drawn back to front (painter's algorithm), tinted from bone 0's
/// colour (blue) to bone 1's (orange) by weight; the strips of quads along the top (vertex 0) and
/// the bottom (vertex 8) of the rest pose in dark red and dark green, so the twist shows.
void draw_tube(svg::document& doc, const view3d::camera& cam, const mesh& rings) {
    struct quad {
        std::array<v3, 4> corners;
        double weight;
        std::size_t stripe;  // 0 none, 1 top, 2 bottom
        long depth;  // rounded to 1e-6: ties keep the order of creation, whatever the last bits
    };
    std::vector<quad> quads;
    for (std::size_t i = 0; i + 1 < rings.size(); ++i)
        for (std::size_t k = 0; k < static_cast<std::size_t>(ring_vertices); ++k) {
            const std::size_t next = (k + 1) % static_cast<std::size_t>(ring_vertices);
            quad q{{rings[i][k], rings[i][next], rings[i + 1][next], rings[i + 1][k]},
                   (weight_1(ring_x(static_cast<int>(i))) +
                    weight_1(ring_x(static_cast<int>(i + 1)))) /
                       2,
                   k == 0   ? 1u
                   : k == 8 ? 2u
                            : 0u,
                   0};
            q.depth = std::lround(cam.depth(centroid({q.corners.begin(), q.corners.end()})) * 1e6);
            quads.push_back(q);
        }
    std::stable_sort(quads.begin(), quads.end(),
                     [](const quad& a, const quad& b) { return a.depth < b.depth; });
    const v3 light = normalize(v3{0.3, -0.5, 1.0} + cam.toward_viewer);
    const double bone_0[3] = {120, 170, 215}, bone_1[3] = {250, 175, 100};
    const double band[3][3] = {{0, 0, 0}, {175, 40, 40}, {40, 125, 40}};
    for (const quad& q : quads) {
        const v3 n = cross(q.corners[2] - q.corners[0], q.corners[3] - q.corners[1]);
        const double lit = norm(n) > 1e-12 ? std::abs(dot(n / norm(n), light)) : 0.5;
        double rgb[3];
        for (int c = 0; c < 3; ++c)
            rgb[c] =
                q.stripe > 0 ? band[q.stripe][c] : bone_0[c] + (bone_1[c] - bone_0[c]) * q.weight;
        std::vector<svg::point> outline;
        for (const v3& p : q.corners) outline.push_back(cam.project(p));
        doc.polygon(outline, {"#333", 0.4, lit_colour(rgb, lit)});
    }
}

// ---- ScLERP ---------------------------------------------------------------------------------

/// Distance of p from the line through `point` with unit `direction`.
double distance_to_line(const v3& p, const v3& point, const v3& direction) {
    return norm(cross(p - point, direction));
}

/// A box (half sizes `half`) at pose dq: its front faces, tinted by the body axis they face.
void draw_block(svg::document& doc, const view3d::camera& cam, const dual_quaterniond& dq,
                const v3& half) {
    const double h[3] = {half.x, half.y, half.z};
    const v3 at = translation_of(dq);
    v3 axis[3];
    for (int a = 0; a < 3; ++a) {
        v3 e{0, 0, 0};
        (a == 0 ? e.x : a == 1 ? e.y : e.z) = 1.0;
        axis[a] = transform_vector(dq, e);
    }
    const v3 light = normalize(v3{0.3, -0.5, 1.0} + cam.toward_viewer);
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (double sign : {1.0, -1.0}) {
            const v3 normal = axis[a] * sign;
            const v3 face_centre = at + normal * h[a];
            if (dot(normal, cam.to_eye(face_centre)) <= 0) continue;
            std::vector<svg::point> corners;
            for (auto [u, v] : {std::pair{1, 1}, {1, -1}, {-1, -1}, {-1, 1}})
                corners.push_back(
                    cam.project(face_centre + axis[b] * (u * h[b]) + axis[c] * (v * h[c])));
            const double lit = std::max(0.0, dot(normal, light));
            doc.polygon(corners, {"#333", 1.0, view3d::shade(a, sign > 0 ? 0.45 : 0.75, lit)});
        }
    }
}

/// v, or 0 when it would print as -0.0000.
double tidy(double v) { return std::abs(v) < 5e-5 ? 0.0 : v; }

std::string format(const char* pattern, double value) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

void skinning(const std::string& out) {
    using example::expect;
    std::printf("rigid_skinning: a tube on two bones, bent 90 deg and twisted 180 deg at x = 1\n");
    // Bone 1 turns the right half about the joint: first twisted a half turn about the tube's axis
    // (x), then bent 90 degrees about y, so that it hangs down. Bone 0 stays put.
    const quatd twist = to_quaternion(axis_angle<double>{{1, 0, 0}, 180 * degree});
    const quatd bend = to_quaternion(axis_angle<double>{{0, 1, 0}, 90 * degree});
    const quatd turn = bend * twist;
    const std::array<dual_quaterniond, 2> bones = {
        dual_quaterniond::identity(), to_dual_quaternion(turn, joint - rotate(turn, joint))};
    expect(norm(transform(bones[1], joint) - joint) < 1e-15, "bone 1 turns about the joint");

    // Linear blend skinning: the bones' 4x4 matrices averaged entry by entry, then applied.
    const std::array<homogeneous_matrix<double>, 2> matrices = {to_homogeneous(bones[0]),
                                                                to_homogeneous(bones[1])};
    const mesh linear = skin([&](const v3& p, double w1) {
        homogeneous_matrix<double> m{};
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                m(r, c) = (1 - w1) * matrices[0](r, c) + w1 * matrices[1](r, c);
        return transform(m, p);
    });
    // Dual-quaternion blending.
    const mesh dual = skin([&](const v3& p, double w1) {
        const std::array<double, 2> weights = {1 - w1, w1};
        return transform(blend(bones, weights), p);
    });

    const std::array<double, 2> linear_middle = radius_range(linear[middle_ring]),
                                dual_middle = radius_range(dual[middle_ring]);
    double dual_error = 0, linear_smallest = tube_radius;
    for (int i = 0; i < ring_count; ++i) {
        const auto ring = static_cast<std::size_t>(i);
        const std::array<double, 2> d = radius_range(dual[ring]);
        dual_error =
            std::max({dual_error, std::abs(d[0] - tube_radius), std::abs(d[1] - tube_radius)});
        linear_smallest = std::min(linear_smallest, radius_range(linear[ring])[0]);
    }
    std::printf(
        "  middle ring (x = 1, weights 0.5 / 0.5), distance of its vertices from its centroid:\n");
    std::printf("    linear blend skinning  %.3f to %.3f  (rest radius %.3f)\n", linear_middle[0],
                linear_middle[1], tube_radius);
    std::printf("    quat::blend            %.3f to %.3f\n", dual_middle[0], dual_middle[1]);
    std::printf("  every ring with quat::blend: radius off %.3f by at most %.1e\n", tube_radius,
                dual_error);
    expect(linear_middle[0] < 0.05, "linear blend skinning collapses the middle ring (< 0.05)");
    expect(linear_smallest == linear_middle[0], "... and it is the thinnest ring");
    expect(std::abs(dual_middle[0] - tube_radius) < 0.05 * tube_radius &&
               std::abs(dual_middle[1] - tube_radius) < 0.05 * tube_radius,
           "quat::blend keeps the middle ring's radius within 5%");
    expect(dual_error < 1e-12, "quat::blend moves every ring rigidly: radius 0.25 within 1e-12");
    // The far end is bone 1's alone under both (weight 1): the two meshes agree there.
    double tip_difference = 0;
    for (int k = 0; k < ring_vertices; ++k)
        tip_difference =
            std::max(tip_difference, norm(linear[ring_count - 1][static_cast<std::size_t>(k)] -
                                          dual[ring_count - 1][static_cast<std::size_t>(k)]));
    expect(tip_difference < 1e-12, "where one bone has all the weight, both agree");

    svg::document doc(1000, 520);
    doc.text({500, 28},
             "Skinning a tube to two bones, bent 90 deg and twisted 180 deg at the elbow", 17,
             "middle", "#222", true);
    const char* const titles[2] = {"linear blend skinning: candy wrapper",
                                   "quat::blend (dual quaternions)"};
    const mesh* meshes[2] = {&linear, &dual};
    for (int panel = 0; panel < 2; ++panel) {
        const double middle = 250 + 500 * panel;
        const auto view =
            view3d::camera::looking_from(-40 * degree, 37 * degree, {middle - 5, 170}, 190);
        doc.text({middle, 72}, titles[panel], 14, "middle", "#222", true);
        draw_tube(doc, view, *meshes[panel]);
        // The middle ring's centre (the joint under both), labelled to the left.
        const svg::point at = view.project(joint);
        doc.line(at, {at.x - 90, at.y + 40}, {"#222", 1.0});
        doc.circle(at, 2.5, {"#222", 1.0, "#222"});
        doc.text({at.x - 94, at.y + 44}, "middle ring", 12, "end", "#222");
        doc.text({at.x - 94, at.y + 59}, "weights 0.5 / 0.5", 11, "end", "#444");
    }
    const std::string linear_text = "middle ring: radius " + format("%.3f", linear_middle[0]) +
                                    " to " + format("%.3f", linear_middle[1]) + " (rest " +
                                    format("%.2f", tube_radius) + ")";
    const std::string dual_text = "middle ring: radius " + format("%.3f", dual_middle[0]) + " to " +
                                  format("%.3f", dual_middle[1]) + "; every ring moves rigidly";
    doc.text({250, 470}, linear_text, 12, "middle", "#444");
    doc.text({750, 470}, dual_text, 12, "middle", "#444");
    doc.text({500, 496},
             "Weights blue (bone 0) to orange (bone 1), a smoothstep over 0.5 <= x <= 1.5; stripes "
             "along the top (red) and bottom (green).",
             12, "middle", "#444");
    doc.text({500, 512},
             "Averaged matrices are no rotation: the identity and a half turn average to a "
             "projection onto the half turn's axis.",
             12, "middle", "#444");
    expect(doc.save(out), "rigid_skinning.svg written");
    std::printf("  wrote %s\n", out.c_str());
}

void screw_motion(const std::string& out) {
    using example::expect;
    std::printf("sclerp: a box from pose a to pose b\n");
    // Pose a: 1.2 from the vertical axis through the origin, at azimuth -60 degrees, tilted. Pose
    // b: pose a moved by a screw about that axis, a turn of 160 degrees and a slide of 1.8 up it.
    const double start = -60 * degree;
    const dual_quaterniond a = to_dual_quaternion(
        to_quaternion(axis_angle<double>{{0, 0, 1}, start}) *
            to_quaternion(axis_angle<double>{normalize(v3{0.3, 1, 0.2}), 35 * degree}),
        v3{1.2 * std::cos(start), 1.2 * std::sin(start), 0});
    const screw<double> world_screw{{0, 0, 1}, {0, 0, 0}, 160 * degree, 1.8};
    const dual_quaterniond b = from_screw(world_screw) * a;

    // The relative motion a^-1 b in a's frame, and its axis line mapped to the world by a.
    const dual_quaterniond relative = inverse(a) * b;
    const screw<double> whole = to_screw(relative);
    const v3 axis_direction = transform_vector(a, whole.direction),
             axis_point = transform(a, cross(whole.direction, whole.moment));
    std::printf("  screw of a^-1 b: angle %.4f deg, displacement %.4f along the axis\n",
                whole.angle / degree, whole.displacement);
    std::printf("  axis in the world: direction (%.4f, %.4f, %.4f) through (%.4f, %.4f, %.4f)\n",
                tidy(axis_direction.x), tidy(axis_direction.y), tidy(axis_direction.z),
                tidy(axis_point.x), tidy(axis_point.y), tidy(axis_point.z));
    // The same line as the screw of b a^-1 read in the world directly, and as the one built.
    const screw<double> in_world = to_screw(b * inverse(a));
    expect(norm(axis_direction - world_screw.direction) < 1e-12 &&
               norm(axis_point - v3{0, 0, 0}) < 1e-12,
           "a maps the axis of a^-1 b onto the screw's axis in the world");
    expect(norm(in_world.direction - axis_direction) < 1e-12 &&
               norm(in_world.moment - cross(axis_point, axis_direction)) < 1e-12 &&
               std::abs(in_world.angle - whole.angle) < 1e-12 &&
               std::abs(in_world.displacement - whole.displacement) < 1e-12,
           "... which is the axis of b a^-1, with the same angle and displacement");

    // Linearity: the screw of a^-1 sclerp(a, b, t) is t times the whole one, on the same line.
    double linear_error = 0, line_error = 0, distance_error = 0, slerp_error = 0;
    const v3 half{0.16, 0.1, 0.06};
    std::vector<v3> body_points = {{0, 0, 0}};
    for (const double x : {-half.x, half.x})
        for (const double y : {-half.y, half.y})
            for (const double z : {-half.z, half.z}) body_points.push_back({x, y, z});
    std::vector<double> start_distance;
    for (const v3& p : body_points)
        start_distance.push_back(distance_to_line(transform(a, p), axis_point, axis_direction));
    constexpr int path_samples = 120;
    for (int k = 0; k <= path_samples; ++k) {
        const double t = static_cast<double>(k) / path_samples;
        const dual_quaterniond at = sclerp(a, b, t);
        const screw<double> part = to_screw(inverse(a) * at);
        linear_error = std::max({linear_error, std::abs(part.angle - t * whole.angle),
                                 std::abs(part.displacement - t * whole.displacement)});
        if (k > 0)
            line_error = std::max({line_error, norm(part.direction - whole.direction),
                                   norm(part.moment - whole.moment)});
        for (std::size_t i = 0; i < body_points.size(); ++i)
            distance_error =
                std::max(distance_error, std::abs(distance_to_line(transform(at, body_points[i]),
                                                                   axis_point, axis_direction) -
                                                  start_distance[i]));
        slerp_error = std::max(slerp_error, angle_between(at.real, slerp(a.real, b.real, t)));
    }
    std::printf("  over %d values of t in [0, 1]:\n", path_samples + 1);
    std::printf("    |angle(t) - t angle|, |displacement(t) - t displacement|  <= %.1e\n",
                linear_error);
    std::printf("    axis line of a^-1 sclerp(a, b, t) off a^-1 b's            <= %.1e\n",
                line_error);
    std::printf("    distance of the box's centre and corners from the axis varies <= %.1e\n",
                distance_error);
    std::printf("    rotation off slerp(a, b, t)                                <= %.1e rad\n",
                slerp_error);
    expect(linear_error < 1e-12, "the angle and the displacement grow linearly in t (1e-12)");
    expect(line_error < 1e-12, "about one fixed axis line (1e-12)");
    expect(distance_error < 1e-12,
           "every point of the box stays at a constant distance from the axis (1e-12)");
    expect(slerp_error < 1e-12, "the rotations are slerp's");

    // The contrast: translation interpolated linearly, rotation by slerp.
    const auto lerp_slerp = [&](double t) {
        return to_dual_quaternion(slerp(a.real, b.real, t),
                                  translation_of(a) * (1 - t) + translation_of(b) * t);
    };
    double nearest = start_distance[0];
    for (int k = 0; k <= path_samples; ++k)
        nearest = std::min(
            nearest,
            distance_to_line(translation_of(lerp_slerp(static_cast<double>(k) / path_samples)),
                             axis_point, axis_direction));
    std::printf("  lerp + slerp: the box's centre comes within %.3f of the axis (sclerp: %.3f)\n",
                nearest, start_distance[0]);
    expect(nearest < 0.5 * start_distance[0], "lerp + slerp cuts across, near the axis");

    svg::document doc(1000, 550);
    doc.text({500, 28}, "From pose a to pose b: quat::sclerp turns and slides about one axis", 17,
             "middle", "#222", true);
    const char* const titles[2] = {"quat::sclerp(a, b, t): a helix about the screw axis",
                                   "lerp of translation, slerp of rotation"};
    const std::function<dual_quaterniond(double)> motions[2] = {
        [&](double t) { return sclerp(a, b, t); }, lerp_slerp};
    constexpr int poses = 12;
    for (int panel = 0; panel < 2; ++panel) {
        const double middle = 250 + 500 * panel;
        const auto view =
            view3d::camera::looking_from(-70 * degree, 25 * degree, {middle, 380}, 112);
        doc.text({middle, 72}, titles[panel], 14, "middle", "#222", true);
        // The screw axis, dashed, and circles about it at the heights of a and b.
        const v3 bottom = axis_point - axis_direction * 0.4,
                 top = axis_point + axis_direction * 2.2;
        for (const v3& centre : {translation_of(a), translation_of(b)}) {
            const v3 foot = axis_point + axis_direction * dot(centre - axis_point, axis_direction);
            std::vector<svg::point> circle;
            for (int k = 0; k <= 96; ++k) {
                const double phi = 2 * numbers::pi * k / 96;
                circle.push_back(
                    view.project(foot + v3{std::cos(phi), std::sin(phi), 0} * start_distance[0]));
            }
            doc.polyline(circle, {"#bbb", 1.0, "none", 1.0, "2 3"});
        }
        doc.line(view.project(bottom), view.project(top), {"#555", 1.2, "none", 1.0, "8 5"});
        const svg::point label = view.project(bottom);
        doc.text({label.x - 8, label.y + 4}, "screw axis", 12, "end", "#555");
        // Paths of the centre and of one corner.
        for (std::size_t p : {std::size_t{0}, std::size_t{8}}) {
            std::vector<svg::point> path;
            for (int k = 0; k <= path_samples; ++k)
                path.push_back(view.project(transform(
                    motions[panel](static_cast<double>(k) / path_samples), body_points[p])));
            doc.polyline(path, p == 0 ? svg::style{"#222", 1.5}
                                      : svg::style{"#9467bd", 1.2, "none", 1.0, "4 3"});
        }
        // The poses, back to front, each with its distance to the axis drawn across to it.
        std::vector<std::pair<double, int>> order;
        for (int k = 0; k < poses; ++k) {
            const v3 centre = translation_of(motions[panel](static_cast<double>(k) / (poses - 1)));
            order.push_back({std::round(view.depth(centre) * 1e6), k});
            const v3 foot = axis_point + axis_direction * dot(centre - axis_point, axis_direction);
            doc.line(view.project(foot), view.project(centre), {"#aaa", 1.0});
        }
        std::sort(order.begin(), order.end());
        for (const auto& [depth, k] : order)
            draw_block(doc, view, motions[panel](static_cast<double>(k) / (poses - 1)), half);
        for (const double t : {0.0, 1.0}) {
            const svg::point p = view.project(translation_of(motions[panel](t)));
            doc.text({p.x + 30, p.y + 5}, t == 0 ? "a" : "b", 15, "middle", "#222", true);
        }
    }
    doc.text({250, 484}, "angle and slide about the axis both linear in t; every point", 12,
             "middle", "#444");
    doc.text({250, 500}, "of the box keeps its distance from the axis (a helix)", 12, "middle",
             "#444");
    doc.text({750, 484}, "the same orientations; the centre moves on a straight line", 12, "middle",
             "#444");
    doc.text({750, 500},
             "and passes " + format("%.2f", nearest) +
                 " from the axis (sclerp: " + format("%.2f", start_distance[0]) + ")",
             12, "middle", "#444");
    doc.text({500, 530},
             "12 poses at t = 0, 1/11, ..., 1; solid: path of the centre, dashed: of a corner; "
             "grey: distance to the axis.",
             12, "middle", "#444");
    expect(doc.save(out), "sclerp_helix.svg written");
    std::printf("  wrote %s\n", out.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    const std::string dir = argc > 1 ? std::string(argv[1]) : std::string(".");
    skinning(dir + "/rigid_skinning.svg");
    screw_motion(dir + "/sclerp_helix.svg");
    return example::failures() == 0 ? 0 : 1;
}
