// The other order: the vendored single header first, then quat's own headers.
#include "../../single_include/quat/quat.hpp"

#include <quat/batch/rotations.hpp>
#include <quat/euler.hpp>
#include <quat/quat.hpp>

double from_include_then_single();

int main() {
    const double y =
        quat::to_quaternion(quat::euler<double>{0, 0, 0}).w + from_include_then_single();
    return y == 3.0 ? 0 : 1;
}
