// This header moved to quat/paths/rotation_spline.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "paths/rotation_spline.hpp"  // IWYU pragma: export
