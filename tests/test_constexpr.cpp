// Everything is usable in constant expressions, and compile-time results match run-time ones.
// The compile-time sqrt/sin/cos/atan2 (detail/math.hpp) compute in long double; the run-time
// ones are <cmath>. They agree to within tolerance<T>::constexpr_vs_runtime (8 epsilon).
#include <cmath>

#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_constexpr {

using namespace quat;

// Algebra, exactly (these hold under C++17 with any compiler).
static_assert(quatd{1, 2, 3, 4} * quatd{5, 6, 7, 8} == quatd{-60, 12, 30, 24});
static_assert(rotate(quatd{0, 0, 0, 1}, vec3<double>{1, 0, 0}) == vec3<double>{-1, 0, 0});
static_assert(to_matrix(quatd{0, 1, 0, 0}) ==
              rotation_matrix<double>::from_rows({1, 0, 0}, {0, -1, 0}, {0, 0, -1}));
// The compile-time elementary functions.
static_assert(detail::sqrt(4.0) == 2.0 && detail::sqrt(2.0) == 1.4142135623730951);
static_assert(detail::sqrt(1e-300) == 1e-150 && detail::sqrt(0.0) == 0.0);
static_assert(detail::cos(0.0) == 1.0 && detail::sin(0.0) == 0.0);
static_assert(detail::atan2(1.0, 1.0) == 0.78539816339744828);
static_assert(detail::atan2(0.0, -1.0) == 3.1415926535897931);
static_assert(detail::atan2(-0.0, -1.0) == -3.1415926535897931);

namespace {

// Results computed during compilation, for float, double and long double.
template <class T>
struct compile_time_results {
    static constexpr quaternion<T> a = normalize(quaternion<T>{T(0.3), T(-0.2), T(0.9), T(0.1)});
    static constexpr quaternion<T> b = to_quaternion(axis_angle<T>{{T(0), T(0.6), T(0.8)}, T(2.5)});
    static constexpr quaternion<T> from_euler =
        to_quaternion(euler<T, sequence::zxz>{{T(0.4), T(1.3), T(-2.2)}});
    static constexpr euler<T, sequence::yxz> angles = to_euler<sequence::yxz>(a);
    static constexpr quaternion<T> interpolated = slerp(a, b, T(0.3));
    static constexpr quaternion<T> exponential = from_rotation_vector(vec3<T>{T(0.5), T(-1), T(2)});
    static constexpr vec3<T> logarithm = to_rotation_vector(b);
    static constexpr quaternion<T> from_matrix = to_quaternion(to_matrix(b));
    static constexpr rotation_matrix<T> repaired = nearest_rotation(rotation_matrix<T>::from_rows(
        {T(1.01), T(0.02), T(0)}, {T(0), T(0.98), T(0.03)}, {T(0.01), T(0), T(1)}));
};

template <class T>
T run_time(T x) {  // hides x from the optimizer, so what follows runs at run time
    volatile T v = x;
    return v;
}

}  // namespace

TEMPLATE_TEST_CASE("compile-time results equal run-time results within 8 epsilon", "[constexpr]",
                   float, double, long double) {
    using T = TestType;
    using C = compile_time_results<T>;
    const T tol = test::tolerance<T>::constexpr_vs_runtime;
    const quaternion<T> a = normalize(quaternion<T>{run_time(T(0.3)), T(-0.2), T(0.9), T(0.1)});
    const quaternion<T> b = to_quaternion(axis_angle<T>{{T(0), T(0.6), T(0.8)}, run_time(T(2.5))});
    auto near = [tol](const quaternion<T>& x, const quaternion<T>& y) {
        return std::abs(x.w - y.w) <= tol && std::abs(x.x - y.x) <= tol &&
               std::abs(x.y - y.y) <= tol && std::abs(x.z - y.z) <= tol;
    };
    CHECK(near(C::a, a));
    CHECK(near(C::b, b));
    CHECK(near(C::from_euler,
               to_quaternion(euler<T, sequence::zxz>{{run_time(T(0.4)), T(1.3), T(-2.2)}})));
    const auto angles = to_euler<sequence::yxz>(a);
    for (int i = 0; i < 3; ++i) CHECK(std::abs(C::angles[i] - angles[i]) <= tol);
    CHECK(near(C::interpolated, slerp(a, b, run_time(T(0.3)))));
    CHECK(near(C::exponential, from_rotation_vector(vec3<T>{run_time(T(0.5)), T(-1), T(2)})));
    const vec3<T> logarithm = to_rotation_vector(b);
    CHECK(std::abs(C::logarithm.x - logarithm.x) + std::abs(C::logarithm.y - logarithm.y) +
              std::abs(C::logarithm.z - logarithm.z) <=
          tol);
    CHECK(near(C::from_matrix, to_quaternion(to_matrix(b))));
    const auto repaired = nearest_rotation(rotation_matrix<T>::from_rows(
        {run_time(T(1.01)), T(0.02), T(0)}, {T(0), T(0.98), T(0.03)}, {T(0.01), T(0), T(1)}));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) CHECK(std::abs(C::repaired(i, j) - repaired(i, j)) <= tol);
}

TEST_CASE("compile-time sin, cos and atan2 track <cmath> over rotation angles", "[constexpr]") {
    // Evaluated through the constexpr paths explicitly, at run time, against <cmath> in long
    // double.
    for (int n = -2000; n <= 2000; ++n) {
        const long double x = n * 0.01;  // a double, so both sides see the same argument
        const auto sc = detail::compile_time::sin_cos(x);
        CHECK(std::abs(static_cast<double>(sc.sin) - std::sin(static_cast<double>(x))) <=
              2 * test::eps<double>);
        CHECK(std::abs(static_cast<double>(sc.cos) - std::cos(static_cast<double>(x))) <=
              2 * test::eps<double>);
        const long double y = std::sin(static_cast<double>(n));  // exact double too
        CHECK(std::abs(static_cast<double>(detail::compile_time::atan2(y, x)) -
                       std::atan2(static_cast<double>(y), static_cast<double>(x))) <=
              4 * test::eps<double>);
        const long double r = std::abs(x) * 1e3L + 1e-300L;
        CHECK(static_cast<double>(detail::compile_time::sqrt(r)) ==
              Approx(std::sqrt(static_cast<double>(r))).epsilon(2 * test::eps<double>));
    }
}

// The first-use spellings in constant expressions.
static_assert(quatd{0, 0, 0, 1} * vec3<double>{1, 0, 0} == vec3<double>{-1, 0, 0});
static_assert(rotation_matrix<double>::identity() * vec3<double>{1, 2, 3} == vec3<double>{1, 2, 3});
static_assert(dual_quaterniond::from_translation({1, 2, 3}) * vec3<double>{1, 1, 1} ==
              vec3<double>{2, 3, 4});
static_assert(inverse(homogeneous_matrix<double>::from_translation({1, 2, 3})) *
                  vec3<double>{1, 2, 3} ==
              vec3<double>{0, 0, 0});
static_assert(angle(quatd{0, 0, 1, 0}) == numbers::pi &&
              axis(quatd{0, 0, 1, 0}) == vec3<double>{0, 1, 0});
static_assert(radians(180.0) == numbers::pi && vec3<double>{4, 5, 6}[1] == 5);
static_assert(lerp(vec3<double>{0, 0, 0}, vec3<double>{2, 4, 8}, 0.5) == vec3<double>{1, 2, 4});

TEMPLATE_TEST_CASE("compile-time exp and log of quaternions equal run-time ones within 8 epsilon",
                   "[constexpr][exp]", float, double, long double) {
    using T = TestType;
    const T tol = test::tolerance<T>::constexpr_vs_runtime;
    static constexpr quaternion<T> q{T(0.7), T(-0.4), T(1.1), T(0.3)};
    static constexpr quaternion<T> e = exp(q), l = log(q);
    const quaternion<T> hidden{run_time(q.w), run_time(q.x), run_time(q.y), run_time(q.z)};
    CHECK(test::max_difference(e, exp(hidden)) <= tol * 4);  // |e| = e^0.7: a few units
    CHECK(test::max_difference(l, log(hidden)) <= tol);
    // The scalar kernels over the whole range, against <cmath>.
    for (int n = -700; n <= 700; n += 7) {
        const long double x = n + 0.375L;
        CHECK(static_cast<double>(detail::compile_time::exp(x)) ==
              Approx(std::exp(static_cast<double>(x))).epsilon(2 * test::eps<double>).margin(0));
        const long double y = std::exp(static_cast<long double>(n) * 0.9L);
        CHECK(
            static_cast<double>(detail::compile_time::log(y)) ==
            Approx(std::log(static_cast<double>(y))).epsilon(2 * test::eps<double>).margin(1e-300));
    }
}

}  // namespace test_constexpr
