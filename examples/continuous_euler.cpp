// continuous_euler: yaw-pitch-roll angles (intrinsic z-y-x, R = Rz(yaw) Ry(pitch) Rx(roll)) read
// back frame by frame from a spinning, tumbling body. Plain to_euler<S, F>(q) gives principal
// angles: they jump by 360 deg whenever yaw or roll passes +-180 deg, and yaw and roll jump by 180
// deg when pitch passes 90 deg. to_euler<S, F>(q, previous), fed its own previous output, gives the
// triple of q nearest the previous frame's: unwrapped by whole turns, pitch beyond 90 deg, and at
// an exact gimbal lock the free roll held at its previous value. Its curves follow the motion
// without a jump. Run: example_continuous_euler [output directory] -> continuous_euler.svg
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <quat/quat.hpp>

#include "check.hpp"
#include "plot.hpp"
#include "svg.hpp"

using namespace quat;

namespace {

constexpr double degree = numbers::pi / 180;
constexpr sequence S = sequence::zyx;
constexpr frame F = frame::intrinsic;
using ypr = euler<double, S, F>;  // {yaw, pitch, roll}

/// Raised cosine: exactly 1 at u = 0, smoothly down to 0 at |u| = 1, and 0 beyond.
double bump(double u) { return std::abs(u) < 1 ? (1 + std::cos(numbers::pi * u)) / 2 : 0.0; }

/// The true motion over 10 s: yaw spins at 1.9 rad/s (about three turns); pitch climbs through
/// +90 deg to 112 deg and back (t = 1 .. 4.2 s), then dips to exactly -90 deg at t = 7.5 s; roll
/// swings +-63 deg about 180 deg, passing +-180 deg every 1.4 s.
ypr truth(double t) {
    return {-2.4 + 1.9 * t, 1.95 * bump((t - 2.6) / 1.6) - numbers::pi / 2 * bump((t - 7.5) / 1.5),
            numbers::pi + 1.1 * std::sin(2.2 * t + 0.3)};
}

/// Largest change of any of the three angles from one frame to the next.
double largest_step(const std::vector<ypr>& angles) {
    double step = 0;
    for (std::size_t n = 1; n < angles.size(); ++n)
        for (std::size_t k = 0; k < 3; ++k)
            step = std::max(step, std::abs(angles[n][k] - angles[n - 1][k]));
    return step;
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/continuous_euler.svg";
    std::printf(
        "continuous_euler: yaw-pitch-roll (intrinsic z-y-x) of a tumbling body, 50 frames/s\n");

    // Frames at t = (n + 1/2) / 50 s, half a frame off the exact lock at 7.5 s, where the plain
    // split of yaw and roll would be left to rounding (and could differ between compilers).
    constexpr double rate = 50;
    constexpr int frames = 500;
    std::vector<double> time;
    std::vector<ypr> exact, plain, continuous;
    ypr previous = truth(0.5 / rate);  // seeded with the true first triple
    double representation_error = 0, truth_error = 0, nearest_cut = numbers::pi,
           nearest_lock = numbers::pi;
    for (int n = 0; n < frames; ++n) {
        const double t = (n + 0.5) / rate;
        const quatd q = to_quaternion(truth(t));
        const ypr p = to_euler<S, F>(q);
        previous = to_euler<S, F>(q, previous);
        time.push_back(t);
        exact.push_back(truth(t));
        plain.push_back(p);
        continuous.push_back(previous);
        representation_error =
            std::max(representation_error, angle_between(to_quaternion(previous), q));
        for (std::size_t k = 0; k < 3; ++k)
            truth_error = std::max(truth_error, std::abs(previous[k] - exact.back()[k]));
        // How close plain yaw and roll come to +-180 deg, where rounding could pick either sign,
        // and pitch to +-90 deg, where yaw and roll lose accuracy (as eps / distance).
        nearest_cut =
            std::min({nearest_cut, numbers::pi - std::abs(p[0]), numbers::pi - std::abs(p[2])});
        nearest_lock = std::min(nearest_lock, numbers::pi / 2 - std::abs(p[1]));
    }
    const double true_step = largest_step(exact), plain_step = largest_step(plain),
                 continuous_step = largest_step(continuous);
    std::printf(
        "  largest frame-to-frame step: truth %.4f rad, plain %.4f rad, continuous %.4f rad\n",
        true_step, plain_step, continuous_step);
    std::printf("  continuous: max angle to q %.2e rad, max |angle - truth| %.2e rad\n",
                representation_error, truth_error);
    std::printf("  plain yaw, roll come within %.2e rad of +-pi, pitch within %.2e of +-pi/2\n",
                nearest_cut, nearest_lock);
    expect(representation_error < 1e-12, "every continuous triple is the rotation q");
    expect(continuous_step <= true_step + 1e-9,
           "continuous angles never step further than the true ones");
    expect(plain_step > 6, "plain angles jump by about 2 pi");
    expect(truth_error < 1e-9, "continuous angles are the true ones (no frame is at the lock)");
    expect(nearest_cut > 1e-6 && nearest_lock > 1e-6,
           "no plain frame is on a branch cut or a lock, so the picture does not hang on rounding");

    // A frame exactly at the lock (t = 7.5 s, pitch -90 deg, checked but not drawn), between frames
    // 374 and 375: q fixes only yaw + roll there, so the continuous form keeps roll from the frame
    // before and puts the rest into yaw. That differs from the true split by one frame's roll
    // change (no angle of q can tell), still equals q, and the next frame has its own split again.
    const ypr at_lock = truth(7.5);
    const quatd locked = to_quaternion(at_lock);
    const ypr held = to_euler<S, F>(locked, continuous[374]);
    const ypr after = to_euler<S, F>(to_quaternion(exact[375]), held);
    std::printf(
        "  exactly at the lock: true (%.4f, %.4f, %.4f), continuous (%.4f, %.4f, %.4f) rad\n",
        at_lock[0], at_lock[1], at_lock[2], held[0], held[1], held[2]);
    expect(held[2] == continuous[374][2], "exactly at the lock roll keeps its previous value");
    expect(angle_between(to_quaternion(held), locked) < 1e-12, "and that triple is still q");
    expect(std::abs(after[0] - exact[375][0]) < 1e-9 && std::abs(after[2] - exact[375][2]) < 1e-9,
           "the frame after the lock has the true yaw and roll again");

    // Three charts over time, angles in degrees: the plain angles on top; below, the continuous
    // ones as wide translucent bands over the true angles, dashed (yaw apart: its turns need a
    // scale of their own).
    const char* names[3] = {"yaw", "pitch", "roll"};
    const char* colours[3] = {"#1f77b4", "#2ca02c", "#d62728"};
    const auto series_of = [&](const std::vector<ypr>& angles, std::size_t k, std::string label,
                               svg::style look) {
        plot::series s{std::move(label), time, {}, std::move(look)};
        for (const ypr& e : angles) s.y.push_back(e[k] / degree);
        return s;
    };
    std::vector<plot::series> plain_curves, pitch_roll_curves, yaw_curves;
    for (std::size_t k = 0; k < 3; ++k)
        plain_curves.push_back(series_of(plain, k, names[k], {colours[k], 1.6}));
    for (std::size_t k = 0; k < 3; ++k) {
        std::vector<plot::series>& curves = k == 0 ? yaw_curves : pitch_roll_curves;
        curves.push_back(series_of(exact, k, std::string("true ") + names[k],
                                   {"#222", 1.3, "none", 1.0, "5 4"}));
        curves.push_back(series_of(continuous, k, std::string("continuous ") + names[k],
                                   {colours[k], 4.5, "none", 0.45}));
    }
    const auto chart = [](double left, double top, double width, const char* title, double y_max) {
        plot::chart c{left, top, width, 220, title, "time (s)", "angle (deg)", 0, 10, -200, y_max};
        return c;
    };
    plot::chart plain_chart =
        chart(70, 80, 860, "Plain to_euler<zyx, intrinsic>(q): principal angles", 300);
    plot::chart pitch_roll_chart =
        chart(70, 420, 400, "to_euler(q, previous): pitch and roll", 300);
    pitch_roll_chart.legend_down = 0.6;  // bottom left, below pitch 0 before its first climb
    plot::chart yaw_chart = chart(530, 420, 400, "to_euler(q, previous): yaw", 1100);

    // Behind the curves: when pitch is beyond 90 deg (1.95 bump(u) = pi/2) and the instant it
    // touches -90 deg.
    const double beyond = 1.6 * std::acos(numbers::pi / 1.95 - 1) / numbers::pi;
    svg::document doc(960, 715);
    for (const plot::chart* c : {&plain_chart, &pitch_roll_chart, &yaw_chart}) {
        const auto x = [c](double t) { return c->left + t / 10 * c->width; };
        const double bottom = c->top + c->height;
        doc.polygon({{x(2.6 - beyond), c->top},
                     {x(2.6 + beyond), c->top},
                     {x(2.6 + beyond), bottom},
                     {x(2.6 - beyond), bottom}},
                    {"none", 0.0, "#fde9b0"});
        doc.line({x(7.5), c->top}, {x(7.5), bottom}, {"#b08000", 1.2, "none", 1.0, "2 3"});
        if (c == &plain_chart) {
            doc.text({x(2.6), c->top + 16}, "pitch > 90 deg", 11, "middle", "#805d00");
            doc.text({x(7.5), c->top + 16}, "pitch = -90 deg (lock)", 11, "middle", "#805d00");
        }
    }
    doc.text({480, 26},
             "Euler angles frame by frame: yaw-pitch-roll, R = Rz(yaw) Ry(pitch) Rx(roll)", 17,
             "middle", "#222", true);
    plot::draw(doc, plain_chart, plain_curves);
    plot::draw(doc, pitch_roll_chart, pitch_roll_curves);
    plot::draw(doc, yaw_chart, yaw_curves);
    char footer[160];
    std::snprintf(footer, sizeof footer,
                  "50 frames/s; largest change between frames: plain %.1f deg, continuous %.2f deg "
                  "(the true motion's %.2f deg)",
                  plain_step / degree, continuous_step / degree, true_step / degree);
    doc.text({480, 702}, footer, 12, "middle", "#444");
    expect(doc.save(out), "continuous_euler.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
