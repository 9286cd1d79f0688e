// Line charts for quat's examples (not part of the library): axes, ticks, optional log scale,
// legend.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "svg.hpp"

namespace plot {

/// One curve: y over x, drawn with `look`.
struct series {
    std::string label;
    std::vector<double> x, y;
    svg::style look;
};

/// A chart occupying the rectangle (left, top, width, height) of the document.
struct chart {
    double left, top, width, height;
    std::string title, x_label, y_label;
    double x_min, x_max, y_min, y_max;
    bool log_y = false;
    bool legend_top_left = true;
    double legend_down = 0.0;  // legend's top edge, as a fraction of the height below the top
    bool legend = true;        // false: the caller draws one elsewhere
};

inline std::string format_tick(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
    return buffer;
}

/// Tick step 1, 2 or 5 times a power of ten giving about `count` ticks over span.
inline double nice_step(double span, int count) {
    const double raw = span / count, power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (raw <= m * power) return m * power;
    return 10 * power;
}

inline void draw(svg::document& doc, const chart& c, const std::vector<series>& curves) {
    const auto y_value = [&](double y) { return c.log_y ? std::log10(std::max(y, 1e-300)) : y; };
    const double y0 = y_value(c.y_min), y1 = y_value(c.y_max);
    const auto map = [&](double x, double y) {
        const double fy = (std::clamp(y_value(y), y0, y1) - y0) / (y1 - y0);
        return svg::point{c.left + (x - c.x_min) / (c.x_max - c.x_min) * c.width,
                          c.top + c.height * (1 - fy)};
    };
    const svg::style grid{"#e3e3e3", 1.0};
    const svg::style frame{"#444", 1.0};
    // Vertical grid and x ticks.
    const double x_step = nice_step(c.x_max - c.x_min, 5);
    for (double x = std::ceil(c.x_min / x_step) * x_step; x <= c.x_max + 1e-9 * x_step;
         x += x_step) {
        const svg::point p = map(x, c.y_min);
        doc.line({p.x, c.top}, {p.x, c.top + c.height}, grid);
        doc.text({p.x, c.top + c.height + 16}, format_tick(x), 11, "middle", "#444");
    }
    // Horizontal grid and y ticks: decades on a log axis, nice steps otherwise.
    if (c.log_y) {
        for (double e = std::ceil(y0); e <= y1 + 1e-9; e += 1) {
            const svg::point p = map(c.x_min, std::pow(10.0, e));
            doc.line({c.left, p.y}, {c.left + c.width, p.y}, grid);
            doc.text({c.left - 6, p.y + 4}, std::string("1e") + format_tick(e), 11, "end", "#444");
        }
    } else {
        const double y_step = nice_step(c.y_max - c.y_min, 5);
        for (double y = std::ceil(c.y_min / y_step) * y_step; y <= c.y_max + 1e-9 * y_step;
             y += y_step) {
            const svg::point p = map(c.x_min, y);
            doc.line({c.left, p.y}, {c.left + c.width, p.y}, grid);
            doc.text({c.left - 6, p.y + 4}, format_tick(y), 11, "end", "#444");
        }
    }
    doc.polygon({{c.left, c.top},
                 {c.left + c.width, c.top},
                 {c.left + c.width, c.top + c.height},
                 {c.left, c.top + c.height}},
                frame);
    doc.text({c.left + c.width / 2, c.top - 30}, c.title, 14, "middle", "#222", true);
    doc.text({c.left + c.width / 2, c.top + c.height + 34}, c.x_label, 12, "middle");
    doc.text({c.left - 8, c.top - 9}, c.y_label, 12, "start");
    for (const series& s : curves) {
        std::vector<svg::point> points;
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
            points.push_back(map(s.x[i], s.y[i]));
        doc.polyline(points, s.look);
    }
    if (!c.legend) return;
    // Legend in a corner box.
    std::size_t longest = 0;
    for (const series& s : curves) longest = std::max(longest, s.label.size());
    const double row = 17, legend_width = 52 + 6.3 * static_cast<double>(longest);
    const double lx = c.legend_top_left ? c.left + 10 : c.left + c.width - legend_width - 10;
    double ly = c.top + 10 + c.legend_down * c.height;
    doc.polygon({{lx, ly},
                 {lx + legend_width, ly},
                 {lx + legend_width, ly + row * static_cast<double>(curves.size()) + 6},
                 {lx, ly + row * static_cast<double>(curves.size()) + 6}},
                {"#ccc", 1.0, "white", 0.9});
    for (const series& s : curves) {
        ly += row;
        svg::style look = s.look;
        look.opacity = 1.0;
        doc.line({lx + 8, ly - 4}, {lx + 34, ly - 4}, look);
        doc.text({lx + 40, ly}, s.label, 11);
    }
}

}  // namespace plot
