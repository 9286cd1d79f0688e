// This header moved to quat/lie/se3.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "lie/se3.hpp"  // IWYU pragma: export
