// This header moved to quat/registration/align_points.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "registration/align_points.hpp"  // IWYU pragma: export
