// The registration family: the rigid motion (and scale) that best aligns two point sets, and
// hand-eye calibration. Opt-in: quat.hpp does not include it.
#ifndef QUAT_REGISTRATION_HPP_INCLUDED
#define QUAT_REGISTRATION_HPP_INCLUDED

#include "registration/align_points.hpp"
#include "registration/hand_eye.hpp"

#endif  // QUAT_REGISTRATION_HPP_INCLUDED
