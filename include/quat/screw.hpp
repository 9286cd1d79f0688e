// This header moved to quat/rigid/screw.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "rigid/screw.hpp"  // IWYU pragma: export
