// hand_eye: a camera on a robot arm, calibrated from the arm's motions and the camera's view of a
// fixed target (eye-in-hand, A_i X = X B_i). The arm moves between random poses; the camera
// measures the target's pose with noise. Three ways: hand_eye on the motions between consecutive
// poses (Daniilidis's dual-quaternion method, and rotation_first), and hand_eye_from_poses on the
// poses themselves (rotation_first, then the mount and the target fitted to the poses). The error
// of the recovered mount X falls as motions are added; the picture shows it for three noise levels.
// Run: example_hand_eye [output directory]  -> hand_eye.svg
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <quat/quat.hpp>
#include <quat/registration/hand_eye.hpp>

#include "check.hpp"
#include "plot.hpp"
#include "svg.hpp"

using namespace quat;

namespace {

constexpr double degree = numbers::pi / 180;

/// A small deterministic generator (SplitMix64), so the picture is the same on every platform.
class generator {
public:
    explicit generator(std::uint64_t seed) : state_(seed) {}
    /// Uniform in [0, 1).
    double uniform() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    }
    /// A direction uniform on the sphere.
    vec3<double> direction() {
        const double z = 2 * uniform() - 1;
        const double a = 2 * numbers::pi * uniform();
        const double r = std::sqrt(1 - z * z);
        return {r * std::cos(a), r * std::sin(a), z};
    }

private:
    std::uint64_t state_;
};

/// The pose measured with noise: turned by `angle` and moved by `offset` in random directions,
/// each scaled by a uniform factor in [0, 2) (mean 1).
dual_quaternion<double> noisy(generator& g, const dual_quaternion<double>& pose, double angle,
                              double offset) {
    // One draw a statement: the order of evaluation within an expression is unspecified.
    const vec3<double> axis = g.direction();
    const double turned = angle * 2 * g.uniform();
    const vec3<double> way = g.direction();
    const double moved = offset * 2 * g.uniform();
    const quatd turn = from_rotation_vector(axis * turned);
    const vec3<double> shift = way * moved;
    return to_dual_quaternion(turn * rotation_of(pose), translation_of(pose) + shift);
}

struct calibration_error {
    double rotation_degrees, translation_mm;
};

/// Calibrates from `motions` arm motions at one noise level, by the three ways on the same
/// measurements; the errors of the mounts found.
struct calibration_errors {
    calibration_error joint, rotation_first, from_poses;
};

calibration_errors calibrate(generator& g, const dual_quaternion<double>& mount, int motions,
                             double angle, double offset) {
    const dual_quaternion<double> target =
        to_dual_quaternion(rotation_z(0.3), vec3<double>{0.8, 0.1, 0.0});
    std::vector<dual_quaternion<double>> hands, cameras;
    for (int j = 0; j <= motions; ++j) {
        // The hand within reach of the target: turned up to 60 degrees about random axes.
        const vec3<double> axis = g.direction();
        const quatd turn = from_rotation_vector(axis * (60 * degree * g.uniform()));
        const vec3<double> at{0.5 + 0.2 * g.uniform(), -0.2 + 0.4 * g.uniform(),
                              0.4 + 0.2 * g.uniform()};
        const dual_quaternion<double> hand = to_dual_quaternion(turn, at);
        hands.push_back(hand);
        cameras.push_back(noisy(g, inverse(hand * mount) * target, angle, offset));
    }
    std::vector<dual_quaternion<double>> a, b;
    for (int j = 0; j < motions; ++j) {
        a.push_back(normalize(inverse(hands[j + 1]) * hands[j]));
        b.push_back(normalize(cameras[j + 1] * inverse(cameras[j])));
    }
    const auto error = [&mount](const hand_eye_calibration<double>& x) {
        return calibration_error{angle_between(x.mount.real, mount.real) / degree,
                                 norm(translation_of(x.mount) - translation_of(mount)) * 1000};
    };
    return {error(hand_eye(a, b)), error(hand_eye(a, b, hand_eye_method::rotation_first)),
            error(hand_eye_from_poses(hands, cameras).calibration)};
}

}  // namespace

int main(int argc, char** argv) {
    using example::expect;
    const std::string out = (argc > 1 ? std::string(argv[1]) : std::string(".")) + "/hand_eye.svg";
    std::printf("hand_eye: a camera on an arm calibrated from noisy motions (A X = X B)\n");

    // The camera 6 cm ahead of the flange, 2 cm aside, looking down its z axis tilted by 15 deg.
    const dual_quaternion<double> mount = to_dual_quaternion(
        rotation_x(15 * degree) * rotation_z(90 * degree), vec3<double>{0.02, 0.0, 0.06});
    generator g(2026);

    const calibration_errors exact = calibrate(g, mount, 8, 0.0, 0.0);
    for (const calibration_error& e : {exact.joint, exact.rotation_first, exact.from_poses}) {
        std::printf("  without noise, 8 motions: %.2g deg, %.2g mm\n", e.rotation_degrees,
                    e.translation_mm);
        expect(e.rotation_degrees < 1e-10 && e.translation_mm < 1e-9,
               "exact measurements give the mount to rounding");
    }

    // Noise of the camera's pose measurement: (degrees, mm).
    const double levels[3][2] = {{0.1, 1}, {0.3, 3}, {1, 10}};
    const int counts[] = {5, 7, 10, 14, 20, 28, 35, 50};
    constexpr int trials = 40;
    std::vector<plot::series> rotation_curves, translation_curves;
    const char* colours[3] = {"#1f77b4", "#ff7f0e", "#d62728"};
    // Per noise level, per method (0: Daniilidis's joint solution, 1: rotation_first, 2:
    // hand_eye_from_poses), per count.
    double rotation_rms[3][3][8] = {}, translation_rms[3][3][8] = {};
    for (int level = 0; level < 3; ++level) {
        const double angle = levels[level][0] * degree, offset = levels[level][1] / 1000;
        for (int c = 0; c < 8; ++c) {
            double squares[3][2] = {};
            for (int t = 0; t < trials; ++t) {
                const calibration_errors e = calibrate(g, mount, counts[c], angle, offset);
                for (int m = 0; m < 3; ++m) {
                    const calibration_error& one =
                        m == 0 ? e.joint : (m == 1 ? e.rotation_first : e.from_poses);
                    squares[m][0] += one.rotation_degrees * one.rotation_degrees;
                    squares[m][1] += one.translation_mm * one.translation_mm;
                }
            }
            for (int m = 0; m < 3; ++m) {
                rotation_rms[level][m][c] = std::sqrt(squares[m][0] / trials);
                translation_rms[level][m][c] = std::sqrt(squares[m][1] / trials);
            }
        }
    }
    const char* method_names[3] = {"Daniilidis (joint)", "rotation_first", "hand_eye_from_poses"};
    const char* dashes[3] = {"2 3", "6 4", ""};
    for (int m = 0; m < 3; ++m) {
        std::printf(
            "  %s: RMS error of the mount over %d calibrations (rotation deg / "
            "translation mm):\n",
            method_names[m], trials);
        std::printf("  %-16s", "noise \\ motions");
        for (const int n : counts) std::printf(" %14d", n);
        std::printf("\n");
        for (int level = 0; level < 3; ++level) {
            char label[64];
            std::snprintf(label, sizeof label, "%g deg, %g mm", levels[level][0], levels[level][1]);
            plot::series rotation{label, {}, {}, {colours[level], 1.8}};
            plot::series translation{label, {}, {}, {colours[level], 1.8}};
            rotation.look.dash = translation.look.dash = dashes[m];
            std::printf("  %-16s", label);
            for (int c = 0; c < 8; ++c) {
                std::printf(" %6.3f / %5.2f", rotation_rms[level][m][c],
                            translation_rms[level][m][c]);
                rotation.x.push_back(counts[c]);
                rotation.y.push_back(rotation_rms[level][m][c]);
                translation.x.push_back(counts[c]);
                translation.y.push_back(translation_rms[level][m][c]);
            }
            std::printf("\n");
            expect(rotation.y.back() < rotation.y.front() &&
                       translation.y.back() < translation.y.front(),
                   "more motions, smaller errors");
            expect(rotation.y.back() < rotation.y.front() / 3 &&
                       translation.y.back() < translation.y.front() / 3,
                   "50 motions: errors below a third of those from 5");
            rotation_curves.push_back(rotation);
            translation_curves.push_back(translation);
        }
    }
    for (int level = 0; level < 3; ++level) {
        expect(rotation_rms[level][1][7] * 1.5 < rotation_rms[level][0][7],
               "rotation_first: the rotation at 50 motions 1.5x more accurate than the joint one");
        bool better = true;
        for (int c = 0; c < 8; ++c)
            better = better && rotation_rms[level][2][c] <= rotation_rms[level][1][c] &&
                     translation_rms[level][2][c] <= translation_rms[level][1][c];
        expect(better, "hand_eye_from_poses: at least as accurate as rotation_first, every count");
    }

    svg::document doc(960, 476);
    doc.text({480, 26}, "Hand-eye calibration (A X = X B): RMS error of the mount found", 17,
             "middle", "#222", true);
    plot::chart left{70, 80, 380, 270, "rotation", "motions", "error (deg)", 5, 50, 1e-3, 10, true};
    plot::chart right{560,          80, 380, 270,  "translation", "motions",
                      "error (mm)", 5,  50,  1e-2, 100,           true};
    left.legend = right.legend = false;
    plot::draw(doc, left, rotation_curves);
    plot::draw(doc, right, translation_curves);
    // One legend for both charts: colour the noise level, dash the method.
    for (int m = 0; m < 3; ++m) {
        const double x = 110 + 260 * m, y = 410;
        svg::style look{"#444", 1.8};
        look.dash = dashes[m];
        doc.line({x, y - 4}, {x + 34, y - 4}, look);
        doc.text({x + 40, y},
                 m == 0   ? "hand_eye(a, b): Daniilidis"
                 : m == 1 ? "hand_eye(a, b, rotation_first)"
                          : "hand_eye_from_poses(hands, cameras)",
                 12);
    }
    for (int level = 0; level < 3; ++level) {
        const double x = 230 + 180 * level, y = 432;
        doc.line({x, y - 4}, {x + 34, y - 4}, {colours[level], 2.5});
        char label[64];
        std::snprintf(label, sizeof label, "%g deg, %g mm", levels[level][0], levels[level][1]);
        doc.text({x + 40, y}, label, 12);
    }
    doc.text({480, 462},
             "camera pose noise per measurement (colour); 40 calibrations per point; relative "
             "motions between consecutive poses",
             12, "middle", "#444");
    expect(doc.save(out), "hand_eye.svg written");
    std::printf("  wrote %s\n", out.c_str());
    return example::failures() == 0 ? 0 : 1;
}
