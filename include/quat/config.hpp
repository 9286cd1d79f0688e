// quat — 3D rotations for C++17/20. Version numbers and the one overridable assertion.
#ifndef QUAT_CONFIG_HPP_INCLUDED
#define QUAT_CONFIG_HPP_INCLUDED

#define QUAT_VERSION_MAJOR 1
#define QUAT_VERSION_MINOR 1
#define QUAT_VERSION_PATCH 0

/// Precondition check used throughout quat: QUAT_ASSERT(condition, message), the message a string
/// literal naming the function and the precondition. Defaults to assert(), so builds with NDEBUG
/// pay nothing. Define it before including quat to log, trap or abort your way. The handler must
/// not return (past a failed index check the function would read out of bounds) and must not throw:
/// quat's functions are noexcept, so an exception leaving the handler calls std::terminate. Debug
/// builds check unit quaternions and axes (|q|^2 within 1/4096 of 1; NaN and infinities pass and
/// propagate), index ranges, output sizes and batch aliasing.
#ifndef QUAT_ASSERT
#include <cassert>
#define QUAT_ASSERT(cond, msg) assert((cond) && (msg))
#endif

#endif  // QUAT_CONFIG_HPP_INCLUDED
