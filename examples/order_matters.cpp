// order_matters (thesis Fig. 2.1): a bar turned 90 degrees about x then y ends in a different pose
// from the same bar turned about y then x, because rotations, like quaternion products, do not
// commute. Run: example_order_matters [output directory] -> order_matters.svg
#include <cstdio>
#include <string>

#include <quat/quat.hpp>

#include "check.hpp"
#include "svg.hpp"
#include "view3d.hpp"

using namespace quat;
using view3d::v3;

namespace {

double rotation_angle(const quatd& from, const quatd& to) {
    return to_axis_angle(conjugate(from) * to).angle;
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/order_matters.svg";

    const quatd qx = to_quaternion(axis_angle<double>{{1, 0, 0}, numbers::pi / 2});
    const quatd qy = to_quaternion(axis_angle<double>{{0, 1, 0}, numbers::pi / 2});
    // a * b applies b first: "x then y" is qy * qx.
    const quatd x_then_y = qy * qx, y_then_x = qx * qy;

    std::printf("order_matters: a bar (long along y) turned 90 deg about x and about y\n");
    const v3 long_axis{0, 1, 0};
    const v3 end_xy = rotate(x_then_y, long_axis), end_yx = rotate(y_then_x, long_axis);
    std::printf("  x then y: long axis ends at (%+.3f, %+.3f, %+.3f)\n", end_xy.x, end_xy.y,
                end_xy.z);
    std::printf("  y then x: long axis ends at (%+.3f, %+.3f, %+.3f)\n", end_yx.x, end_yx.y,
                end_yx.z);
    expect(norm(end_xy - v3{1, 0, 0}) < 1e-12, "x then y lays the bar along +x");
    expect(norm(end_yx - v3{0, 0, 1}) < 1e-12, "y then x stands the bar up along +z");
    const double apart = rotation_angle(x_then_y, y_then_x);
    std::printf("  the two final poses differ by a rotation of %.1f deg\n",
                apart * 180 / numbers::pi);
    expect(apart > 1.0, "qy * qx != qx * qy: the order matters");
    const rotation_matrix<double> mx = to_matrix(qx), my = to_matrix(qy);
    expect(angle_between(to_quaternion(my * mx), x_then_y) < 1e-12,
           "matrices compose in the same order (My Mx)");

    const double cell_w = 300, cell_h = 270, top = 40;
    svg::document doc(3 * cell_w, top + 2 * cell_h + 40);
    doc.text({3 * cell_w / 2, 24},
             "Rotation order matters (thesis Fig. 2.1): 90 deg turns about x and y", 17, "middle",
             "#222", true);
    const quatd rows[2][3] = {{quatd::identity(), qx, x_then_y}, {quatd::identity(), qy, y_then_x}};
    const char* labels[2][3] = {{"start", "90 deg about x", "then 90 deg about y"},
                                {"start", "90 deg about y", "then 90 deg about x"}};
    const char* row_titles[2] = {"x first:  q = q_y * q_x", "y first:  q = q_x * q_y"};
    for (int r = 0; r < 2; ++r) {
        for (int c = 0; c < 3; ++c) {
            const double x0 = c * cell_w, y0 = top + r * cell_h;
            const auto cam = view3d::camera::looking_from(
                0.6, 0.45, {x0 + cell_w / 2, y0 + cell_h / 2 + 22}, 62, 9.0);
            view3d::draw_world_axes(doc, cam, 1.9);
            view3d::draw_box(doc, cam, rows[r][c], {0.3, 1.0, 0.12}, {0, 0, 0}, 1.45);
            doc.text({x0 + cell_w / 2, y0 + cell_h - 8}, labels[r][c], 13, "middle");
            if (c > 0)
                doc.arrow({x0 - 22, y0 + cell_h / 2}, {x0 + 8, y0 + cell_h / 2}, {"#555", 2.0});
        }
        doc.text({8, top + r * cell_h + 16}, row_titles[r], 14, "start", "#222", true);
    }
    doc.text({3 * cell_w / 2, top + 2 * cell_h + 25},
             "Positive angles turn counter-clockwise seen from the axis tip (the thesis says "
             "clockwise; see docs/thesis-notes.md).",
             12, "middle", "#555");
    expect(doc.save(out), "order_matters.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
