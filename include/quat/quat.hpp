// quat — 3D rotations for C++17/20: quaternions, Euler angles, axis-angle and rotation matrices,
// and rigid motions as dual quaternions and 4x4 homogeneous matrices.
// https://opensource.org/licenses/MIT
//
// Conventions, everywhere in this library:
// - Quaternions are scalar first, w + xi + yj + zk, with Hamilton's product: ij = k, jk = i, ki =
//   j.
// - Rotations are active (they move vectors; the frame stays) in right-handed coordinates, and a
//   positive angle turns counter-clockwise when seen from the tip of the axis toward the origin.
// - A unit quaternion q rotates v as q (0, v) q*; q and -q are the same rotation. Where a
//   conversion has to pick one, it returns the one with w >= 0.
// - Products compose right to left: a * b applies b first, then a, for quaternions and matrices
//   alike,
//   and to_matrix(a * b) == to_matrix(a) * to_matrix(b).
// - Matrices act on column vectors, v' = M v, and rotate(q, v) == rotate(to_matrix(q), v).
// - Euler angles carry their axis sequence and frame in their type: euler<T, sequence::zyx,
//   frame::intrinsic>{a0, a1, a2} is R = Rz(a0) Ry(a1) Rx(a2); frame::extrinsic reverses the
//   product.
// - Rigid motions are x -> R x + t, rotation first: a dual quaternion real + eps dual has real = q
//   and dual = (0, t) q / 2, and a homogeneous matrix is [R t; 0 0 0 1] acting on (x, y, z, 1);
//   their products compose right to left like the rotations'.
// - Angles are in radians. Functions expecting unit input say so; try_* functions check untrusted
//   input
//   and return an empty std::optional instead of NaN.
#ifndef QUAT_QUAT_HPP_INCLUDED
#define QUAT_QUAT_HPP_INCLUDED

#include "align.hpp"
#include "axis_angle.hpp"
#include "config.hpp"
#include "constants.hpp"
#include "continuous_euler.hpp"
#include "conversions.hpp"
#include "euler.hpp"
#include "kinematics.hpp"
#include "quaternion.hpp"
#include "random.hpp"
#include "rotation_matrix.hpp"
#include "swing_twist.hpp"
#include "vec3.hpp"

// The families quat.hpp brings; lie.hpp and registration.hpp are opt-in.
#include "batch.hpp"
#include "fitting.hpp"
#include "paths.hpp"
#include "rigid.hpp"

#endif  // QUAT_QUAT_HPP_INCLUDED
