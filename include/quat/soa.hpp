// This header moved to quat/batch/soa.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "batch/soa.hpp"  // IWYU pragma: export
