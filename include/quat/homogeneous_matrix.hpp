// This header moved to quat/rigid/homogeneous_matrix.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "rigid/homogeneous_matrix.hpp"  // IWYU pragma: export
