// quat — 3D rotations for C++17/20. Version numbers and the one overridable assertion.
#ifndef QUAT_CONFIG_HPP_INCLUDED
#define QUAT_CONFIG_HPP_INCLUDED

#define QUAT_VERSION_MAJOR 1
#define QUAT_VERSION_MINOR 0
#define QUAT_VERSION_PATCH 0

/// Precondition check used throughout quat. Defaults to assert(), so release builds pay nothing;
/// define QUAT_ASSERT(cond, msg) before including quat to throw, log or abort instead.
#ifndef QUAT_ASSERT
#include <cassert>
#define QUAT_ASSERT(cond, msg) assert((cond) && (msg))
#endif

#endif  // QUAT_CONFIG_HPP_INCLUDED
