// This header moved to quat/paths/slerp_fast.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "paths/slerp_fast.hpp"  // IWYU pragma: export
