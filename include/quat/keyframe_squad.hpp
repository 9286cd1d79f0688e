// This header moved to quat/paths/keyframe_squad.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "paths/keyframe_squad.hpp"  // IWYU pragma: export
