// Must NOT compile: CTest glm_unqualified_quat_is_ambiguous (clang builds) passes only when the
// compiler reports that the reference to quat is ambiguous. After `using namespace glm;` the name
// quat means both glm::quat (a type) and namespace quat, which [namespace.udir]/6 makes ill-formed
// (g++ 12 accepts it anyway), so user code writes ::quat::quatd or a namespace alias
// (docs/integration.md "With GLM in the same file"; tests/test_glm_namespace.cpp compiles those
// spellings).
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <quat/quat.hpp>

using namespace glm;

double unqualified() {
    const quat::quatd q = quat::quatd::identity();  // does not compile: two candidates for quat
    return q.w;
}
