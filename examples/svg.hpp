// A tiny SVG writer for quat's examples (not part of the library): lines, polygons, circles, text.
// Coordinates are SVG pixels, y pointing down; callers map their own coordinates onto them.
#pragma once

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace svg {

/// A point in SVG pixel coordinates (x right, y down).
struct point {
    double x, y;
};

/// Stroke, fill and dash attributes of a shape.
struct style {
    std::string stroke;
    double width;
    std::string fill;
    double opacity;
    std::string dash;  // e.g. "6 4"; empty for a solid line

    // A constructor rather than an aggregate, so callers may give only the leading attributes.
    style(std::string stroke_colour = "#222", double stroke_width = 1.5,
          std::string fill_colour = "none", double alpha = 1.0, std::string dash_pattern = "")
        : stroke(std::move(stroke_colour)),
          width(stroke_width),
          fill(std::move(fill_colour)),
          opacity(alpha),
          dash(std::move(dash_pattern)) {}
};

/// An SVG document built in memory and written with save().
class document {
public:
    document(double width, double height) : width_(width), height_(height) {
        body_ << "<rect x=\"0\" y=\"0\" width=\"" << num(width) << "\" height=\"" << num(height)
              << "\" fill=\"white\"/>\n";
    }

    void line(point a, point b, const style& s = {}) {
        body_ << "<line x1=\"" << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\"" << num(b.x)
              << "\" y2=\"" << num(b.y) << "\"" << attributes(s) << "/>\n";
    }

    void polyline(const std::vector<point>& points, const style& s = {}) {
        body_ << "<polyline points=\"" << list(points) << "\"" << attributes(s) << "/>\n";
    }

    void polygon(const std::vector<point>& points, const style& s = {}) {
        body_ << "<polygon points=\"" << list(points) << "\"" << attributes(s) << "/>\n";
    }

    void circle(point centre, double radius, const style& s = {}) {
        body_ << "<circle cx=\"" << num(centre.x) << "\" cy=\"" << num(centre.y) << "\" r=\""
              << num(radius) << "\"" << attributes(s) << "/>\n";
    }

    /// A line from a to b with a filled arrow head at b.
    void arrow(point a, point b, const style& s = {}, double head = 9.0) {
        const double dx = b.x - a.x, dy = b.y - a.y, length = std::sqrt(dx * dx + dy * dy);
        if (length < 1e-9) return;
        const double ux = dx / length, uy = dy / length;
        const point base{b.x - ux * head, b.y - uy * head};
        line(a, base, s);
        style head_style = s;
        head_style.fill = s.stroke;
        head_style.dash.clear();
        polygon({b,
                 {base.x - uy * head * 0.4, base.y + ux * head * 0.4},
                 {base.x + uy * head * 0.4, base.y - ux * head * 0.4}},
                head_style);
    }

    /// Text at p; anchor is "start", "middle" or "end".
    void text(point p, const std::string& content, double size = 14,
              const std::string& anchor = "start", const std::string& colour = "#222",
              bool bold = false) {
        body_ << "<text x=\"" << num(p.x) << "\" y=\"" << num(p.y)
              << "\" font-family=\"DejaVu Sans, Arial, sans-serif\""
              << " font-size=\"" << num(size) << "\" text-anchor=\"" << anchor << "\" fill=\""
              << colour << "\"" << (bold ? " font-weight=\"bold\"" : "") << ">" << escape(content)
              << "</text>\n";
    }

    [[nodiscard]] std::string str() const {
        std::ostringstream out;
        out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width_) << "\" height=\""
            << num(height_) << "\" viewBox=\"0 0 " << num(width_) << " " << num(height_) << "\">\n"
            << body_.str() << "</svg>\n";
        return out.str();
    }

    /// Writes the document; false if the file cannot be written.
    [[nodiscard]] bool save(const std::string& path) const {
        std::ofstream file(path, std::ios::binary);
        file << str();
        return static_cast<bool>(file);
    }

private:
    // Two decimals keep the files small and byte-for-byte reproducible across runs.
    static std::string num(double v) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.2f", v);
        std::string s = buffer;
        if (s == "-0.00") s = "0.00";
        return s;
    }

    static std::string list(const std::vector<point>& points) {
        std::string out;
        for (const point& p : points) out += num(p.x) + "," + num(p.y) + " ";
        if (!out.empty()) out.pop_back();
        return out;
    }

    static std::string attributes(const style& s) {
        std::string out = " stroke=\"" + s.stroke + "\" stroke-width=\"" + num(s.width) +
                          "\" fill=\"" + s.fill + "\"";
        if (s.opacity < 1.0) out += " opacity=\"" + num(s.opacity) + "\"";
        if (!s.dash.empty()) out += " stroke-dasharray=\"" + s.dash + "\"";
        out += " stroke-linejoin=\"round\" stroke-linecap=\"round\"";
        return out;
    }

    static std::string escape(const std::string& text) {
        std::string out;
        for (char c : text) {
            if (c == '&') out += "&amp;";
            else if (c == '<') out += "&lt;";
            else if (c == '>') out += "&gt;";
            else out += c;
        }
        return out;
    }

    double width_, height_;
    std::ostringstream body_;
};

}  // namespace svg
