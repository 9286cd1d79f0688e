// Must NOT compile: CTest glm_and_quat_unqualified_euler_is_ambiguous passes only when the compiler
// reports the ambiguity. After `using namespace glm; using namespace quat;` the name euler is both
// glm::euler<T>() (GLM's Euler-Mascheroni constant, from <glm/gtc/constants.hpp>, which
// <glm/gtc/quaternion.hpp> includes) and quat::euler (a class template), so user code writes
// ::quat::euler or a namespace alias's qt::euler (docs/integration.md "With GLM in the same file";
// tests/test_glm_namespace.cpp compiles those spellings). g++ 12 and clang++ 14 both reject it.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/quat.hpp>

using namespace glm;
using namespace quat;

double unqualified() {
    const euler<double> e{0.5, 0, 0};  // does not compile: glm::euler or quat::euler?
    return e[0];
}
