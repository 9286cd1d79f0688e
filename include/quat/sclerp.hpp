// This header moved to quat/rigid/sclerp.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "rigid/sclerp.hpp"  // IWYU pragma: export
