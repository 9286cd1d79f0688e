// single_include/quat/io.hpp with only single_include/ on the include path: it brings the single
// quat.hpp beside it, and a second include of either header is harmless.
#include <quat/io.hpp>
#include <quat/quat.hpp>
#include <sstream>
#include <string>

int main() {
    std::ostringstream out;
    out << quat::quaternion<double>{1, 0, 0, 0} << ' '
        << quat::euler<double, quat::sequence::zxz, quat::frame::extrinsic>{0.5, 0.25, 0};
    return out.str() == "quaternion{1, 0, 0, 0} euler<zxz, extrinsic>{0.5, 0.25, 0}" ? 0 : 1;
}
