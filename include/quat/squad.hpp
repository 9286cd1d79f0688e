// This header moved to quat/paths/squad.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "paths/squad.hpp"  // IWYU pragma: export
