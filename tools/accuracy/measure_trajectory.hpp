// `quat_accuracy --trajectory [--quick]`: the worst errors of the trajectory family's derivatives
// and Jacobians in double (measure_trajectory_bspline.hpp, measure_trajectory_paths.hpp say what
// each row compares), as two markdown tables: the B-splines by order K, the keyframe paths by
// path; each cell the worst over the sample classes, with the class it occurred in. Exit status 1
// when a row exceeds its bound (1e-12 relative to the largest entry of the
// reference, 1e-13 between forward-mode and analytic Jacobians, 8 eps between the recurrences and
// the product rule; 4 eps for the keyframes, the tests' bound).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "harness.hpp"
#include "measure_trajectory_bspline.hpp"
#include "measure_trajectory_paths.hpp"
#include "trajectory_differences.hpp"

namespace accuracy {
namespace trajectory {

inline void print_rows(const std::vector<measured_row>& rows) {
    for (const measured_row& r : rows) {
        const bool eps = r.unit == "eps";
        const std::string bound =
            std::isnan(r.bound) ? "—" : "≤ " + format_number(r.bound) + (eps ? " eps" : "");
        std::printf("| %s | %s | %s |", r.group.c_str(), r.quantity.c_str(), bound.c_str());
        for (std::size_t c = 0; c < r.columns.size(); ++c) {
            int which = 0;
            const worst_error* w = r.worst(c, &which);
            if (w == nullptr) {
                std::printf(" — |");
                continue;
            }
            std::printf(" %s (%s)%s |", format_number(w->max).c_str(), class_names[which],
                        std::isnan(r.bound) || w->max <= r.bound ? "" : " **exceeded**");
        }
        std::printf("\n");
    }
}

/// Prints each class's worst of a row that exceeds its bound, and returns how many rows did.
inline int report_exceeded(const std::vector<measured_row>& rows,
                           const std::vector<std::string>& columns) {
    int exceeded = 0;
    for (const measured_row& r : rows) {
        if (!r.exceeded()) continue;
        ++exceeded;
        for (std::size_t c = 0; c < r.columns.size(); ++c)
            for (int k = 0; k < class_count; ++k) {
                const worst_error& e = r.columns[c][static_cast<std::size_t>(k)];
                if (e.count > 0 && !std::isnan(r.bound) && !(e.max <= r.bound))
                    std::fprintf(stderr, "EXCEEDED: %s %s [%s, %s]: %s > %s at %s\n",
                                 r.group.c_str(), r.quantity.c_str(), columns[c].c_str(),
                                 class_names[k], format_number(e.max).c_str(),
                                 format_number(r.bound).c_str(), e.where.c_str());
            }
    }
    return exceeded;
}

inline int run_trajectory(bool quick, std::uint64_t seed) {
    const int sets = quick ? 1 : 6, random_times = quick ? 3 : 12;
    std::vector<measured_row> splines = measure_bspline<so3_kind>(sets, random_times, seed);
    for (measured_row& r : measure_bspline<se3_kind>(sets, random_times, seed + 1))
        splines.push_back(std::move(r));
    for (measured_row& r : measure_split_bspline(sets, random_times, seed + 2))
        splines.push_back(std::move(r));
    const int path_sets = quick ? 2 : 20, path_times = quick ? 5 : 30;
    const std::vector<measured_row> paths = measure_keyframe_paths(path_sets, path_times, seed + 3);

    std::printf(
        "Worst error in double over the sample classes (the class in brackets): random t (random "
        "control points, times inside segments), knots (the same points at every knot), near "
        "identity (points within 1e-7 of the identity), near π (increments of π − 1e-2 rad); "
        "\"relative\" rows: max \\|error\\| / max \\|entry\\| of the reference, for the "
        "rates (and the eps rows of the rates) the rate's largest entry over the set's times.\n\n");
    std::printf("| spline | quantity | bound | K = 4 | K = 5 | K = 6 |\n");
    std::printf("|---|---|---|---|---|---|\n");
    print_rows(splines);
    std::printf(
        "\nReferences: the library's own long double evaluation, differentiated by "
        "Richardson-extrapolated differences (in time: central with steps 1e-3 dt, /2, /4 inside "
        "segments, one-sided with steps 1e-3 dt … /32 at knots; over the control points: central "
        "in δ of x_m exp(δ), steps 1e-3, /2, /4); dual numbers (tests/support/dual_number.hpp) "
        "through the double evaluation; the O(K²) product rule "
        "(tests/support/bspline_reference.hpp) in long double on the control points normalized "
        "in long double. Per order and class %d sets of 12 control points, every knot and %d "
        "random times each; seed %llu.\n\n",
        sets, random_times, static_cast<unsigned long long>(seed));

    std::printf("| keyframe path | quantity | bound | split_keyframe_path | se3_keyframe_path |\n");
    std::printf("|---|---|---|---|---|\n");
    print_rows(paths);
    std::printf(
        "\nKeyframe paths: 12 keyframes, durations 0.05 … 0.5 (log-uniform), rotation steps up to "
        "2 rad and translation steps of about 1 (random t, knots: the keyframes), both below 1e-7 "
        "from the identity, or rotation steps of π − 1e-2 rad; rates against Richardson "
        "differences in time of the long double path (one-sided at keyframes); %d sets a class, "
        "every keyframe and %d random times each.\n",
        path_sets, path_times);

    const int exceeded = report_exceeded(splines, {"K = 4", "K = 5", "K = 6"}) +
                         report_exceeded(paths, {"split_keyframe_path", "se3_keyframe_path"});
    if (exceeded > 0) std::fprintf(stderr, "%d trajectory rows exceed their bounds\n", exceeded);
    return exceeded;
}

}  // namespace trajectory
}  // namespace accuracy
