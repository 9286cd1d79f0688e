// Instantiates continuous_euler.hpp for every convention and floating-point type under the strict
// warning flags (see instantiate.cpp).
#include <quat/continuous_euler.hpp>

namespace {

template <class T, quat::sequence S, quat::frame F>
T continuous(const quat::quaternion<T>& q) {
    const quat::euler<T, S, F> previous{T(3), T(1), T(-3)};
    return quat::to_euler(q, previous)[0] + quat::to_euler<S, F>(q, previous)[2];
}

template <class T>
T every_convention() {
    using quat::frame;
    using quat::sequence;
    const quat::quaternion<T> q{T(0.5), T(0.5), T(-0.5), T(0.5)};
    return continuous<T, sequence::xyz, frame::intrinsic>(q) +
           continuous<T, sequence::zyx, frame::extrinsic>(q) +
           continuous<T, sequence::zxz, frame::intrinsic>(q) +
           continuous<T, sequence::yzy, frame::extrinsic>(q);
}

}  // namespace

int main() {
    return static_cast<int>(every_convention<float>()) +
           static_cast<int>(every_convention<double>()) +
           static_cast<int>(every_convention<long double>());
}
