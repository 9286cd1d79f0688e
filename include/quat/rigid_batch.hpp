// This header moved to quat/batch/rigid_motions.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "batch/rigid_motions.hpp"  // IWYU pragma: export
