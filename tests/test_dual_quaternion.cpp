// Specification of rigid/dual_quaternion.hpp: dual quaternions as rigid motions x -> R x + t,
// checked against 4x4 matrices in long double (tests/support/rigid_reference.hpp) and GLM's
// tdualquat.
#include <cmath>
#include <limits>
#include <type_traits>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/dual_quaternion.hpp>
#include <quat/interop/glm.hpp>
#include <quat/rigid/dual_quaternion.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/rigid_reference.hpp"
#include "support/same_bits.hpp"
#include "support/tolerance.hpp"

namespace test_dual_quaternion {

using quat::dual_quaternion;
using quat::quaternion;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

namespace {

// R p + t from the long double matrix of dq.
template <class T>
vec3<long double> reference_transform(const dual_quaternion<T>& dq, const vec3<T>& p) {
    const quat::test::matrix4 m = quat::test::reference_matrix(dq);
    const long double x = p.x, y = p.y, z = p.z;
    return {m[0][0] * x + m[0][1] * y + m[0][2] * z + m[0][3],
            m[1][0] * x + m[1][1] * y + m[1][2] * z + m[1][3],
            m[2][0] * x + m[2][1] * y + m[2][2] * z + m[2][3]};
}

using quat::test::same_bits;

template <class T>
long double difference(const vec3<T>& a, const vec3<long double>& b) {
    return std::max({std::fabs(a.x - b.x), std::fabs(a.y - b.y), std::fabs(a.z - b.z)});
}

}  // namespace

TEMPLATE_TEST_CASE("to_dual_quaternion(q, t) is the motion x -> R x + t, rotation first",
                   "[dual_quaternion]", float, double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        const quaternion<TestType> q = random.unit_quaternion<TestType>();
        const vec3<TestType> t = random.vector<TestType>(2.0);
        const vec3<TestType> p = random.vector<TestType>(1.0);
        const auto dq = quat::to_dual_quaternion(q, t);
        CHECK(quat::rotation_of(dq) == q);
        CHECK(max_difference(quat::translation_of(dq), t) <= 32 * eps<TestType>);
        const vec3<TestType> moved = quat::transform(dq, p);
        CHECK(difference(moved, reference_transform(dq, p)) <= 16 * eps<TestType>);
        CHECK(max_difference(moved, quat::rotate(q, p) + t) <= 16 * eps<TestType>);
        CHECK(max_difference(quat::transform_vector(dq, p), quat::rotate(q, p)) == 0);
        // dq and -dq are one motion.
        CHECK(max_difference(quat::transform(-dq, p), moved) <= 16 * eps<TestType>);
    }
}

TEMPLATE_TEST_CASE("a * b applies b first, as 4x4 products do", "[dual_quaternion]", float,
                   double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        const auto a = random.rigid_motion<TestType>();
        const auto b = random.rigid_motion<TestType>();
        const vec3<TestType> p = random.vector<TestType>(1.0);
        const auto ab = a * b;
        const quat::test::matrix4 reference =
            quat::test::reference_matrix(a) * quat::test::reference_matrix(b);
        CHECK(quat::test::max_difference(quat::test::reference_matrix(ab), reference) <=
              32 * eps<TestType>);
        CHECK(max_difference(quat::transform(ab, p), quat::transform(a, quat::transform(b, p))) <=
              32 * eps<TestType>);
        auto c = a;
        c *= b;
        CHECK(c == ab);
    }
}

TEMPLATE_TEST_CASE("inverse is the rigid inverse x -> R^T (x - t), also of scaled input",
                   "[dual_quaternion]", float, double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        const auto a = random.rigid_motion<TestType>();
        const vec3<TestType> p = random.vector<TestType>(1.0);
        const auto back = quat::transform(quat::inverse(a), quat::transform(a, p));
        CHECK(max_difference(back, p) <= 32 * eps<TestType>);
        const auto product = a * quat::inverse(a);
        CHECK(max_difference(product.real, quaternion<TestType>::identity()) <= 4 * eps<TestType>);
        CHECK(max_difference(product.dual, quaternion<TestType>{0, 0, 0, 0}) <= 16 * eps<TestType>);
        // A scaled unit dual quaternion: the inverse of s dq is dq^-1 / s.
        const TestType s = TestType(2.5);
        const dual_quaternion<TestType> scaled{a.real * s, a.dual * s};
        const auto scaled_inverse = quat::inverse(scaled);
        CHECK(max_difference(scaled_inverse.real * s, quat::conjugate(a.real)) <=
              4 * eps<TestType>);
        CHECK(max_difference(scaled_inverse.dual * s, quat::conjugate(a.dual)) <=
              8 * eps<TestType>);
    }
}

TEMPLATE_TEST_CASE("normalize gives a unit real part and a dual part orthogonal to it",
                   "[dual_quaternion]", float, double) {
    quat::test::random_rotations random;
    for (int i = 0; i < 200; ++i) {
        const auto a = random.rigid_motion<TestType>();
        const TestType s = random.uniform<TestType>(0.01, 100.0);
        const TestType drift = random.uniform<TestType>(-0.1, 0.1);
        // Scaled, and the dual part pushed along the real part (as rounding in long chains does).
        const dual_quaternion<TestType> off{a.real * s, (a.dual + a.real * drift) * s};
        const auto n = quat::normalize(off);
        CHECK(std::abs(quat::norm(n.real) - 1) <= quat::test::tolerance<TestType>::unit_norm);
        CHECK(std::abs(quat::dot(n.real, n.dual)) <= 8 * eps<TestType>);
        CHECK(max_difference(n.real, a.real) <= 4 * eps<TestType>);
        CHECK(max_difference(quat::translation_of(n), quat::translation_of(a)) <=
              32 * eps<TestType>);
    }
}

TEST_CASE("try_normalize rejects a zero real part and non-finite input", "[dual_quaternion]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const quat::quatd zero{0, 0, 0, 0};
    CHECK_FALSE(quat::try_normalize(quat::dual_quaterniond{zero, {0, 1, 0, 0}}));
    CHECK_FALSE(quat::try_normalize(quat::dual_quaterniond{{1, 0, 0, 0}, {0, nan, 0, 0}}));
    CHECK_FALSE(quat::try_normalize(quat::dual_quaterniond{{1, 0, 0, 0}, {0, 0, inf, 0}}));
    CHECK_FALSE(quat::try_normalize(quat::dual_quaterniond{{nan, 0, 0, 0}, {0, 0, 0, 0}}));
    const auto ok = quat::try_normalize(quat::dual_quaterniond{{2, 0, 0, 0}, {0, 2, 0, 0}});
    REQUIRE(ok);
    CHECK(quat::translation_of(*ok) == vec3<double>{2, 0, 0});
    // The unchecked normalize documents NaN for the zero real part.
    CHECK(std::isnan(quat::normalize(quat::dual_quaterniond{zero, zero}).real.w));
}

TEST_CASE("dual quaternions agree with GLM's tdualquat", "[dual_quaternion][glm]") {
    quat::test::random_rotations random;
    for (int i = 0; i < 100; ++i) {
        const quaternion<double> q = random.unit_quaternion<double>();
        const vec3<double> t = random.vector<double>(2.0);
        const vec3<double> p = random.vector<double>(1.0);
        const auto ours = quat::to_dual_quaternion(q, t);
        const glm::dualquat theirs_f(quat::to_glm(quaternion<float>(q)),
                                     quat::to_glm(vec3<float>(t)));
        const glm::tdualquat<double> theirs(quat::to_glm(q), quat::to_glm(t));
        CHECK(max_difference(quat::from_glm(theirs.real), ours.real) == 0);
        CHECK(max_difference(quat::from_glm(theirs.dual), ours.dual) <= 2 * eps<double>);
        CHECK(max_difference(quat::from_glm(theirs * quat::to_glm(p)), quat::transform(ours, p)) <=
              32 * eps<double>);
        const auto other =
            quat::to_dual_quaternion(random.unit_quaternion<double>(), random.vector<double>(2.0));
        const glm::tdualquat<double> other_glm(quat::to_glm(other.real), quat::to_glm(other.dual));
        const auto product = theirs * other_glm;
        CHECK(max_difference(quat::from_glm(product.real), (ours * other).real) <= 4 * eps<double>);
        CHECK(max_difference(quat::from_glm(product.dual), (ours * other).dual) <= 8 * eps<double>);
        CHECK(max_difference(quat::from_glm(theirs_f.dual), quaternion<float>(ours.dual)) <=
              8 * eps<float>);
    }
}

TEST_CASE("dual quaternion edge cases", "[dual_quaternion]") {
    const auto identity = quat::dual_quaterniond::identity();
    const vec3<double> p{1, -2, 3};
    CHECK(quat::transform(identity, p) == p);
    CHECK(quat::translation_of(identity) == vec3<double>{0, 0, 0});
    // A pure translation.
    const auto shift = quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{4, 5, 6});
    CHECK(quat::transform(shift, p) == vec3<double>{5, 3, 9});
    CHECK(quat::transform_vector(shift, p) == p);
    // A half turn about z, then the shift: exact in every component.
    const auto turn = quat::to_dual_quaternion(quat::quatd{0, 0, 0, 1}, vec3<double>{4, 5, 6});
    CHECK(quat::transform(turn, p) == vec3<double>{3, 7, 9});
    CHECK(turn != shift);
    CHECK(quat::dual_quaternion<float>(turn).dual.w == -3.0f);  // -t . axis / 2
    // NaN in, NaN out.
    auto bad = turn;
    bad.real.x = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isnan(quat::transform(bad, p).y));
    CHECK(std::isnan(quat::inverse(bad).dual.z));
    CHECK(std::isnan(quat::translation_of(bad).z));
}

TEST_CASE("dual quaternion algebra is constexpr", "[dual_quaternion][constexpr]") {
    constexpr auto a = quat::to_dual_quaternion(quat::quatd{0, 0, 0, 1}, vec3<double>{1, 0, 0});
    constexpr auto b = quat::to_dual_quaternion(quat::quatd::identity(), vec3<double>{0, 2, 0});
    constexpr vec3<double> moved = quat::transform(a * b, vec3<double>{0, 0, 0});
    static_assert(moved.x == 1 && moved.y == -2 && moved.z == 0);
    constexpr auto back = quat::inverse(a) * a;
    STATIC_REQUIRE(back.real.w == 1);
}

TEMPLATE_TEST_CASE("inverse is the multiplicative inverse of any dual quaternion with real part",
                   "[dual_quaternion][edge]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    quat::test::random_rotations rng;
    const dual_quaternion<T> one{quaternion<T>::identity(), quaternion<T>{0, 0, 0, 0}};
    for (int i = 0; i < 100; ++i) {
        // A dual part not orthogonal to the real part, as GLM's inverse also handles.
        const dual_quaternion<T> dq{rng.unit_quaternion<T>(), rng.unit_quaternion<T>() * T(3)};
        const dual_quaternion<T> product = dq * quat::inverse(dq);
        CHECK(quat::test::max_difference(product.real, one.real) <= 16 * limits::epsilon());
        CHECK(quat::test::max_difference(product.dual, one.dual) <= 64 * limits::epsilon());
        // Huge and tiny real parts whose inverse is representable.
        const T big = sizeof(T) == 4 ? T(1e30) : T(1e300);
        for (T scale : {big, T(1) / big}) {
            INFO("scale " << scale);
            const dual_quaternion<T> scaled{dq.real * scale, dq.dual * scale};
            const dual_quaternion<T> inverse = quat::inverse(scaled);
            const dual_quaternion<T> expected = quat::inverse(dq);
            CHECK(quat::test::max_difference(inverse.real * scale, expected.real) <=
                  16 * limits::epsilon());
            CHECK(quat::test::max_difference(inverse.dual * scale, expected.dual) <=
                  64 * limits::epsilon());
        }
    }
    const dual_quaternion<T> zero_real{quaternion<T>{0, 0, 0, 0}, quaternion<T>{0, 1, 0, 0}};
    CHECK(std::isnan(quat::inverse(zero_real).real.w));
    CHECK(std::isnan(quat::inverse(zero_real).dual.x));
}

TEST_CASE("try_normalize of a dual quaternion is empty when the dual part overflows",
          "[dual_quaternion][edge]") {
    // The float case: |real| = 1e-20, so the dual part 1e30 becomes 1e50.
    const dual_quaternion<float> dq{quaternion<float>{1e-20f, 0, 0, 0},
                                    quaternion<float>{0, 1e30f, 0, 0}};
    CHECK_FALSE(quat::try_normalize(dq).has_value());
    const dual_quaternion<float> fine{quaternion<float>{1e-20f, 0, 0, 0},
                                      quaternion<float>{0, 1e-19f, 0, 0}};
    const auto normalized = quat::try_normalize(fine);
    REQUIRE(normalized.has_value());
    CHECK(normalized->dual.x == Approx(10.0f));
}

TEMPLATE_TEST_CASE("dq * p is transform(dq, p), bit for bit, and GLM's tdualquat * vec3",
                   "[dual_quaternion][first-use]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (int i = 0; i < 2000; ++i) {
        const dual_quaternion<T> dq = random.rigid_motion<T>();
        const vec3<T> p = random.vector<T>(3.0);
        // A point transform: rotated, then translated (transform_vector turns a direction only).
        CHECK(same_bits(dq * p, quat::transform(dq, p)));
        const glm::tdualquat<T> theirs(quat::to_glm(dq.real), quat::to_glm(dq.dual));
        CHECK(max_difference(quat::from_glm(theirs * quat::to_glm(p)), dq * p) <= 64 * eps<T>);
    }
    constexpr auto shift = quat::dual_quaterniond::from_translation({4, 5, 6});
    static_assert(shift * vec3<double>{1, -2, 3} == vec3<double>{5, 3, 9});
}

TEMPLATE_TEST_CASE(
    "transform(dq, p) is rotate(real, p) + translation_of(dq), bit for bit, and "
    "stays finite where R p pulls a translation past max() back",
    "[dual_quaternion][edge]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    quat::test::random_rotations random;
    for (int i = 0; i < 2000; ++i) {
        // A real part up to a few eps off unit, as normalize leaves it.
        dual_quaternion<T> dq = random.rigid_motion<T>();
        dq.real = dq.real * (T(1) + T(random.uniform<double>(-4, 4)) * limits::epsilon());
        const vec3<T> p = random.vector<T>(3.0);
        CHECK(
            same_bits(quat::transform(dq, p), quat::rotate(dq.real, p) + quat::translation_of(dq)));
    }
    // t = 2 dual real* has x = 2^(max_exponent), one binade past max(), which translation_of
    // clamps to max(). p = -max() brings the point back: R p + t = 2^(max_exponent) - max() is
    // exact, and transform gives it, where rotate + translation_of would give 0.
    const T half_t = std::ldexp(T(1), limits::max_exponent - 1);
    const dual_quaternion<T> far{quaternion<T>::identity(), quaternion<T>{0, half_t, 0, 0}};
    CHECK(quat::translation_of(far).x == limits::max());
    const vec3<T> moved = quat::transform(far, vec3<T>{-limits::max(), T(1), T(-2)});
    CHECK(moved.x == std::ldexp(T(1), limits::max_exponent - limits::digits));
    CHECK(moved.y == T(1));
    CHECK(moved.z == T(-2));
    // Past max() for real: infinite, with the sign of the overflow.
    CHECK(quat::transform(far, vec3<T>{limits::max(), 0, 0}).x == limits::infinity());
    // Subnormal results: the halved sum keeps multiples of denorm_min, so the result is a multiple
    // of 2 denorm_min, within denorm_min of the exact one.
    const dual_quaternion<T> identity = dual_quaternion<T>::identity();
    for (int k = 1; k < 10; ++k) {
        const T tiny = limits::denorm_min() * T(k);
        const T moved_x = quat::transform(identity, vec3<T>{tiny, T(0), T(0)}).x;
        CHECK(std::fmod(moved_x, 2 * limits::denorm_min()) == 0);
        CHECK(std::fabs(moved_x - tiny) <= limits::denorm_min());
    }
}

TEMPLATE_TEST_CASE("a pure rotation and a pure translation are the long forms with zero parts",
                   "[dual_quaternion][first-use]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const vec3<T> zero{T(0), T(0), T(0)};
    for (int i = 0; i < 1000; ++i) {
        const quaternion<T> q = random.unit_quaternion<T>();
        const vec3<T> t = random.vector<T>(2.0), p = random.vector<T>(1.0);
        CHECK(same_bits(quat::to_dual_quaternion(q), quat::to_dual_quaternion(q, zero)));
        CHECK(same_bits(dual_quaternion<T>::from_translation(t),
                        quat::to_dual_quaternion(quaternion<T>::identity(), t)));
        // What they mean: x -> R x, and x -> x + t exactly (half of t, doubled back, is exact).
        CHECK(quat::to_dual_quaternion(q) * p == quat::rotate(q, p));
        CHECK(quat::translation_of(dual_quaternion<T>::from_translation(t)) == t);
        CHECK(dual_quaternion<T>::from_translation(t) * p == p + t);
        // Composed, rotation first: the motion to_dual_quaternion(q, t) builds.
        const dual_quaternion<T> composed =
            dual_quaternion<T>::from_translation(t) * quat::to_dual_quaternion(q);
        CHECK(max_difference(composed.real, q) == 0);
        CHECK(max_difference(composed.dual, quat::to_dual_quaternion(q, t).dual) <= 4 * eps<T>);
    }
    static_assert(quat::to_dual_quaternion(quat::quatd{0, 0, 0, 1}).dual ==
                  quat::quatd{0, 0, 0, 0});
}

TEST_CASE("a scalar times a dual quaternion scales all eight components, as GLM's",
          "[dual_quaternion][first-use]") {
    quat::test::random_rotations random;
    for (int i = 0; i < 500; ++i) {
        const dual_quaternion<double> dq = random.rigid_motion<double>();
        const double s = random.uniform<double>(-3, 3);
        const dual_quaternion<double> scaled = dq * s;
        CHECK(same_bits(scaled.real, dq.real * s));
        CHECK(same_bits(scaled.dual, dq.dual * s));
        CHECK(same_bits(s * dq, scaled));
        CHECK(same_bits(dq / s, dual_quaternion<double>{dq.real / s, dq.dual / s}));
        dual_quaternion<double> in_place = dq;
        in_place *= s;
        CHECK(same_bits(in_place, scaled));
        in_place = dq;
        in_place /= s;
        CHECK(same_bits(in_place, dq / s));
        const glm::tdualquat<double> theirs(quat::to_glm(dq.real), quat::to_glm(dq.dual));
        const glm::tdualquat<double> glm_scaled = theirs * s, glm_divided = theirs / s;
        CHECK(max_difference(quat::from_glm(glm_scaled.real), scaled.real) == 0);
        CHECK(max_difference(quat::from_glm(glm_scaled.dual), scaled.dual) == 0);
        CHECK(max_difference(quat::from_glm(glm_divided.dual), (dq / s).dual) == 0);
    }
    // The scalar converts to the dual quaternion's precision, as for quaternion.
    const quat::dual_quaternionf f = quat::dual_quaternionf::identity();
    static_assert(std::is_same_v<decltype(f * 2), quat::dual_quaternionf>);
    static_assert(std::is_same_v<decltype(0.5 * f), quat::dual_quaternionf>);
    CHECK((f * 2).real.w == 2.0f);
    CHECK((f / 4).real.w == 0.25f);
    constexpr auto doubled = 2.0 * quat::dual_quaterniond::identity();
    static_assert(doubled.real.w == 2 && doubled.dual.w == 0);
}

}  // namespace test_dual_quaternion

#undef GLM_ENABLE_EXPERIMENTAL
