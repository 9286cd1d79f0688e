// Must NOT compile: CTest glm_and_quat_unqualified_vec3_is_ambiguous passes only when the compiler
// reports the ambiguity. After `using namespace glm; using namespace quat;` the name vec3 is both
// glm::vec3 (a type) and quat::vec3 (a class template), so user code writes ::quat::vec3, glm::vec3
// or a namespace alias's qt::vec3 (docs/integration.md "With GLM in the same file";
// tests/test_glm_namespace.cpp compiles those spellings). g++ 12 and clang++ 14 both reject it.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/quat.hpp>

using namespace glm;
using namespace quat;

double unqualified() {
    const vec3<double> v{1, 0, 0};  // does not compile: glm::vec3 or quat::vec3?
    return v.x;
}
