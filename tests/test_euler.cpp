// Specification of euler.hpp: all 12 sequences in both frames, canonical ranges and gimbal lock.
#include <cmath>
#include <type_traits>
#include <utility>

#include <quat/euler.hpp>

#include "support/catch.hpp"
#include "support/conventions.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_euler {

using quat::euler;
using quat::frame;
using quat::quaternion;
using quat::sequence;
using quat::vec3;
using quat::test::for_each_convention;
using quat::test::tolerance;

static_assert(!std::is_convertible_v<euler<double, sequence::zyx>, euler<double, sequence::xyz>>,
              "conventions don't mix");
static_assert(!std::is_convertible_v<euler<double, sequence::zyx, frame::intrinsic>,
                                     euler<double, sequence::zyx, frame::extrinsic>>);
static_assert(std::is_same_v<euler<double>, euler<double, sequence::zyx, frame::intrinsic>>,
              "the thesis's R = Rz Ry Rx is the default");
static_assert(std::is_trivially_default_constructible_v<euler<float>>, "a plain struct");
static_assert(std::is_constructible_v<euler<double>, euler<float>> &&
                  !std::is_convertible_v<euler<float>, euler<double>>,
              "precisions convert explicitly only");

namespace {

template <class T>
vec3<T> unit_axis(int axis) {
    return {T(axis == 0), T(axis == 1), T(axis == 2)};
}

// Independent reference: the definition, a product of three axis-angle rotations.
template <class T, sequence S, frame F>
quaternion<T> by_definition(const euler<T, S, F>& e) {
    constexpr auto axes = quat::detail::axes_of(S);
    const quaternion<T> q0 =
        quat::to_quaternion(quat::axis_angle<T>{unit_axis<T>(axes.first), e[0]});
    const quaternion<T> q1 =
        quat::to_quaternion(quat::axis_angle<T>{unit_axis<T>(axes.second), e[1]});
    const quaternion<T> q2 =
        quat::to_quaternion(quat::axis_angle<T>{unit_axis<T>(axes.third), e[2]});
    return F == frame::intrinsic ? q0 * q1 * q2 : q2 * q1 * q0;
}

template <sequence S>
constexpr bool is_proper = quat::detail::axes_of(S).first == quat::detail::axes_of(S).third;

}  // namespace

TEMPLATE_TEST_CASE("Euler angles to quaternion and matrix follow the definition", "[euler]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    for_each_convention<T>([&](auto convention) {
        using E = decltype(convention);
        for (int n = 0; n < 300; ++n) {
            const E e{{random.uniform<T>(-3.14, 3.14), random.uniform<T>(-3.14, 3.14),
                       random.uniform<T>(-3.14, 3.14)}};
            const quaternion<T> reference = by_definition(e);
            CHECK(quat::angle_between(quat::to_quaternion(e), reference) <=
                  tolerance<T>::round_trip);
            CHECK(quat::test::max_difference(quat::to_matrix(e), quat::to_matrix(reference)) <=
                  tolerance<T>::conversion);
        }
    });
}

TEMPLATE_TEST_CASE("quaternion -> Euler -> quaternion reproduces the rotation in canonical ranges",
                   "[euler]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for_each_convention<T>([&](auto convention) {
        using E = decltype(convention);
        constexpr sequence S = E::axis_sequence;
        constexpr frame F = E::rotation_frame;
        const T pi = quat::numbers::pi_v<T>;
        for (int n = 0; n < 2000; ++n) {
            const quaternion<T> q = random.unit_quaternion<T>();
            const E e = quat::to_euler<S, F>(q);
            CHECK(quat::angle_between(quat::to_quaternion(e), q) <= tolerance<T>::euler_round_trip);
            CHECK(std::abs(e[0]) <= pi);
            CHECK(std::abs(e[2]) <= pi);
            if constexpr (is_proper<S>) {
                CHECK((e[1] >= 0 && e[1] <= pi));
            } else {
                CHECK(std::abs(e[1]) <= pi / 2);
            }
            const E from_matrix = quat::to_euler<S, F>(quat::to_matrix(q));
            CHECK(quat::angle_between(quat::to_quaternion(from_matrix), q) <=
                  tolerance<T>::euler_round_trip);
        }
    });
}

TEST_CASE("at and near gimbal lock the angles still reproduce the rotation to 1e-12", "[euler]") {
    quat::test::random_rotations random;
    const double pi = quat::numbers::pi;
    for_each_convention<double>([&](auto convention) {
        using E = decltype(convention);
        constexpr sequence S = E::axis_sequence;
        constexpr frame F = E::rotation_frame;
        // Tait-Bryan sequences lock at a middle angle of +-pi/2, proper Euler ones at 0 and pi.
        const double locks[2] = {is_proper<S> ? 0.0 : -pi / 2, is_proper<S> ? pi : pi / 2};
        for (const double lock : locks) {
            for (int k = 1; k <= 16; ++k) {
                const double offset = k == 16 ? 0.0 : std::pow(10.0, -k);
                for (const double side : {-1.0, 1.0}) {
                    const E e{{random.uniform<double>(-3, 3), lock + side * offset,
                               random.uniform<double>(-3, 3)}};
                    const quaternion<double> q = quat::to_quaternion(e);
                    const auto extraction = quat::extract_euler<S, F>(q);
                    CAPTURE(static_cast<int>(S), static_cast<int>(F), lock, side * offset);
                    CHECK(quat::angle_between(quat::to_quaternion(extraction.angles), q) <= 1e-12);
                    if (offset == 0) {
                        CHECK(extraction.gimbal_lock);
                        CHECK(extraction.angles[2] == 0);
                    }
                    if (offset >= 1e-12) CHECK_FALSE(extraction.gimbal_lock);
                }
            }
        }
    });
}

TEST_CASE("gimbal lock: two different Euler triples give one rotation, and extract_euler says so",
          "[euler]") {
    using E = euler<double>;  // R = Rz(yaw) Ry(pitch) Rx(roll)
    const double pitch = quat::numbers::pi / 2;
    // With pitch = 90°, yaw and roll turn about the same world axis: only yaw - roll matters.
    const E a{{0.7, pitch, 0.2}}, b{{0.9, pitch, 0.4}};
    CHECK(quat::angle_between(quat::to_quaternion(a), quat::to_quaternion(b)) <= 1e-15);
    const auto extraction = quat::extract_euler<quat::sequence::zyx>(quat::to_quaternion(a));
    CHECK(extraction.gimbal_lock);
    CHECK(extraction.angles[0] == Approx(0.5));
    CHECK(extraction.angles[1] == Approx(pitch));
    CHECK(extraction.angles[2] == 0);
    CHECK_FALSE(quat::extract_euler<quat::sequence::zyx>(quat::to_quaternion(E{{0.7, 1.2, 0.2}}))
                    .gimbal_lock);
}

TEST_CASE("the default convention is the thesis's yaw-pitch-roll, R = Rz Ry Rx", "[euler]") {
    const euler<double> e{{0.3, -0.4, 1.1}};  // yaw psi, pitch theta, roll phi
    const auto rz = quat::to_matrix(quat::axis_angle<double>{{0, 0, 1}, 0.3});
    const auto ry = quat::to_matrix(quat::axis_angle<double>{{0, 1, 0}, -0.4});
    const auto rx = quat::to_matrix(quat::axis_angle<double>{{1, 0, 0}, 1.1});
    CHECK(quat::test::max_difference(quat::to_matrix(e), rz * ry * rx) <= 1e-15);
    // The extrinsic x-y-z sequence with reversed angles is the same rotation.
    const euler<double, sequence::xyz, frame::extrinsic> fixed_axes{{1.1, -0.4, 0.3}};
    CHECK(quat::test::max_difference(quat::to_matrix(fixed_axes), rz * ry * rx) <= 1e-15);
    const auto converted = quat::to_euler<sequence::xyz, frame::extrinsic>(e);
    CHECK(converted[0] == Approx(1.1));
    CHECK(converted[2] == Approx(0.3));
}

namespace {

template <sequence S, frame F>
void check_structured_bindings() {
    euler<double, S, F> e{0.25, -0.5, 1.5};
    auto [a0, a1, a2] = e;
    CHECK((a0 == 0.25 && a1 == -0.5 && a2 == 1.5));
    auto& [r0, r1, r2] = e;
    r1 = 2;
    CHECK(e[1] == 2);
    (void)r0;
    (void)r2;
    static_assert(std::tuple_size_v<euler<double, S, F>> == 3);
    static_assert(std::is_same_v<std::tuple_element_t<2, euler<float, S, F>>, float>);
    const euler<float, S, F> single{e};  // explicit precision change keeps the convention
    CHECK(single[0] == 0.25f);
    CHECK(single[1] == 2.0f);
    static_assert(!std::is_convertible_v<euler<double, S, F>, euler<float, S, F>>);
}

template <std::size_t... I>
void check_all_structured_bindings(std::index_sequence<I...>) {
    constexpr sequence all[12] = {sequence::xyz, sequence::xzy, sequence::yxz, sequence::yzx,
                                  sequence::zxy, sequence::zyx, sequence::xyx, sequence::xzx,
                                  sequence::yxy, sequence::yzy, sequence::zxz, sequence::zyz};
    (check_structured_bindings < all[I / 2], I % 2 == 0 ? frame::intrinsic : frame::extrinsic > (),
     ...);
}

}  // namespace

TEST_CASE("auto [a0, a1, a2] = e works for every Euler convention", "[euler][first-use]") {
    check_all_structured_bindings(std::make_index_sequence<24>{});
    constexpr euler<double> from_array{{1.0, 2.0, 3.0}};
    static_assert(from_array[2] == 3.0, "euler<T>{{a0, a1, a2}} still initializes from an array");
    static_assert(!std::is_constructible_v<euler<double, sequence::xyz>, euler<double>>,
                  "conventions never convert into each other");
}

}  // namespace test_euler
