// The fitting family: the rotation that best aligns two sets of directions (Wahba's problem), the
// rotation nearest to a matrix, and the chordal mean of many rotations. Included by quat.hpp.
#ifndef QUAT_FITTING_HPP_INCLUDED
#define QUAT_FITTING_HPP_INCLUDED

#include "fitting/align_vectors.hpp"
#include "fitting/mean.hpp"
#include "fitting/nearest_rotation.hpp"

#endif  // QUAT_FITTING_HPP_INCLUDED
