// The picture of the camera_imu_spline example (not part of the library): a top view of the path,
// the errors over time, and the fitted velocity, acceleration and angular velocity against the
// truth, with tables of the biases and the RMS errors.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "camera_imu_run.hpp"
#include "plot.hpp"
#include "svg.hpp"

namespace picture {

using camera_imu::state;
using camera_imu::v3;

/// Rows of text: the first is a bold header, the first column is left-aligned, the others are
/// right-aligned at `right_edges`.
using table = std::vector<std::vector<std::string>>;

/// printf into a string, for the picture's short texts.
template <class... Arguments>
std::string text(const char* format, Arguments... arguments) {
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, format, arguments...);
    return buffer;
}

inline const char* const axis_colour[3] = {"#d62728", "#2ca02c", "#1f77b4"};  // x, y, z
inline const char* const axis_label[3] = {"x", "y", "z"};

/// One curve per axis of `member` at every `stride`-th time: thin for the fit, wide and pale for
/// the truth.
inline void add_components(std::vector<plot::series>& curves, const std::vector<double>& times,
                           const std::vector<state>& states, v3 state::*member, bool is_truth,
                           std::size_t stride) {
    for (int axis = 0; axis < 3; ++axis) {
        plot::series s{axis_label[axis],
                       {},
                       {},
                       {axis_colour[axis], is_truth ? 5.0 : 1.2, "none", is_truth ? 0.3 : 1.0}};
        for (std::size_t i = 0; i < times.size(); i += stride) {
            const v3& v = states[i].*member;
            s.x.push_back(times[i]);
            s.y.push_back(axis == 0 ? v.x : axis == 1 ? v.y : v.z);
        }
        curves.push_back(std::move(s));
    }
}

inline void draw_table(svg::document& doc, double left, double top,
                       const std::vector<double>& right_edges, const table& rows) {
    double y = top;
    for (std::size_t r = 0; r < rows.size(); ++r, y += 18) {
        for (std::size_t c = 0; c < rows[r].size(); ++c) {
            if (c == 0) doc.text({left, y}, rows[r][c], 12, "start", "#222", r == 0);
            else if (c - 1 < right_edges.size())
                doc.text({left + right_edges[c - 1], y}, rows[r][c], 12, "end", "#222", r == 0);
        }
    }
}

/// Rows "<sensor> <axis> (<unit>)": the true bias, the fitted one, and the error over the
/// standard error.
inline void add_bias_rows(table& rows, const char* sensor, const char* unit, const v3& truth,
                          const v3& fitted, const v3& sigma) {
    const double t[] = {truth.x, truth.y, truth.z}, f[] = {fitted.x, fitted.y, fitted.z},
                 s[] = {sigma.x, sigma.y, sigma.z};
    for (std::size_t axis = 0; axis < 3; ++axis)
        rows.push_back({std::string(sensor) + " " + axis_label[axis] + " (" + unit + ")",
                        text("%.4f", t[axis]), text("%.4f", f[axis]),
                        text("%.1f", (f[axis] - t[axis]) / s[axis])});
}

/// The RMS errors of both fits and of the camera's poses (which have no derivatives).
inline table error_table(const camera_imu::rms_errors& split, const camera_imu::rms_errors& se3,
                         const camera_imu::rms_errors& camera) {
    const double degree = quat::numbers::pi / 180;
    return {{"", "split", "SE(3)", "camera"},
            {"position (mm)", text("%.2f", 1e3 * split.position), text("%.2f", 1e3 * se3.position),
             text("%.2f", 1e3 * camera.position)},
            {"orientation (°)", text("%.3f", split.orientation / degree),
             text("%.3f", se3.orientation / degree), text("%.3f", camera.orientation / degree)},
            {"velocity (mm/s)", text("%.2f", 1e3 * split.velocity),
             text("%.2f", 1e3 * se3.velocity), ""},
            {"acceleration (m/s²)", text("%.4f", split.acceleration),
             text("%.4f", se3.acceleration), ""},
            {"angular velocity (rad/s)", text("%.5f", split.angular_velocity),
             text("%.5f", se3.angular_velocity), ""}};
}

/// Writes the picture; false if the file cannot be written.
inline bool draw(const std::string& path, const std::string& subtitle,
                 const std::vector<double>& times, const std::vector<state>& truth,
                 const std::vector<state>& fitted, const std::vector<v3>& camera_positions,
                 const table& biases, const table& errors) {
    svg::document doc(1000, 1030);
    doc.text({500, 30}, "A B-spline fitted to a camera-IMU run with Ceres", 18, "middle", "#222",
             true);
    doc.text({500, 52}, subtitle, 12, "middle", "#444");
    // One legend for every chart.
    double x = 250;
    for (int axis = 0; axis < 3; ++axis, x += 48) {
        doc.line({x, 74}, {x + 22, 74}, {axis_colour[axis], 2.0});
        doc.text({x + 27, 78}, axis_label[axis], 12);
    }
    doc.line({x + 10, 74}, {x + 36, 74}, {"#222", 1.2});
    doc.text({x + 41, 78}, "fitted spline", 12);
    doc.line({x + 140, 74}, {x + 166, 74}, {"#222", 5.0, "none", 0.3});
    doc.text({x + 171, 78}, "truth", 12);
    doc.circle({x + 230, 74}, 2.2, {"#ff7f0e", 0.0, "#ff7f0e"});
    doc.text({x + 238, 78}, "camera", 12);

    const double left = 75, right = 575, width = 385, height = 215;
    const std::size_t stride = 10;  // the curves at 20 Hz: smooth at this size, files stay small

    plot::chart top_view{left, 140, width, height, "Path seen from above", "x (m)", "y (m)",
                         -2.5, 2.5, -1.4,  1.4};
    top_view.legend = false;
    plot::series truth_path{"truth", {}, {}, {"#222", 5.0, "none", 0.3}};
    plot::series fitted_path{"fitted", {}, {}, {"#222", 1.2}};
    const auto add_point = [&](std::size_t i) {
        truth_path.x.push_back(truth[i].position.x);
        truth_path.y.push_back(truth[i].position.y);
        fitted_path.x.push_back(fitted[i].position.x);
        fitted_path.y.push_back(fitted[i].position.y);
    };
    for (std::size_t i = 0; i < times.size(); i += stride) add_point(i);
    add_point(times.size() - 1);  // the last time too, so the path closes
    plot::draw(doc, top_view, {truth_path, fitted_path});
    // Translucent, so the fitted path shows through.
    for (const v3& p : camera_positions)
        doc.circle({left + (p.x + 2.5) / 5.0 * width, 140 + (1.4 - p.y) / 2.8 * height}, 1.5,
                   {"#ff7f0e", 0.0, "#ff7f0e", 0.7});

    plot::chart error_chart{
        right,         140,          width, height, "Fitted minus truth (magnitudes)", "t (s)", "",
        times.front(), times.back(), 1e-7,  1};
    error_chart.log_y = true;
    error_chart.legend_top_left = false;
    error_chart.legend_down = 0.58;        // below the curves
    std::vector<plot::series> error_curves{// Colours apart from the axes' red, green and blue.
                                           {"position (m)", {}, {}, {"#8c564b", 1.0}},
                                           {"orientation (rad)", {}, {}, {"#9467bd", 1.0}},
                                           {"velocity (m/s)", {}, {}, {"#17becf", 1.2}},
                                           {"acceleration (m/s²)", {}, {}, {"#e377c2", 1.0}}};
    for (std::size_t i = 0; i < times.size(); i += stride) {
        const state &a = fitted[i], &b = truth[i];
        const double values[] = {
            quat::norm(a.position - b.position), quat::angle_between(a.rotation, b.rotation),
            quat::norm(a.velocity - b.velocity), quat::norm(a.acceleration - b.acceleration)};
        for (std::size_t k = 0; k < 4; ++k) {
            error_curves[k].x.push_back(times[i]);
            error_curves[k].y.push_back(values[k]);
        }
    }
    plot::draw(doc, error_chart, error_curves);

    const auto time_chart = [&](double chart_left, double top, const char* title, const char* unit,
                                double range, v3 state::*member) {
        plot::chart c{chart_left, top,           width,        height, title, "t (s)",
                      unit,       times.front(), times.back(), -range, range};
        c.legend = false;
        std::vector<plot::series> curves;
        // The truth is a sum of slow sines: 10 Hz draws it as smoothly as 20 Hz under its width.
        add_components(curves, times, truth, member, true, 2 * stride);
        add_components(curves, times, fitted, member, false, stride);
        plot::draw(doc, c, curves);
    };
    time_chart(left, 445, "Linear velocity p' (world frame)", "m/s", 2.0, &state::velocity);
    time_chart(right, 445, "Linear acceleration p'' (world frame)", "m/s²", 2.5,
               &state::acceleration);
    time_chart(left, 750, "Angular velocity (body frame)", "rad/s", 2.0, &state::angular_velocity);

    doc.text({right, 735}, "Biases", 14, "start", "#222", true);
    draw_table(doc, right, 758, {215, 290, 385}, biases);
    doc.text({right, 895}, "RMS against truth", 14, "start", "#222", true);
    draw_table(doc, right, 918, {215, 300, 385}, errors);
    return doc.save(path);
}

}  // namespace picture
