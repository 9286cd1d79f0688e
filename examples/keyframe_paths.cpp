// keyframe_paths: a camera on a tripod follows a ball circling it, but its orientation is only
// keyframed four times a second (look_rotation toward the ball) and interpolated in between: the
// thesis's "camera moves that follow a moving object". Three ways through the same keyframes:
//   keyframe_slerp     constant angular velocity per segment: the velocity jumps at every keyframe
//   squad              Shoemake's spherical cubic: velocity continuous (evenly spaced keyframes),
//                      acceleration jumps
//   rotation_spline    C2: velocity and acceleration continuous
// Picture: angular speed and angular acceleration over time, against the camera that aims at the
// ball every instant; ticks mark the keyframes.
// Run: example_keyframe_paths [output directory]  -> keyframe_paths.svg
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <quat/quat.hpp>

#include "check.hpp"
#include "plot.hpp"
#include "svg.hpp"

using namespace quat;
using v3 = vec3<double>;

namespace {

// One 5 s lap, keyframed every 0.25 s (21 keyframes) and sampled every 5 ms: sample k is at
// k * duration / samples, so every 50th sample is exactly a keyframe time.
constexpr double duration = 5, key_step = 0.25;
constexpr int key_count = 21, samples = 1000;
constexpr double dt = duration / samples;
const v3 world_up{0, 0, 1};  // the camera sits at the origin, world z up

/// The ball at time t: an ellipse off-centre round the camera, 1.9 m away at its nearest
/// (t = 2.5 s) and 4.7 m at its farthest, bobbing 0.6 m up and down. Never overhead, so
/// look_rotation is well-conditioned all the way; the camera turns four times faster on the near
/// pass than on the far one.
v3 ball(double t) {
    const double a = 2 * numbers::pi * (t - 2.5) / duration;
    return {4 * std::sin(a), 1.5 - 3 * std::cos(a), 1.2 + 0.6 * std::sin(2 * a)};
}

quatd aim(double t) { return look_rotation(ball(t), world_up); }

double sample_time(int k) { return k * duration / samples; }

struct method {
    const char* name;
    std::function<quatd(double)> at;
    svg::style look;
};

/// The one-sided angular velocity at t, from after (side +1) or before (side -1): the difference
/// quotient over h is the velocity plus h / 2 times the acceleration, and twice the one over h / 2
/// minus it cancels that term (Richardson), leaving O(h^2).
v3 one_sided_velocity(const std::function<quatd(double)>& q, double t, double side,
                      double h = 1e-5) {
    const quatd at_t = q(t);
    const auto quotient = [&](double step) {
        return body_angular_velocity(at_t, q(t + side * step), side * step);
    };
    return quotient(h / 2) * 2.0 - quotient(h);
}

/// The one-sided angular acceleration at t (body frame, as rotation_spline's): a second-order
/// one-sided difference of velocities at t, t + 2 ms and t + 4 ms on the given side.
v3 one_sided_acceleration(const std::function<quatd(double)>& q, double t, double side) {
    const double d = 2e-3;
    const auto velocity = [&](double s) {  // central differences inside the segment
        return body_angular_velocity(q(s - 1e-5), q(s + 1e-5), 2e-5);
    };
    return (one_sided_velocity(q, t, side) * -3.0 + velocity(t + side * d) * 4.0 -
            velocity(t + side * 2 * d)) /
           (2 * d * side);
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out =
        (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/keyframe_paths.svg";
    std::printf("keyframe_paths: camera aimed at a ball, keyframed every %.2f s over %.0f s\n",
                key_step, duration);

    std::vector<double> times;
    std::vector<quatd> keys;
    for (int i = 0; i < key_count; ++i) {
        times.push_back(i * key_step);
        keys.push_back(aim(times.back()));
    }
    // Squad's inner control points; the end keyframes are passed twice.
    std::vector<quatd> controls;
    for (std::size_t i = 0; i < keys.size(); ++i)
        controls.push_back(squad_control(keys[i > 0 ? i - 1 : 0], keys[i],
                                         keys[std::min(i + 1, keys.size() - 1)]));
    const rotation_spline<double> spline(times, keys);

    const std::vector<method> methods = {
        {"piecewise slerp (keyframe_slerp)",
         [&](double t) { return keyframe_slerp(times, keys, t); },
         {"#ff7f0e", 1.5}},
        {"squad (squad_control, squad)",
         [&](double t) {
             // Segment i holds [t_i, t_(i+1)); squad's parameter is the fraction of it gone by.
             const auto i = static_cast<std::size_t>(
                 std::clamp(std::floor(t / key_step), 0.0, double(key_count - 2)));
             return squad(keys[i], controls[i], controls[i + 1], keys[i + 1],
                          (t - times[i]) / key_step);
         },
         {"#2ca02c", 2.0, "none", 1.0, "7 4"}},
        {"rotation_spline", [&](double t) { return spline(t); }, {"#1f77b4", 2.0}},
        {"aimed every instant (truth)", aim, {"#222", 1.0, "none", 1.0, "2 3"}},
    };

    // All three pass through the keyframes (the truth does by definition).
    for (std::size_t m = 0; m < 3; ++m) {
        double miss = 0;
        for (std::size_t i = 0; i < keys.size(); ++i)
            miss = std::max(miss, angle_between(methods[m].at(times[i]), keys[i]));
        std::printf("  %-34s keyframes missed by at most %.0e rad\n", methods[m].name, miss);
        expect(miss < 1e-9, "passes through every keyframe");
    }

    // Angular speed: finite differences between consecutive samples, at their midpoints; for the
    // spline its own angular_velocity, which the differences cross-check.
    std::vector<plot::series> speed;
    double spline_difference = 0, fastest = 0;
    for (std::size_t m = 0; m < methods.size(); ++m) {
        plot::series s{methods[m].name, {}, {}, methods[m].look};
        for (int k = 0; k < samples; ++k) {
            const double t = sample_time(k) + dt / 2;
            const v3 omega = body_angular_velocity(methods[m].at(sample_time(k)),
                                                   methods[m].at(sample_time(k + 1)), dt);
            if (m == 2)
                spline_difference = std::max(
                    spline_difference, norm(omega - spline.angular_velocity(t)) / norm(omega));
            if (m == 3) fastest = std::max(fastest, norm(omega));
            s.x.push_back(t);
            s.y.push_back(norm(m == 2 ? spline.angular_velocity(t) : omega));
        }
        speed.push_back(s);
    }
    std::printf("  the camera aimed every instant turns at up to %.2f rad/s\n", fastest);
    std::printf("  spline's angular_velocity vs finite differences: %.0e relative\n",
                spline_difference);
    expect(spline_difference < 1e-4, "the spline's angular_velocity is its rate of turn");

    // The largest jumps across the 19 inner keyframes: by one-sided finite differences, and for the
    // spline also from its own angular_velocity and angular_acceleration one ulp before and at the
    // keyframe time (each segment's cubic, exactly).
    const auto largest_jump = [&](const auto& at_side) {
        double jump = 0;
        for (std::size_t i = 1; i + 1 < times.size(); ++i)
            jump = std::max(jump, norm(at_side(times[i], 1.0) - at_side(times[i], -1.0)));
        return jump;
    };
    const auto velocity_jump = [&](std::size_t m) {
        return largest_jump(
            [&](double t, double side) { return one_sided_velocity(methods[m].at, t, side); });
    };
    const auto acceleration_jump = [&](std::size_t m) {
        return largest_jump(
            [&](double t, double side) { return one_sided_acceleration(methods[m].at, t, side); });
    };
    const auto just_before = [](double t, double side) {
        return side > 0 ? t : std::nextafter(t, -std::numeric_limits<double>::infinity());
    };
    const double slerp_jump = velocity_jump(0), squad_jump = velocity_jump(1),
                 squad_acceleration_jump = acceleration_jump(1),
                 spline_jump = largest_jump([&](double t, double side) {
                     return spline.angular_velocity(just_before(t, side));
                 }),
                 spline_acceleration_jump = largest_jump([&](double t, double side) {
                     return spline.angular_acceleration(just_before(t, side));
                 }),
                 spline_fd_jump = velocity_jump(2),
                 spline_fd_acceleration_jump = acceleration_jump(2);
    std::printf("  largest jump across a keyframe   angular velocity   angular acceleration\n");
    std::printf("  %-32s %10.2f rad/s           infinite\n", methods[0].name, slerp_jump);
    std::printf("  %-32s %10.0e rad/s   %10.2f rad/s^2\n", methods[1].name, squad_jump,
                squad_acceleration_jump);
    std::printf("  %-32s %10.0e rad/s   %10.0e rad/s^2\n", methods[2].name, spline_jump,
                spline_acceleration_jump);
    std::printf("  %-32s %10.0e rad/s   %10.0e rad/s^2\n", "  ... by finite differences",
                spline_fd_jump, spline_fd_acceleration_jump);
    expect(slerp_jump > 0.5, "slerp's angular velocity jumps at the keyframes");
    expect(squad_jump < 1e-6, "squad's is continuous (evenly spaced keyframes)");
    expect(spline_jump < 1e-9 && spline_fd_jump < 1e-6, "so is the spline's");
    expect(squad_acceleration_jump > 5, "squad's angular acceleration jumps at the keyframes");
    expect(spline_acceleration_jump < 1e-9 && spline_fd_acceleration_jump < 1e-2,
           "the spline's is continuous");
    // The dips at both ends of squad's curve: with the end keyframe passed twice the end control
    // point is a quarter of the way to the next keyframe, which halves the starting velocity.
    const double start_ratio = norm(one_sided_velocity(methods[1].at, 0, 1)) /
                               norm(one_sided_velocity(methods[0].at, 0, 1));
    std::printf("  squad starts at %.3f times the first segment's slerp speed\n", start_ratio);
    expect(std::abs(start_ratio - 0.5) < 1e-6,
           "squad with the end keyframe passed twice starts at half the slerp's speed");

    // Angular acceleration: the spline's own, and second differences of the others (slerp's is zero
    // inside the segments and infinite at the keyframes, so it is left out).
    std::vector<plot::series> acceleration;
    for (std::size_t m = 1; m < methods.size(); ++m) {
        plot::series s{methods[m].name, {}, {}, methods[m].look};
        const auto& q = methods[m].at;
        for (int k = 1; k < samples; ++k) {
            const double t = sample_time(k);
            const v3 alpha = m == 2 ? spline.angular_acceleration(t)
                                    : (body_angular_velocity(q(t), q(sample_time(k + 1)), dt) -
                                       body_angular_velocity(q(sample_time(k - 1)), q(t), dt)) /
                                          dt;
            s.x.push_back(t);
            s.y.push_back(norm(alpha));
        }
        acceleration.push_back(s);
    }

    svg::document doc(1000, 760);
    doc.text({500, 28},
             "A camera following a ball from keyframes 4 times a second: three interpolations", 17,
             "middle", "#222", true);
    const auto keyframe_ticks = [&](const plot::chart& c) {  // at the top and bottom edges
        for (const double t : times) {
            const double x = c.left + t / duration * c.width;
            doc.line({x, c.top + c.height}, {x, c.top + c.height - 8}, {"#444", 1.5});
            doc.line({x, c.top}, {x, c.top + 8}, {"#444", 1.5});
        }
    };
    const plot::chart top{80,
                          95,
                          880,
                          250,
                          "Angular speed",
                          "time (s); ticks: keyframes",
                          "|angular velocity| (rad/s)",
                          0,
                          duration,
                          0,
                          4};
    plot::draw(doc, top, speed);
    keyframe_ticks(top);
    const plot::chart bottom{80,
                             455,
                             880,
                             220,
                             "Angular acceleration",
                             "time (s); ticks: keyframes",
                             "|angular acceleration| (rad/s^2)",
                             0,
                             duration,
                             0,
                             14};
    plot::draw(doc, bottom, acceleration);
    keyframe_ticks(bottom);
    doc.text({950, 480}, "piecewise slerp: 0 between keyframes, infinite at them", 11, "end",
             "#ff7f0e");
    doc.text({500, 730},
             "The ball circles the camera on an ellipse, nearest at 2.5 s; each keyframe is "
             "look_rotation(ball - camera, up = +z).",
             12, "middle", "#444");
    doc.text({500, 746},
             "slerp's angular velocity jumps at the keyframes; squad's is continuous but its "
             "acceleration jumps; the spline's are both continuous.",
             12, "middle", "#444");
    expect(doc.save(out), "keyframe_paths.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
