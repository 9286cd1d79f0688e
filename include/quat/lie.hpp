// The Lie-group family, for estimation: SO(3) and SE(3) with exp and log, plus and minus, adjoints
// and Jacobians, geodesic (Karcher) means on both groups, and the relative-pose errors of pose
// graphs. Opt-in: quat.hpp does not include it.
#ifndef QUAT_LIE_HPP_INCLUDED
#define QUAT_LIE_HPP_INCLUDED

#include "lie/geodesic_mean.hpp"
#include "lie/relative_pose.hpp"
#include "lie/se3.hpp"
#include "lie/so3.hpp"

#endif  // QUAT_LIE_HPP_INCLUDED
