// `quat_accuracy --scipy`: how far quat's align_vectors (rotation, sensitivity) and mean lie from
// SciPy 1.10's answers on the committed reference sets (tests/data/scipy_reference.hpp, written by
// tools/scipy_reference.py), in float and double. GLM and Eigen have neither operation. The inputs
// are SciPy's doubles; the float rows round them to float first, so they measure that rounding too.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string_view>
#include <vector>

#include <quat/fitting/align_vectors.hpp>
#include <quat/fitting/mean.hpp>

#include "data/scipy_reference.hpp"
#include "measure_scipy_spline.hpp"

namespace accuracy {

struct scipy_agreement {
    double align_angle = 0;       // max rotation angle to SciPy's, rad
    double sensitivity = 0;       // max |difference| / max |SciPy's element|
    double exact_rssd = 0;        // max rssd on the exact sets (SciPy: its eigenvalue formula)
    double scipy_exact_rssd = 0;  // SciPy's largest rssd on those sets
    double mean_angle = 0;        // max rotation angle to SciPy's mean, rad
    int align_sets = 0, mean_sets = 0;
};

template <class T>
scipy_agreement measure_scipy() {
    namespace ref = quat::test::scipy;
    scipy_agreement out;
    for (const ref::align_case& c : ref::align_cases) {
        std::vector<quat::vec3<T>> targets, sources;
        std::vector<T> weights;
        for (std::size_t i = 0; i < c.count; ++i) {
            targets.push_back({T(c.targets[i][0]), T(c.targets[i][1]), T(c.targets[i][2])});
            sources.push_back({T(c.sources[i][0]), T(c.sources[i][1]), T(c.sources[i][2])});
            weights.push_back(T(c.weights[i]));
        }
        const auto result = quat::align_vectors_with_sensitivity(targets, sources, weights);
        if (!result.unique) continue;  // SciPy's answer is one of many
        ++out.align_sets;
        const quat::quaternion<T> expected{T(c.rotation[0]), T(c.rotation[1]), T(c.rotation[2]),
                                           T(c.rotation[3])};
        out.align_angle =
            std::max(out.align_angle, double(quat::angle_between(result.rotation, expected)));
        double largest = 0, difference = 0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                largest = std::max(largest, std::abs(c.sensitivity[i][j]));
                difference = std::max(
                    difference, std::abs(double(result.sensitivity(i, j)) - c.sensitivity[i][j]));
            }
        out.sensitivity = std::max(out.sensitivity, difference / largest);
        if (std::string_view(c.name).rfind("exact", 0) == 0) {
            out.exact_rssd = std::max(out.exact_rssd, double(result.rssd));
            out.scipy_exact_rssd = std::max(out.scipy_exact_rssd, c.rssd);
        }
    }
    for (const ref::mean_case& c : ref::mean_cases) {
        std::vector<quat::quaternion<T>> rotations;
        std::vector<T> weights;
        for (std::size_t i = 0; i < c.count; ++i) {
            const auto& q = c.rotations[i];
            rotations.push_back({T(q[0]), T(q[1]), T(q[2]), T(q[3])});
            weights.push_back(T(c.weights[i]));
        }
        ++out.mean_sets;
        const quat::quaternion<T> expected{T(c.mean[0]), T(c.mean[1]), T(c.mean[2]), T(c.mean[3])};
        out.mean_angle = std::max(
            out.mean_angle, double(quat::angle_between(quat::mean(rotations, weights), expected)));
    }
    return out;
}

/// Prints the tables; returns 0 (the bounds are asserted by tests/test_align_vectors.cpp,
/// tests/test_mean.cpp, tests/test_keyframe_slerp.cpp and tests/test_rotation_spline.cpp).
inline int run_scipy() {
    std::printf("| quat against SciPy 1.10 | float | double |\n|---|---|---|\n");
    const scipy_agreement f = measure_scipy<float>(), d = measure_scipy<double>();
    std::printf(
        "| align_vectors: rotation angle, rad (%d sets with a unique answer) | %.2g | %.2g |\n",
        d.align_sets, f.align_angle, d.align_angle);
    std::printf("| align_vectors: sensitivity, max difference / max element | %.2g | %.2g |\n",
                f.sensitivity, d.sensitivity);
    std::printf("| align_vectors: largest rssd on the exact sets (SciPy: %.2g) | %.2g | %.2g |\n",
                d.scipy_exact_rssd, f.exact_rssd, d.exact_rssd);
    std::printf("| mean: rotation angle, rad (%d sets) | %.2g | %.2g |\n", d.mean_sets,
                f.mean_angle, d.mean_angle);
    run_scipy_spline();
    return 0;
}

}  // namespace accuracy
