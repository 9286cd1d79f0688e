// This header moved to quat/batch/elementwise.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "batch/elementwise.hpp"  // IWYU pragma: export
