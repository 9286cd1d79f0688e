// This header moved to quat/lie/so3.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "lie/so3.hpp"  // IWYU pragma: export
