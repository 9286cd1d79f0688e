// This header moved to quat/lie/geodesic_mean.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "lie/geodesic_mean.hpp"  // IWYU pragma: export
