// Edge cases: identity, half turns, gimbal lock in all 24 conventions, extreme
// magnitudes, q against -q, non-unit input, NaN/Inf, non-rotation matrices, constexpr = run time.
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <quat/quat.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_edge_cases {

namespace {

using quat::frame;
using quat::sequence;
using quat::test::tolerance;

constexpr double pi = 3.141592653589793;

constexpr sequence all_sequences[12] = {sequence::xyz, sequence::xzy, sequence::yxz, sequence::yzx,
                                        sequence::zxy, sequence::zyx, sequence::xyx, sequence::xzx,
                                        sequence::yxy, sequence::yzy, sequence::zxz, sequence::zyz};

template <class Fn, std::size_t... I>
void for_each_convention(Fn&& fn, std::index_sequence<I...>) {
    (fn(std::integral_constant<sequence, all_sequences[I / 2]>{}, std::integral_constant < frame,
        I % 2 == 0 ? frame::intrinsic : frame::extrinsic > {}),
     ...);
}
/// Calls fn(integral_constant<sequence>, integral_constant<frame>) for all 24 conventions.
template <class Fn>
void for_each_convention(Fn&& fn) {
    for_each_convention(std::forward<Fn>(fn), std::make_index_sequence<24>{});
}

constexpr bool is_proper(sequence s) {
    return static_cast<int>(s) >= static_cast<int>(sequence::xyx);
}

template <class T>
bool has_nan(const quat::quaternion<T>& q) {
    return std::isnan(q.w) || std::isnan(q.x) || std::isnan(q.y) || std::isnan(q.z);
}
template <class T>
bool all_finite(const quat::quaternion<T>& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

/// Half turns: (0, axis) for +-x, +-y, +-z and 20 random axes.
template <class T>
std::vector<quat::quaternion<T>> half_turns() {
    std::vector<quat::quaternion<T>> out;
    const T one(1), zero(0);
    for (T s : {one, -one}) {
        out.push_back({zero, s, zero, zero});
        out.push_back({zero, zero, s, zero});
        out.push_back({zero, zero, zero, s});
    }
    quat::test::random_rotations rng;
    for (int i = 0; i < 20; ++i) {
        const quat::vec3<T> a = rng.unit_vector<T>();
        out.push_back({zero, a.x, a.y, a.z});
    }
    return out;
}

}  // namespace

TEMPLATE_TEST_CASE("the identity is exact in every conversion", "[edge]", float, double) {
    using T = TestType;
    const auto id = quat::quaternion<T>::identity();
    CHECK(quat::to_matrix(id) == quat::rotation_matrix<T>::identity());
    CHECK(quat::to_quaternion(quat::rotation_matrix<T>::identity()) == id);
    CHECK(quat::from_rotation_vector(quat::vec3<T>{0, 0, 0}) == id);
    const quat::vec3<T> log_id = quat::to_rotation_vector(id);
    CHECK((log_id.x == 0 && log_id.y == 0 && log_id.z == 0));
    CHECK(quat::to_axis_angle(id).angle == 0);
    CHECK(quat::slerp(id, id, T(0.3)) == id);
    CHECK(quat::angle_between(id, -id) == 0);
    for_each_convention([&](auto s, auto f) {
        const auto e = quat::to_euler<decltype(s)::value, decltype(f)::value>(id);
        INFO("convention " << int(decltype(s)::value) << " frame " << int(decltype(f)::value));
        // The rotation is reproduced exactly; proper sequences are at their lock (middle angle 0).
        CHECK(quat::angle_between(quat::to_quaternion(e), id) == 0);
        CHECK(e[1] == 0);
    });
}

TEMPLATE_TEST_CASE("half turns about coordinate and random axes survive every conversion", "[edge]",
                   float, double) {
    using T = TestType;
    for (const auto& q : half_turns<T>()) {
        INFO("q = " << q.w << ", " << q.x << ", " << q.y << ", " << q.z);
        // Shepperd's largest-diagonal branch keeps the 180° matrix -> quaternion exact up to sign.
        const auto back = quat::to_quaternion(quat::to_matrix(q));
        CHECK(quat::angle_between(back, q) <= tolerance<T>::round_trip);
        CHECK(back.w >= 0);
        CHECK(std::abs(quat::to_axis_angle(q).angle - T(pi)) <= tolerance<T>::conversion);
        CHECK(std::abs(quat::norm(quat::to_rotation_vector(q)) - T(pi)) <=
              tolerance<T>::conversion);
        CHECK(quat::angle_between(quat::from_rotation_vector(quat::to_rotation_vector(q)), q) <=
              tolerance<T>::round_trip);
        CHECK(std::abs(quat::angle_between(quat::quaternion<T>::identity(), q) - T(pi)) <=
              tolerance<T>::conversion);
        for_each_convention([&](auto s, auto f) {
            const auto e = quat::to_euler<decltype(s)::value, decltype(f)::value>(q);
            INFO("convention " << int(decltype(s)::value) << " frame " << int(decltype(f)::value));
            CHECK(quat::angle_between(quat::to_quaternion(e), q) <= tolerance<T>::euler_round_trip);
        });
    }
}

TEMPLATE_TEST_CASE("middle Euler angle at and near gimbal lock, all 24 conventions",
                   "[edge][euler]", float, double) {
    using T = TestType;
    quat::test::random_rotations rng;
    for_each_convention([&](auto s, auto f) {
        constexpr sequence S = decltype(s)::value;
        constexpr frame F = decltype(f)::value;
        const std::vector<double> locks =
            is_proper(S) ? std::vector<double>{0.0, pi} : std::vector<double>{-pi / 2, pi / 2};
        for (double lock : locks)
            for (int k = 0; k <= 15; ++k)
                for (double sign : {-1.0, 1.0}) {
                    const double middle = k == 0 ? lock : lock + sign * std::pow(10.0, -k);
                    const quat::euler<T, S, F> e{rng.uniform<T>(-pi, pi), T(middle),
                                                 rng.uniform<T>(-pi, pi)};
                    const auto q = quat::to_quaternion(e);
                    const auto extraction = quat::extract_euler<S, F>(q);
                    const auto& back = extraction.angles;
                    INFO("convention " << int(S) << " frame " << int(F) << " middle " << middle
                                       << " k " << k);
                    // The returned angles reproduce the rotation, whatever split they chose.
                    CHECK(quat::angle_between(quat::to_quaternion(back), q) <=
                          tolerance<T>::euler_round_trip);
                    // Canonical ranges hold even for inputs just outside them.
                    CHECK(std::abs(back[0]) <= T(pi));
                    CHECK(std::abs(back[2]) <= T(pi));
                    if (is_proper(S)) {
                        CHECK((back[1] >= 0 && back[1] <= T(pi)));
                    } else {
                        CHECK(std::abs(back[1]) <= T(pi / 2));
                    }
                    // Far from the lock (10^-k well above epsilon) no lock is reported; at a lock
                    // the third angle is the one fixed by convention.
                    if (k > 0 &&
                        std::pow(10.0, -k) > 1e3 * double(std::numeric_limits<T>::epsilon()))
                        CHECK_FALSE(extraction.gimbal_lock);
                    if (extraction.gimbal_lock) CHECK(back[2] == 0);
                }
    });
}

TEMPLATE_TEST_CASE("huge, tiny and subnormal components normalize to the same unit quaternion",
                   "[edge]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    quat::test::random_rotations rng;
    for (int i = 0; i < 200; ++i) {
        const auto q = rng.unit_quaternion<T>();
        const auto unit = quat::normalize(q);
        for (T scale : {limits::max() / 4, T(1e30), T(1e-30), limits::min(),
                        limits::denorm_min() * T(1 << 20)}) {
            const quat::quaternion<T> scaled = q * scale;
            INFO("scale " << scale << " (" << (sizeof(T) == 4 ? "float" : "double") << ")");
            const auto n = quat::normalize(scaled);
            REQUIRE(all_finite(n));
            // Subnormal components carry fewer significant bits, so compare the rotation loosely
            // there.
            const T tol = scale < limits::min() ? T(1e-5) : tolerance<T>::unit_norm;
            CHECK(quat::test::max_difference(n, unit) <= tol);
            CHECK(std::abs(quat::norm(n) - 1) <= tolerance<T>::unit_norm);
            CHECK(quat::try_normalize(scaled).has_value());
            CHECK(std::isfinite(quat::norm(scaled)));
        }
    }
    // The smallest subnormal alone is still a direction.
    const quat::quaternion<T> smallest{limits::denorm_min(), 0, 0, 0};
    CHECK(quat::normalize(smallest) == quat::quaternion<T>::identity());
}

TEMPLATE_TEST_CASE(
    "to_euler and to_rotation_vector are scale-invariant for huge, tiny and subnormal q", "[edge]",
    float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    quat::test::random_rotations rng;
    for (int i = 0; i < 50; ++i) {
        const auto q = rng.unit_quaternion<T>();
        for (T scale : {limits::max() / 4, T(1e30), T(1e-30), limits::min(),
                        limits::denorm_min() * T(1 << 20)}) {
            const quat::quaternion<T> scaled = q * scale;
            INFO("scale " << scale << " (" << (sizeof(T) == 4 ? "float" : "double") << ")");
            // Documented: "any non-zero scale of q gives the same result/angles".
            const T tol = scale < limits::min() ? T(1e-5) : tolerance<T>::euler_round_trip;
            CHECK(quat::angle_between(quat::from_rotation_vector(quat::to_rotation_vector(scaled)),
                                      q) <= tol);
            CHECK(quat::angle_between(quat::to_quaternion(quat::to_euler<sequence::zyx>(scaled)),
                                      q) <= tol);
        }
    }
}

TEMPLATE_TEST_CASE("q and -q are one rotation everywhere", "[edge]", float, double) {
    using T = TestType;
    quat::test::random_rotations rng;
    for (int i = 0; i < 500; ++i) {
        const auto q = rng.unit_quaternion<T>();
        const auto b = rng.unit_quaternion<T>();
        const auto v = rng.vector<T>();
        CHECK(quat::to_matrix(q) == quat::to_matrix(-q));  // products of two negations are exact
        CHECK(quat::test::max_difference(quat::rotate(q, v), quat::rotate(-q, v)) == 0);
        CHECK(quat::test::max_difference(quat::to_rotation_vector(q),
                                         quat::to_rotation_vector(-q)) <= tolerance<T>::conversion);
        const auto e1 = quat::to_euler<sequence::zyx>(q), e2 = quat::to_euler<sequence::zyx>(-q);
        CHECK(std::abs(e1[0] - e2[0]) + std::abs(e1[1] - e2[1]) + std::abs(e1[2] - e2[2]) <=
              tolerance<T>::conversion);
        CHECK(quat::angle_between(q, -q) <= tolerance<T>::conversion);
        const T t = rng.uniform<T>(0, 1);
        CHECK(quat::angle_between(quat::slerp(q, b, t), quat::slerp(q, -b, t)) <=
              tolerance<T>::slerp_angle);
    }
}

// The conversions that read only directions (to_euler, to_axis_angle, to_rotation_vector,
// angle_between) are scale-invariant, so non-unit input is harmless there. to_matrix, rotate and
// slerp require |q| = 1: debug builds check it (tests/assert/, the QUAT_ASSERT death tests).
TEMPLATE_TEST_CASE("non-unit input: the direction-only conversions are scale-invariant", "[edge]",
                   float, double) {
    using T = TestType;
    quat::test::random_rotations rng;
    for (int i = 0; i < 200; ++i) {
        const auto q = rng.unit_quaternion<T>();
        const quat::quaternion<T> big = q * 3;
        CHECK(quat::angle_between(quat::from_rotation_vector(quat::to_rotation_vector(big)), q) <=
              tolerance<T>::round_trip);
        CHECK(std::abs(quat::to_axis_angle(big).angle - quat::to_axis_angle(q).angle) <=
              tolerance<T>::conversion);
        CHECK(quat::angle_between(quat::to_quaternion(quat::to_euler<sequence::xzx>(big)), q) <=
              tolerance<T>::euler_round_trip);
    }
}

TEMPLATE_TEST_CASE("NaN and Inf in give NaN out or an empty optional", "[edge]", float, double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const T inf = std::numeric_limits<T>::infinity();
    for (T bad : {nan, inf, -inf}) {
        INFO("bad component " << bad);
        const quat::quaternion<T> q{T(0.5), bad, T(0.5), T(0.5)};
        CHECK_FALSE(quat::try_normalize(q).has_value());
        CHECK_FALSE(quat::try_inverse(q).has_value());
        CHECK_FALSE(quat::try_normalize(quat::vec3<T>{bad, 0, 0}).has_value());
        CHECK_FALSE(quat::try_to_quaternion(quat::axis_angle<T>{{bad, 0, 1}, T(1)}).has_value());
        CHECK_FALSE(quat::try_to_quaternion(quat::axis_angle<T>{{0, 0, 1}, bad}).has_value());
        auto m = quat::rotation_matrix<T>::identity();
        m(1, 2) = bad;
        CHECK_FALSE(quat::try_to_quaternion(m).has_value());
        CHECK_FALSE(quat::try_nearest_rotation(m).has_value());
        const auto n = quat::nearest_rotation(m);  // terminates; documented NaN elements
        CHECK(std::isnan(n(0, 0) + n(1, 1) + n(2, 2) + n(0, 1) + n(1, 2) + n(2, 0)));
        if (std::isnan(bad)) {
            CHECK(has_nan(quat::normalize(q)));
            CHECK(has_nan(quat::to_quaternion(m)));
            const auto e = quat::to_euler<sequence::zyx>(q);
            CHECK(std::isnan(e[0] + e[1] + e[2]));
            CHECK(has_nan(quat::slerp(q, quat::quaternion<T>::identity(), T(0.5))));
            CHECK(has_nan(quat::from_rotation_vector(quat::vec3<T>{bad, 0, 0})));
        }
    }
    CHECK_FALSE(quat::try_normalize(quat::quaternion<T>{0, 0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_inverse(quat::quaternion<T>{0, 0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_to_quaternion(quat::axis_angle<T>{{0, 0, 0}, T(1)}).has_value());
}

TEMPLATE_TEST_CASE("non-orthogonal and reflected matrices", "[edge][nearest_rotation]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations rng;
    const auto reflect_z = quat::rotation_matrix<T>::from_rows({1, 0, 0}, {0, 1, 0}, {0, 0, -1});
    for (int i = 0; i < 200; ++i) {
        const auto r = quat::to_matrix(rng.unit_quaternion<T>());
        // A reflection is never a rotation, however orthogonal.
        CHECK_FALSE(quat::try_to_quaternion(r * reflect_z).has_value());
        // Far from orthogonal: rejected by try_to_quaternion, repaired by nearest_rotation.
        auto skewed = r;
        skewed(0, 1) += T(1e-2);
        skewed(2, 0) -= T(2e-2);
        CHECK_FALSE(quat::try_to_quaternion(skewed).has_value());
        const auto repaired = quat::nearest_rotation(skewed);
        CHECK(quat::orthogonality_error(repaired) <= tolerance<T>::conversion);
        CHECK(std::abs(quat::determinant(repaired) - 1) <= tolerance<T>::conversion);
        CHECK(quat::try_to_quaternion(repaired).has_value());
        // A scaled rotation's nearest rotation is the rotation itself.
        CHECK(quat::test::max_difference(
                  quat::nearest_rotation(
                      r * quat::rotation_matrix<T>{{{2, 0, 0}, {0, 2, 0}, {0, 0, 2}}}),
                  r) <= tolerance<T>::conversion);
        // Reflected input still yields a proper rotation (documented: the nearest proper one).
        const auto from_reflection = quat::nearest_rotation(r * reflect_z);
        CHECK(std::abs(quat::determinant(from_reflection) - 1) <= tolerance<T>::conversion);
        CHECK(quat::orthogonality_error(from_reflection) <= tolerance<T>::conversion);
    }
    // -I has a whole circle of nearest rotations: reported as not unique; zero has no direction.
    const auto minus_identity =
        quat::rotation_matrix<T>::from_rows({-1, 0, 0}, {0, -1, 0}, {0, 0, -1});
    CHECK_FALSE(quat::try_nearest_rotation(minus_identity).has_value());
    CHECK_FALSE(quat::try_to_quaternion(minus_identity).has_value());
    const auto zero = quat::rotation_matrix<T>::from_rows({0, 0, 0}, {0, 0, 0}, {0, 0, 0});
    CHECK_FALSE(quat::try_nearest_rotation(zero).has_value());
    CHECK(quat::orthogonality_error(quat::nearest_rotation(zero)) <= tolerance<T>::conversion);
}

namespace {

// Inputs for the constexpr = run-time table: generic rotation, near identity, near a half turn,
// a non-unit quaternion, and one near gimbal lock of zyx (pitch just below pi/2).
template <class T>
constexpr std::array<quat::quaternion<T>, 5> constexpr_inputs{{
    {T(0.5), T(-0.5), T(0.5), T(0.5)},
    {T(1), T(1e-5), T(-2e-6), T(3e-7)},
    {T(1e-4), T(0.6), T(-0.8), T(0)},
    {T(3), T(-4), T(12), T(0.5)},
    {T(0.7071067811865476), T(0.0001), T(0.7071067811865475), T(-0.0002)},
}};

/// Six derived numbers per input: normalize, exp(log), Euler zyx, Euler zxz, slerp to the next
/// input.
template <class T>
constexpr std::array<T, 5 * 16> constexpr_table(const std::array<quat::quaternion<T>, 5>& in) {
    std::array<T, 5 * 16> out{};
    for (std::size_t i = 0; i < in.size(); ++i) {
        const quat::quaternion<T> n = quat::normalize(in[i]);
        const quat::vec3<T> log = quat::to_rotation_vector(n);
        const quat::quaternion<T> exp = quat::from_rotation_vector(log);
        const auto zyx = quat::to_euler<sequence::zyx>(n);
        const auto zxz = quat::to_euler<sequence::zxz, frame::extrinsic>(n);
        const quat::quaternion<T> s =
            quat::slerp(n, quat::normalize(in[(i + 1) % in.size()]), T(0.3));
        const T values[16] = {n.w,    n.x,    n.y,    n.z,    log.x,  log.y,  log.z, exp.w,
                              zyx[0], zyx[1], zyx[2], zxz[0], zxz[1], zxz[2], s.w,   s.x};
        for (std::size_t j = 0; j < 16; ++j) out[i * 16 + j] = values[j];
    }
    return out;
}

template <class T>
constexpr auto constexpr_results = constexpr_table(constexpr_inputs<T>);
// Evaluated by the compiler: a normalized quaternion's w and a zyx pitch within range.
static_assert(constexpr_results<double>[0] > 0.4 && constexpr_results<double>[0] < 0.6);
static_assert(constexpr_results<double>[4 * 16 + 9] > 1.5 &&
              constexpr_results<double>[4 * 16 + 9] < 1.5708);
static_assert(constexpr_results<float>[3] > 0.4f && constexpr_results<float>[3] < 0.6f);

}  // namespace

TEMPLATE_TEST_CASE("constexpr results equal run-time results within constexpr_vs_runtime",
                   "[edge][constexpr]", float, double) {
    using T = TestType;
    // Launder the inputs through volatile so the run-time call really uses <cmath>.
    std::array<quat::quaternion<T>, 5> runtime_inputs{};
    for (std::size_t i = 0; i < runtime_inputs.size(); ++i) {
        volatile T w = constexpr_inputs<T>[i].w, x = constexpr_inputs<T>[i].x,
                   y = constexpr_inputs<T>[i].y, z = constexpr_inputs<T>[i].z;
        runtime_inputs[i] = {w, x, y, z};
    }
    const auto runtime = constexpr_table(runtime_inputs);
    for (std::size_t k = 0; k < runtime.size(); ++k) {
        INFO("input " << k / 16 << " value " << k % 16 << ": constexpr " << constexpr_results<T>[k]
                      << " run time " << runtime[k]);
        const T scale = std::max(T(1), std::abs(runtime[k]));
        CHECK(std::abs(constexpr_results<T>[k] - runtime[k]) <=
              tolerance<T>::constexpr_vs_runtime * scale);
    }
}

// ---- Every function documented for "any non-zero length/scale" keeps its answer from
// the smallest subnormal to the largest finite scale (norms formed from user input are scaled by
// the largest component first, as hypot does).

namespace {

/// Scales spanning the whole finite range of T: the normal extremes, 1e-300/1e300 (double) or
/// 1e-38/1e38 (float, where 1e-38 is subnormal), subnormals and max().
template <class T>
std::vector<T> extreme_scales() {
    using limits = std::numeric_limits<T>;
    const T big = sizeof(T) == 4 ? T(1e38) : T(1e300),
            small = sizeof(T) == 4 ? T(1e-38) : T(1e-300);
    return {limits::max(),
            limits::max() / 3,
            big,
            T(1) / limits::epsilon(),
            small,
            limits::min(),
            limits::min() / 1024,
            limits::denorm_min() * T(1 << 20)};
}

/// The error a scaled input may carry: a few eps, plus the relative spacing of subnormals at scale.
template <class T>
T scaled_tolerance(T scale) {
    return 16 * std::numeric_limits<T>::epsilon() +
           4 * std::numeric_limits<T>::denorm_min() / scale;
}

template <class T>
bool unit_within(const quat::vec3<T>& v, T tolerance) {
    return std::abs(quat::norm(v) - 1) <= tolerance;
}

}  // namespace

TEMPLATE_TEST_CASE("normalize and try_normalize of a vec3 accept any finite non-zero length",
                   "[edge][magnitude]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    const T half = std::sqrt(T(0.5)), eps = limits::epsilon();
    // Both lengths of the issue: |v|^2 overflows, and |v| itself overflows or underflows.
    for (T component : {T(0.9) * limits::max(), limits::max(), limits::denorm_min(),
                        limits::denorm_min() * 3, limits::min()}) {
        INFO("component " << component);
        const quat::vec3<T> v{component, component, 0};
        const quat::vec3<T> n = quat::normalize(v);
        CHECK(std::abs(n.x - half) <= 2 * eps);
        CHECK(std::abs(n.y - half) <= 2 * eps);
        CHECK(n.z == 0);
        const auto checked = quat::try_normalize(v);
        REQUIRE(checked.has_value());
        CHECK(*checked == n);
    }
    quat::test::random_rotations rng;
    for (int i = 0; i < 100; ++i) {
        const quat::vec3<T> u = rng.unit_vector<T>();
        for (T scale : extreme_scales<T>()) {
            INFO("scale " << scale);
            const quat::vec3<T> n = quat::normalize(u * scale);
            CHECK(unit_within(n, 4 * eps));  // unit even where the input has few digits
            CHECK(quat::test::max_difference(n, u) <= scaled_tolerance(scale));
            CHECK(quat::try_normalize(u * scale).has_value());
        }
    }
    CHECK_FALSE(quat::try_normalize(quat::vec3<T>{0, 0, 0}).has_value());
    CHECK(std::isnan(quat::normalize(quat::vec3<T>{0, 0, 0}).x));
    CHECK(std::isnan(quat::normalize(quat::vec3<T>{limits::infinity(), 1, 0}).y));
}

TEMPLATE_TEST_CASE("the direction-only conversions of q keep their answer at any scale of q",
                   "[edge][magnitude]", float, double) {
    using T = TestType;
    quat::test::random_rotations rng;
    for (int i = 0; i < 100; ++i) {
        const quat::quaternion<T> q = rng.unit_quaternion<T>();
        const quat::axis_angle<T> reference = quat::to_axis_angle(q);
        const quat::vec3<T> rotation_vector = quat::to_rotation_vector(q);
        const quat::vec3<T> mrp = quat::to_mrp(q);
        for (T scale : extreme_scales<T>()) {
            INFO("scale " << scale);
            const quat::quaternion<T> scaled = q * scale;
            const T tol = scaled_tolerance(scale);
            const quat::axis_angle<T> a = quat::to_axis_angle(scaled);
            CHECK(unit_within(a.axis, 4 * std::numeric_limits<T>::epsilon()));
            CHECK(quat::test::max_difference(a.axis, reference.axis) <= 4 * tol);
            CHECK(std::abs(a.angle - reference.angle) <= 4 * tol);
            CHECK(quat::test::max_difference(quat::to_rotation_vector(scaled), rotation_vector) <=
                  8 * tol);
            CHECK(quat::test::max_difference(quat::to_mrp(scaled), mrp) <= 4 * tol);
        }
    }
}

TEMPLATE_TEST_CASE("try_to_quaternion(axis_angle) normalizes any finite non-zero axis",
                   "[edge][magnitude]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    quat::test::random_rotations rng;
    for (int i = 0; i < 100; ++i) {
        const quat::vec3<T> axis = rng.unit_vector<T>();
        const T angle = rng.uniform<T>(-6, 6);
        const quat::quaternion<T> reference = quat::to_quaternion(quat::axis_angle<T>{axis, angle});
        for (T scale : extreme_scales<T>()) {
            INFO("scale " << scale);
            const auto q = quat::try_to_quaternion(quat::axis_angle<T>{axis * scale, angle});
            REQUIRE(q.has_value());
            CHECK(quat::test::max_difference(*q, reference) <= 2 * scaled_tolerance(scale));
        }
    }
    // The subnormal axis: engaged, unit, and no debug check fires on the way.
    const auto q = quat::try_to_quaternion(
        quat::axis_angle<T>{{limits::denorm_min(), limits::denorm_min(), 0}, T(1)});
    REQUIRE(q.has_value());
    CHECK(std::abs(quat::norm(*q) - 1) <= 4 * limits::epsilon());
}

TEMPLATE_TEST_CASE("rotation_between and swing_twist take directions of any finite length",
                   "[edge][magnitude][align]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    const T eps = limits::epsilon();
    quat::test::random_rotations rng;
    for (int i = 0; i < 100; ++i) {
        const quat::vec3<T> from = rng.unit_vector<T>(), to = rng.unit_vector<T>();
        const quat::quaternion<T> reference = quat::rotation_between(from, to);
        const quat::quaternion<T> q = rng.unit_quaternion<T>();
        const quat::swing_twist_parts<T> parts = quat::swing_twist(q, from);
        for (T scale : extreme_scales<T>()) {
            INFO("scale " << scale);
            const T tol = 4 * scaled_tolerance(scale);
            const quat::quaternion<T> r = quat::rotation_between(from * scale, to);
            CHECK(quat::angle_between(r, reference) <= tol);
            CHECK(std::abs(quat::norm(r) - 1) <= 4 * eps);
            const auto checked = quat::try_rotation_between(from, to * scale);
            REQUIRE(checked.has_value());
            CHECK(quat::angle_between(*checked, reference) <= tol);
            CHECK(std::abs(quat::norm(*checked) - 1) <= 4 * eps);
            const quat::swing_twist_parts<T> scaled_parts = quat::swing_twist(q, from * scale);
            CHECK(quat::angle_between(scaled_parts.twist, parts.twist) <= tol);
            CHECK(quat::angle_between(scaled_parts.swing, parts.swing) <= tol);
        }
    }
    // Float's largest lengths (the products are formed in double).
    const auto huge = quat::try_rotation_between(quat::vec3<T>{T(3e38), T(3e38), 0},
                                                 quat::vec3<T>{0, T(3e38), T(3e38)});
    REQUIRE(huge.has_value());
    CHECK(quat::angle_between(*huge, quat::rotation_between(quat::vec3<T>{1, 1, 0},
                                                            quat::vec3<T>{0, 1, 1})) <= 8 * eps);
    // Nearly opposite with a subnormal cross product: still a unit quaternion.
    const T tiny = limits::denorm_min() * 16;
    const quat::quaternion<T> opposite =
        quat::rotation_between(quat::vec3<T>{1, 0, 0}, quat::vec3<T>{-1, tiny, tiny});
    CHECK(std::abs(quat::squared_norm(opposite) - 1) <= 4 * eps);
}

TEMPLATE_TEST_CASE("inverse of a quaternion is accurate wherever it is representable",
                   "[edge][magnitude]", float, double) {
    using T = TestType;
    using limits = std::numeric_limits<T>;
    quat::test::random_rotations rng;
    const T big = sizeof(T) == 4 ? T(1e37) : T(1e300);
    for (int i = 0; i < 100; ++i) {
        const quat::quaternion<T> q = rng.unit_quaternion<T>();
        for (T scale : {big, T(1) / big, limits::min(), T(1) / limits::min()}) {
            INFO("scale " << scale);
            // (s q)^-1 = q* / s
            const quat::quaternion<T> expected = quat::conjugate(q) / scale;
            const T tol = 8 * limits::epsilon() / scale;
            CHECK(quat::test::max_difference(quat::inverse(q * scale), expected) <= tol);
            const auto checked = quat::try_inverse(q * scale);
            REQUIRE(checked.has_value());
            CHECK(quat::test::max_difference(*checked, expected) <= tol);
        }
    }
    CHECK(quat::inverse(quat::quaternion<T>{T(sizeof(T) == 4 ? 1e38 : 1e300), 0, 0, 0}).w > 0);
    // No representable inverse, or no inverse at all: NaN or an empty optional.
    CHECK_FALSE(quat::try_inverse(quat::quaternion<T>{limits::denorm_min(), 0, 0, 0}).has_value());
    CHECK_FALSE(quat::try_inverse(quat::quaternion<T>{0, 0, 0, 0}).has_value());
    CHECK(std::isnan(quat::inverse(quat::quaternion<T>{0, 0, 0, 0}).w));
    CHECK(std::isnan(quat::inverse(quat::quaternion<T>{limits::infinity(), 0, 0, 0}).w));
}

TEMPLATE_TEST_CASE("is_unit is false for infinite components whatever the tolerance", "[edge]",
                   float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity();
    for (int i = 0; i < 4; ++i) {
        quat::quaternion<T> q{0, 0, 0, 0};
        (i == 0 ? q.w : i == 1 ? q.x : i == 2 ? q.y : q.z) = inf;
        CHECK_FALSE(quat::is_unit(q, inf));
        CHECK_FALSE(quat::is_unit(-q, inf));
    }
    CHECK(quat::is_unit(quat::quaternion<T>{2, 0, 0, 0}, inf));
}

TEMPLATE_TEST_CASE("an infinite w gives NaN, not a clean rotation, from the angle readers",
                   "[edge]", float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity();
    for (T w : {inf, -inf}) {
        const quat::quaternion<T> q{w, T(0.1), 0, 0};
        INFO("w " << w);
        CHECK(std::isnan(quat::to_axis_angle(q).angle));
        CHECK(std::isnan(quat::to_rotation_vector(q).x));
        CHECK(std::isnan(quat::to_mrp(q).x));
        CHECK_FALSE(all_finite(quat::pow(q, T(0.5))));
    }
}

}  // namespace test_edge_cases
