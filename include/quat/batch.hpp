// The batch family: one rotation or rigid motion applied to many points, element-by-element
// products and conversions, and the struct-of-arrays views they take. Included by quat.hpp.
#ifndef QUAT_BATCH_HPP_INCLUDED
#define QUAT_BATCH_HPP_INCLUDED

#include "batch/elementwise.hpp"
#include "batch/rigid_motions.hpp"
#include "batch/rotations.hpp"
#include "batch/soa.hpp"

#endif  // QUAT_BATCH_HPP_INCLUDED
