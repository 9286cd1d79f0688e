// This header moved to quat/fitting/mean.hpp; the old path keeps compiling (docs/architecture.md,
// "Include paths before 1.1").
#include "fitting/mean.hpp"  // IWYU pragma: export
