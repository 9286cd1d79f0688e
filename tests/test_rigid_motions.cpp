// Specification of batch/rigid_motions.hpp: moving many points by one rigid motion (both layouts,
// in place, containers, the streaming path) and composing many dual quaternions.
#include <cmath>
#include <cstddef>
#include <vector>

#include <quat/batch/rigid_motions.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/rigid_reference.hpp"
#include "support/tolerance.hpp"

namespace test_rigid_motions {

using quat::dual_quaternion;
using quat::soa_points;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

namespace {

template <class T>
std::vector<vec3<T>> random_points(quat::test::random_rotations& random, std::size_t n) {
    std::vector<vec3<T>> p(n);
    for (auto& v : p) v = random.vector<T>(10.0);
    return p;
}

}  // namespace

TEMPLATE_TEST_CASE("batch transform equals the scalar transform, both layouts, every size",
                   "[rigid_batch]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (const std::size_t n : {0u, 1u, 3u, 7u, 255u, 256u, 257u, 1025u}) {
        const dual_quaternion<T> dq = random.rigid_motion<T>();
        const quat::homogeneous_matrix<T> m = quat::to_homogeneous(dq);
        const std::vector<vec3<T>> in = random_points<T>(random, n);
        std::vector<vec3<T>> by_dq(n), by_m(n);
        quat::transform(dq, in, by_dq);
        quat::transform(m, in.data(), by_m.data(), n);
        std::vector<T> x(n), y(n), z(n), ox(n), oy(n), oz(n);
        for (std::size_t i = 0; i < n; ++i) x[i] = in[i].x, y[i] = in[i].y, z[i] = in[i].z;
        quat::transform(dq, soa_points<const T>{x.data(), y.data(), z.data(), n},
                        soa_points<T>{ox.data(), oy.data(), oz.data(), n});
        for (std::size_t i = 0; i < n; ++i) {
            // Points reach ~40 and translations ~8: the tolerance scales with them.
            const vec3<T> expected = quat::transform(dq, in[i]);
            CHECK(max_difference(by_dq[i], expected) <= 64 * quat::test::tolerance<T>::rotate);
            CHECK(max_difference(by_m[i], expected) <= 64 * quat::test::tolerance<T>::rotate);
            CHECK(max_difference(vec3<T>{ox[i], oy[i], oz[i]}, by_m[i]) <=
                  4 * quat::test::tolerance<T>::rotate);
        }
        // In place, both layouts: output == input.
        std::vector<vec3<T>> same = in;
        quat::transform(m, same, same);
        CHECK(same == by_m);
        quat::transform(m, soa_points<const T>{x.data(), y.data(), z.data(), n},
                        soa_points<T>{x.data(), y.data(), z.data(), n});
        for (std::size_t i = 0; i < n; ++i)
            CHECK(vec3<T>{x[i], y[i], z[i]} == vec3<T>{ox[i], oy[i], oz[i]});
    }
}

TEST_CASE(
    "batch transform beyond the streaming threshold (streaming stores) equals the scalar transform",
    "[rigid_batch]") {
    const auto dq = quat::to_dual_quaternion(quat::normalize(quat::quatf{0.3f, -0.5f, 0.7f, 0.2f}),
                                             vec3<float>{1, -2, 3});
    const std::size_t n = quat::detail::streaming_threshold_bytes() / (3 * sizeof(float)) + 77;
    std::vector<vec3<float>> in(n), out(n);
    std::vector<float> x(n), y(n), z(n), ox(n), oy(n), oz(n);
    for (std::size_t i = 0; i < n; ++i) {
        in[i] = {float(i % 31), -float(i % 17), 0.5f};
        x[i] = in[i].x, y[i] = in[i].y, z[i] = in[i].z;
    }
    quat::transform(dq, in, out);
    quat::transform(dq, soa_points<const float>{x.data(), y.data(), z.data(), n},
                    soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const vec3<float> expected = quat::transform(dq, in[i]);
        if (!(max_difference(out[i], expected) <= 1e-4f)) ++mismatches;
        if (!(max_difference(vec3<float>{ox[i], oy[i], oz[i]}, expected) <= 1e-4f)) ++mismatches;
    }
    CHECK(mismatches == 0);
}

TEMPLATE_TEST_CASE("compose(span) of rigid motions is their product", "[rigid_batch]", float,
                   double) {
    using T = TestType;
    quat::test::random_rotations random;
    CHECK(quat::compose(std::vector<dual_quaternion<T>>{}) == dual_quaternion<T>::identity());
    for (const std::size_t n : {1u, 5u, 16u, 17u, 100u, 1024u}) {
        std::vector<dual_quaternion<T>> chain(n);
        quat::test::matrix4 reference = quat::test::identity4();
        // Small steps, so the product's translation stays near the steps' size.
        for (auto& step : chain) {
            const quat::quaternion<T> q = random.unit_quaternion<T>();
            const vec3<T> t = random.vector<T>(0.05);
            step = quat::to_dual_quaternion(q, t);
            reference = reference * quat::test::reference_matrix(step);
        }
        const dual_quaternion<T> product = quat::compose(chain);
        const dual_quaternion<T> by_pointer = quat::compose(chain.data(), n);
        CHECK(product == by_pointer);
        // Rounding grows like sqrt(n) per component in each of the two orders.
        const long double error =
            quat::test::max_difference(quat::test::reference_matrix(product), reference) /
            std::max(1.0L, quat::test::max_abs(reference));
        CHECK(error <= 8 * eps<T> * std::sqrt(T(n)) * 4);
    }
}

TEMPLATE_TEST_CASE("struct-of-arrays transform in place: soa_points<T> is also the const input",
                   "[rigid_batch]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const dual_quaternion<T> dq = random.rigid_motion<T>(10.0);
    const std::size_t n = 29;
    std::vector<T> x(n), y(n), z(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = T(i), y[i] = T(2) - T(i), z[i] = T(0.25) * T(i);
    std::vector<vec3<T>> expected(n);
    for (std::size_t i = 0; i < n; ++i)
        expected[i] = quat::transform(dq, vec3<T>{x[i], y[i], z[i]});
    const soa_points<T> points{x.data(), y.data(), z.data(), n};
    quat::transform(dq, points, points);  // soa_points<T> converts to soa_points<const T>
    for (std::size_t i = 0; i < n; ++i)
        CHECK(max_difference(vec3<T>{x[i], y[i], z[i]}, expected[i]) <= 256 * eps<T>);
    quat::transform(quat::to_homogeneous(quat::inverse(dq)), points, points);  // and back
    for (std::size_t i = 0; i < n; ++i) CHECK(std::abs(x[i] - T(i)) <= 1024 * eps<T>);
}

}  // namespace test_rigid_motions
