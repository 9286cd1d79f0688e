// A batch call with a constant count, in a loop as a caller's frame loop makes it: g++ 12 warned
// here of an overflowing iteration (-Waggressive-loop-optimizations; rotate by a matrix, 1024
// points, -O2 -march=x86-64-v3), which -Werror turns into a failed build of user code. One call
// alone in its translation unit: beside other callers g++ keeps the batch loop out of line and
// the warning does not show. Built with -Werror (tests/contracts/CMakeLists.txt); nothing runs.
#include <quat/batch.hpp>

void rotate_1024_points(const quat::rotation_matrix<float>& m, const quat::vec3<float>* in,
                        quat::vec3<float>* out, int frames) {
    for (int frame = 0; frame < frames; ++frame) quat::rotate(m, in, out, 1024);
}
