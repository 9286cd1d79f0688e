// The trajectory family: paths of a rigid body through (time, pose) keyframes (split_keyframe_path,
// se3_keyframe_path, with velocities and accelerations), and cumulative B-splines with uniform knots
// on SO(3) (so3_bspline), SE(3) (se3_bspline), R^3 (euclidean_bspline) and SO(3) x R^3
// (split_bspline), with body-frame velocities and their derivatives and analytic Jacobians with
// respect to the control points. Opt-in: quat.hpp does not include it.
#ifndef QUAT_TRAJECTORY_HPP_INCLUDED
#define QUAT_TRAJECTORY_HPP_INCLUDED

#include "trajectory/bspline_segment.hpp"
#include "trajectory/euclidean_bspline.hpp"
#include "trajectory/keyframe_path_state.hpp"
#include "trajectory/se3_bspline.hpp"
#include "trajectory/se3_keyframe_path.hpp"
#include "trajectory/so3_bspline.hpp"
#include "trajectory/split_bspline.hpp"
#include "trajectory/split_keyframe_path.hpp"

#endif  // QUAT_TRAJECTORY_HPP_INCLUDED
