// The paths family: slerp and its relatives (paths/interpolation.hpp), fast slerp approximations,
// squad, and paths through keyframes (piecewise slerp, squad, the C2 rotation spline).
// Included by quat.hpp.
#ifndef QUAT_PATHS_HPP_INCLUDED
#define QUAT_PATHS_HPP_INCLUDED

#include "paths/interpolation.hpp"
#include "paths/keyframe_slerp.hpp"
#include "paths/keyframe_squad.hpp"
#include "paths/rotation_spline.hpp"
#include "paths/slerp_fast.hpp"
#include "paths/squad.hpp"

#endif  // QUAT_PATHS_HPP_INCLUDED
