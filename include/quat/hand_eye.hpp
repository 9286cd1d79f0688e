// This header moved to quat/registration/hand_eye.hpp; the old path keeps compiling
// (docs/architecture.md, "Include paths before 1.1").
#include "registration/hand_eye.hpp"  // IWYU pragma: export
