// This header moved to quat/fitting/nearest_rotation.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "fitting/nearest_rotation.hpp"  // IWYU pragma: export
