// This header moved to quat/fitting/align_vectors.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "fitting/align_vectors.hpp"  // IWYU pragma: export
