// `quat_accuracy --scipy`, second table: keyframe_slerp and rotation_spline against SciPy 1.10's
// Slerp and RotationSpline on the committed reference sets (tests/data/scipy_spline_reference.hpp,
// written by tools/scipy_spline_reference.py). Rotations by angle (rad), rates by
// |difference| / (1 + |value|), the largest over every sample of every set.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <vector>

#include <quat/quat.hpp>

#include "data/scipy_spline_reference.hpp"

namespace accuracy {

struct spline_agreement {
    int sets = 0;
    double angle = 0, velocity = 0, acceleration = 0;
};

inline double rate_difference(const quat::vec3<double>& a, const double (&b)[3]) {
    const quat::vec3<double> reference{b[0], b[1], b[2]};
    return quat::norm(a - reference) / (1 + quat::norm(reference));
}

inline quat::quaternion<double> quaternion_of(const double (&q)[4]) {
    return {q[0], q[1], q[2], q[3]};
}

/// quat's spline (double) against one of SciPy's answers on the sets `use` accepts.
template <class Use>
spline_agreement measure_spline(Use use, bool converged_answer) {
    spline_agreement out;
    for (const auto& c : quat::test::scipy::spline_cases) {
        if (!use(c)) continue;
        ++out.sets;
        std::vector<double> times(c.times, c.times + c.count);
        std::vector<quat::quaternion<double>> rotations;
        for (std::size_t i = 0; i < c.count; ++i)
            rotations.push_back(quaternion_of(c.rotations[i]));
        const quat::rotation_spline<double> spline(times, rotations);
        const auto* rotation = converged_answer ? c.converged_rotation : c.rotation;
        const auto* velocity = converged_answer ? c.converged_angular_velocity : c.angular_velocity;
        const auto* acceleration =
            converged_answer ? c.converged_angular_acceleration : c.angular_acceleration;
        for (std::size_t k = 0; k < c.samples; ++k) {
            const double t = c.sample_times[k];
            out.angle =
                std::max(out.angle, quat::angle_between(spline(t), quaternion_of(rotation[k])));
            out.velocity =
                std::max(out.velocity, rate_difference(spline.angular_velocity(t), velocity[k]));
            out.acceleration = std::max(
                out.acceleration, rate_difference(spline.angular_acceleration(t), acceleration[k]));
        }
    }
    return out;
}

/// SciPy's default answer against its own converged one, on the sets where it stops early.
inline spline_agreement measure_scipy_early_stop() {
    spline_agreement out;
    for (const auto& c : quat::test::scipy::spline_cases) {
        if (c.scipy_converged || !c.reference_converged) continue;
        ++out.sets;
        for (std::size_t k = 0; k < c.samples; ++k) {
            const quat::vec3<double> v{c.angular_velocity[k][0], c.angular_velocity[k][1],
                                       c.angular_velocity[k][2]};
            const quat::vec3<double> a{c.angular_acceleration[k][0], c.angular_acceleration[k][1],
                                       c.angular_acceleration[k][2]};
            out.angle =
                std::max(out.angle, quat::angle_between(quaternion_of(c.rotation[k]),
                                                        quaternion_of(c.converged_rotation[k])));
            out.velocity =
                std::max(out.velocity, rate_difference(v, c.converged_angular_velocity[k]));
            out.acceleration =
                std::max(out.acceleration, rate_difference(a, c.converged_angular_acceleration[k]));
        }
    }
    return out;
}

template <class T>
double measure_keyframe_slerp() {
    double worst = 0;
    for (const auto& c : quat::test::scipy::slerp_cases) {
        if (sizeof(T) < sizeof(double) && c.times[c.count - 1] > 100) continue;  // float times
        std::vector<T> times(c.times, c.times + c.count);
        std::vector<quat::quaternion<T>> rotations;
        for (std::size_t i = 0; i < c.count; ++i)
            rotations.push_back(quat::quaternion<T>(quaternion_of(c.rotations[i])));
        for (std::size_t k = 0; k < c.samples; ++k)
            worst =
                std::max(worst, double(quat::angle_between(
                                    quat::keyframe_slerp(times, rotations, T(c.sample_times[k])),
                                    quat::quaternion<T>(quaternion_of(c.rotation[k])))));
    }
    return worst;
}

inline void print_spline_row(const char* what, const spline_agreement& a) {
    std::printf("| %s (%d sets) | %.2g | %.2g | %.2g |\n", what, a.sets, a.angle, a.velocity,
                a.acceleration);
}

inline void run_scipy_spline() {
    using case_type = quat::test::scipy::spline_case;
    std::printf(
        "\n| rotation_spline (double) against RotationSpline | rotation, rad | angular "
        "velocity | angular acceleration |\n|---|---|---|---|\n");
    print_spline_row("SciPy's default, where its solver converged",
                     measure_spline([](const case_type& c) { return c.scipy_converged; }, false));
    print_spline_row(
        "SciPy run to convergence (100000 steps, tolerance 1e-14)",
        measure_spline([](const case_type& c) { return c.reference_converged; }, true));
    print_spline_row(
        "for comparison: SciPy's default against its converged answer, where it "
        "stops after 10 steps",
        measure_scipy_early_stop());
    std::printf(
        "\n| keyframe_slerp against Slerp, rotation angle (rad) | float | double |\n"
        "|---|---|---|\n| %zu sets | %.2g | %.2g |\n",
        std::size(quat::test::scipy::slerp_cases), measure_keyframe_slerp<float>(),
        measure_keyframe_slerp<double>());
}

}  // namespace accuracy
