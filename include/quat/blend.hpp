// This header moved to quat/rigid/blend.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "rigid/blend.hpp"  // IWYU pragma: export
