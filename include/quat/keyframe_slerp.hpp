// This header moved to quat/paths/keyframe_slerp.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "paths/keyframe_slerp.hpp"  // IWYU pragma: export
