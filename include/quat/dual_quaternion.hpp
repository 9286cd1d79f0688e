// This header moved to quat/rigid/dual_quaternion.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "rigid/dual_quaternion.hpp"  // IWYU pragma: export
