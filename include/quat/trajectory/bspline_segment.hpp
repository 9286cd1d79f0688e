// Where a time falls on a uniform B-spline: the first control point of its segment and the time
// into that segment, the two numbers interop/ceres_trajectory.hpp's residuals take.
#ifndef QUAT_TRAJECTORY_BSPLINE_SEGMENT_HPP_INCLUDED
#define QUAT_TRAJECTORY_BSPLINE_SEGMENT_HPP_INCLUDED

#include <cstddef>

#include "../config.hpp"

namespace quat {
#include "../detail/isa_namespace.inc"

/// The segment of a uniform B-spline of order K that holds a time t: its K control points are
/// first .. first + K - 1, and offset = t - t0 - first dt, in [0, dt] (the last segment includes
/// its end). What the splines' segment_at returns.
template <class T>
struct bspline_segment {
    std::size_t first;  ///< the segment's first control point
    T offset;           ///< the time since the segment's start, in [0, dt]
};

}  // inline namespace isa_...
}  // namespace quat

#endif  // QUAT_TRAJECTORY_BSPLINE_SEGMENT_HPP_INCLUDED
