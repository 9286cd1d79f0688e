// The rigid-motion family, x -> R x + t: dual quaternions, homogeneous matrices, screw parameters,
// screw interpolation (sclerp), dual-quaternion blending, and similarities (a rigid motion after a
// uniform scale). Included by quat.hpp.
#ifndef QUAT_RIGID_HPP_INCLUDED
#define QUAT_RIGID_HPP_INCLUDED

#include "rigid/blend.hpp"
#include "rigid/dual_quaternion.hpp"
#include "rigid/homogeneous_matrix.hpp"
#include "rigid/sclerp.hpp"
#include "rigid/screw.hpp"
#include "rigid/similarity.hpp"

#endif  // QUAT_RIGID_HPP_INCLUDED
