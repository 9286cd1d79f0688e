// This header moved to quat/paths/interpolation.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "paths/interpolation.hpp"  // IWYU pragma: export
