// A dependency vendors the single header while the project uses include/: one translation unit
// sees both, in either order, without redefinitions (the headers share their include guards).
#include <quat/quat.hpp>

#include "../../single_include/quat/quat.hpp"

double from_include_then_single() { return quat::rotate(quat::quatd::identity(), {1, 2, 3}).y; }
