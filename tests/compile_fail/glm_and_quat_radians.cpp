// Must NOT compile: CTest glm_and_quat_unqualified_radians_is_ambiguous passes only when the
// compiler reports the ambiguity. After `using namespace glm; using namespace quat;` the names
// radians and degrees are function templates taking any scalar in both libraries, equally good for
// a double, so user code writes ::quat::radians or glm::radians (equal for double)
// (docs/integration.md "With GLM in the same file"; tests/test_glm_namespace.cpp compiles those
// spellings). g++ 12 and clang++ 14 both reject it.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/quat.hpp>

using namespace glm;
using namespace quat;

double unqualified() {
    return radians(90.0);  // does not compile: glm::radians or quat::radians?
}
