// The trajectory family: paths of a rigid body through (time, pose) keyframes, with velocities
// and accelerations. Opt-in: quat.hpp does not include it.
#ifndef QUAT_TRAJECTORY_HPP_INCLUDED
#define QUAT_TRAJECTORY_HPP_INCLUDED

#include "trajectory/keyframe_path_state.hpp"
#include "trajectory/se3_keyframe_path.hpp"
#include "trajectory/split_keyframe_path.hpp"

#endif  // QUAT_TRAJECTORY_HPP_INCLUDED
