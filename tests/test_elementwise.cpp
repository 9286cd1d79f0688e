// Specification of batch/elementwise.hpp: rotate_each, compose_each, to_matrix_each and
// to_quaternion_each give the scalar results element by element, at every count (the tails of every
// vector width), in place, through containers and in both layouts; NaN stays in its element; a
// user-defined scalar gets the scalar functions' results.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include <quat/batch/elementwise.hpp>

#include "support/catch.hpp"
#include "support/random.hpp"
#include "support/tolerance.hpp"

namespace test_elementwise {

using quat::quaternion;
using quat::rotation_matrix;
using quat::soa_points;
using quat::soa_quaternions;
using quat::vec3;
using quat::test::eps;
using quat::test::max_difference;

namespace {

/// rotate_each against rotate(q, v), per component and relative to |v|: the factored formula of
/// the float and double loops rounds differently. Measured at most 4.2 eps (200000 random pairs,
/// float and double, g++ 12 and clang 14, -march=x86-64 to native, -O0 to -O3).
template <class T>
constexpr T rotate_each_vs_rotate = 6 * eps<T>;

/// The struct-of-arrays rotate_each against the array-of-structs one: the same formula in another
/// loop, where the compiler may fuse other multiply-adds; per component, relative to |v|.
/// Measured at most 2.2 eps (g++ with FMA); equal in SSE2 builds, which share the loop.
template <class T>
constexpr T soa_vs_aos = 4 * eps<T>;

/// Scalar results recomputed by the batch functions, in loops where the compiler may fuse other
/// multiply-adds than in the scalar call (g++ does by default where FMA exists; -ffp-contract):
/// per component of a unit quaternion or matrix entry. Measured at most 0.5 eps (g++ 12 and
/// clang 14, -O0 to -O3, x86-64 to native); in the other builds the results were equal.
template <class T>
constexpr T contraction = 2 * eps<T>;

/// Counts 0 ... 70 (every tail of 4-, 8- and 16-wide vectors and of 64-element blocks) and 1024.
std::vector<std::size_t> counts() {
    std::vector<std::size_t> n;
    for (std::size_t i = 0; i <= 70; ++i) n.push_back(i);
    n.push_back(1024);
    n.push_back(1237);  // float struct of arrays past detail::prefetch_bytes: outputs prefetched
    return n;
}

template <class T>
std::vector<quaternion<T>> random_rotations(quat::test::random_rotations& random, std::size_t n) {
    std::vector<quaternion<T>> q(n);
    for (auto& r : q) r = random.unit_quaternion<T>();
    return q;
}

template <class T>
std::vector<vec3<T>> random_points(quat::test::random_rotations& random, std::size_t n) {
    std::vector<vec3<T>> p(n);
    for (auto& v : p) v = random.vector<T>(10.0);
    return p;
}

template <class T>
T length(const vec3<T>& v) {
    return std::sqrt(quat::squared_norm(v));
}

/// A copy of quaternions as four component arrays, for the struct-of-arrays forms.
template <class T>
struct component_arrays {
    std::vector<T> w, x, y, z;

    explicit component_arrays(const std::vector<quaternion<T>>& q)
        : w(q.size()), x(q.size()), y(q.size()), z(q.size()) {
        for (std::size_t i = 0; i < q.size(); ++i)
            w[i] = q[i].w, x[i] = q[i].x, y[i] = q[i].y, z[i] = q[i].z;
    }
    soa_quaternions<const T> view() const {
        return {w.data(), x.data(), y.data(), z.data(), w.size()};
    }
};

/// How many i < n fail `holds(i)`: the out-of-cache tests check millions of elements, one CHECK
/// for all of them.
template <class Predicate>
std::size_t failures(std::size_t n, Predicate holds) {
    std::size_t failed = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!holds(i)) ++failed;
    return failed;
}

/// Largest component difference of a and b in units of eps |v| (|v| at least 1).
template <class T>
T relative_error(const vec3<T>& a, const vec3<T>& b, const vec3<T>& v) {
    return max_difference(a, b) / (std::max(T(1), length(v)) * eps<T>);
}

/// Whether v is rotate(q, p) within rotate_each's tolerance.
bool is_rotate(const vec3<float>& v, const quaternion<float>& q, const vec3<float>& p) {
    return relative_error(v, quat::rotate(q, p), p) <= rotate_each_vs_rotate<float> / eps<float>;
}

}  // namespace

TEMPLATE_TEST_CASE("rotate_each turns point i by rotation i, as rotate(q, v), at every count",
                   "[elementwise]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    T worst = 0;
    for (const std::size_t n : counts()) {
        const std::vector<quaternion<T>> q = random_rotations<T>(random, n);
        const std::vector<vec3<T>> p = random_points<T>(random, n);
        std::vector<vec3<T>> out(n);
        quat::rotate_each(q.data(), p.data(), out.data(), n);
        for (std::size_t i = 0; i < n; ++i) {
            const T error = relative_error(out[i], quat::rotate(q[i], p[i]), p[i]);
            worst = std::max(worst, error);
            CHECK(error <= rotate_each_vs_rotate<T> / eps<T>);
        }
        // In place: output == points gives the same values.
        std::vector<vec3<T>> same = p;
        quat::rotate_each(q.data(), same.data(), same.data(), n);
        CHECK(same == out);
    }
    INFO("largest difference from rotate(q, v): " << worst << " eps |v|");
    CHECK(worst <= rotate_each_vs_rotate<T> / eps<T>);
}

TEMPLATE_TEST_CASE("rotate_each of struct of arrays equals the array-of-structs form",
                   "[elementwise]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (const std::size_t n : counts()) {
        const std::vector<quaternion<T>> q = random_rotations<T>(random, n);
        const std::vector<vec3<T>> p = random_points<T>(random, n);
        std::vector<vec3<T>> aos(n);
        quat::rotate_each(q, p, aos);
        std::vector<T> w(n), x(n), y(n), z(n), px(n), py(n), pz(n), ox(n), oy(n), oz(n);
        for (std::size_t i = 0; i < n; ++i) {
            w[i] = q[i].w, x[i] = q[i].x, y[i] = q[i].y, z[i] = q[i].z;
            px[i] = p[i].x, py[i] = p[i].y, pz[i] = p[i].z;
        }
        const soa_quaternions<const T> rotations{w.data(), x.data(), y.data(), z.data(), n};
        quat::rotate_each(rotations, soa_points<const T>{px.data(), py.data(), pz.data(), n},
                          soa_points<T>{ox.data(), oy.data(), oz.data(), n});
        // The same formula in another loop: equal up to how the compiler fuses multiply-adds.
        for (std::size_t i = 0; i < n; ++i)
            CHECK(relative_error(vec3<T>{ox[i], oy[i], oz[i]}, aos[i], p[i]) <=
                  soa_vs_aos<T> / eps<T>);
        // In place, each output array its own input array.
        quat::rotate_each(rotations, soa_points<const T>{px.data(), py.data(), pz.data(), n},
                          soa_points<T>{px.data(), py.data(), pz.data(), n});
        for (std::size_t i = 0; i < n; ++i)
            CHECK(vec3<T>{px[i], py[i], pz[i]} == vec3<T>{ox[i], oy[i], oz[i]});
    }
}

TEST_CASE(
    "rotate_each beyond the streaming threshold (non-temporal stores on x86) gives rotate's "
    "results, in both layouts and in place",
    "[elementwise]") {
    quat::test::random_rotations random;
    const std::size_t n =
        quat::detail::streaming_threshold_bytes() / sizeof(vec3<float>) + 77;  // odd tail
    const std::vector<quaternion<float>> q = random_rotations<float>(random, n);
    const std::vector<vec3<float>> p = random_points<float>(random, n);
    std::vector<vec3<float>> out(n);
    quat::rotate_each(q, p, out);
    CHECK(failures(n, [&](std::size_t i) { return is_rotate(out[i], q[i], p[i]); }) == 0);
    // In place (the plain prefix may differ in length, as above): rotate's results again.
    std::vector<vec3<float>> same = p;
    quat::rotate_each(q, same, same);
    CHECK(failures(n, [&](std::size_t i) { return is_rotate(same[i], q[i], p[i]); }) == 0);

    const component_arrays<float> rotations(q);
    std::vector<float> px(n), py(n), pz(n), ox(n), oy(n), oz(n);
    for (std::size_t i = 0; i < n; ++i) px[i] = p[i].x, py[i] = p[i].y, pz[i] = p[i].z;
    quat::rotate_each(rotations.view(), soa_points<const float>{px.data(), py.data(), pz.data(), n},
                      soa_points<float>{ox.data(), oy.data(), oz.data(), n});
    CHECK(failures(n, [&](std::size_t i) {
              return relative_error(vec3<float>{ox[i], oy[i], oz[i]}, out[i], p[i]) <=
                     soa_vs_aos<float> / eps<float>;
          }) == 0);
    quat::rotate_each(rotations.view(), soa_points<const float>{px.data(), py.data(), pz.data(), n},
                      soa_points<float>{px.data(), py.data(), pz.data(), n});
    CHECK(failures(n, [&](std::size_t i) {
              return relative_error(vec3<float>{px[i], py[i], pz[i]}, out[i], p[i]) <=
                     soa_vs_aos<float> / eps<float>;
          }) == 0);
}

TEST_CASE("compose_each beyond the streaming threshold gives operator*'s products, also in place",
          "[elementwise]") {
    quat::test::random_rotations random;
    const std::size_t n =
        quat::detail::streaming_threshold_bytes() / sizeof(quaternion<float>) + 77;
    const std::vector<quaternion<float>> a = random_rotations<float>(random, n);
    const std::vector<quaternion<float>> b = random_rotations<float>(random, n);
    std::vector<quaternion<float>> out(n);
    quat::compose_each(a, b, out);
    CHECK(failures(n, [&](std::size_t i) {
              return max_difference(out[i], a[i] * b[i]) <= contraction<float>;
          }) == 0);
    // In place (its prefix before a cache line may differ, and with it which elements the plain
    // loop does): operator*'s products again.
    std::vector<quaternion<float>> same = a;
    quat::compose_each(same, b, same);
    CHECK(failures(n, [&](std::size_t i) {
              return max_difference(same[i], a[i] * b[i]) <= contraction<float>;
          }) == 0);
}

#if defined(__AVX__)
TEST_CASE("streamed compose_each: every offset of the output from a cache line, every short tail",
          "[elementwise]") {
    quat::test::random_rotations random;
    const std::vector<quaternion<float>> a = random_rotations<float>(random, 3000);
    const std::vector<quaternion<float>> b = random_rotations<float>(random, 3000);
    const quaternion<float> sentinel{9, 9, 9, 9};
    for (std::size_t offset = 0; offset < 4; ++offset) {
        for (const std::size_t count : {0u, 1u, 3u, 7u, 8u, 15u, 16u, 17u, 31u, 33u, 257u, 2999u}) {
            INFO("offset " << offset << ", " << count << " products");
            std::vector<quaternion<float>> buffer(3010, sentinel);
            quaternion<float>* out = buffer.data() + offset;
            quat::detail::compose_each_streaming(a.data(), b.data(), out, count);
            CHECK(failures(count, [&](std::size_t i) {
                      return max_difference(out[i], a[i] * b[i]) <= contraction<float>;
                  }) == 0);
            CHECK(out[count] == sentinel);  // nothing written past the end
        }
    }
}
#endif

#if defined(__AVX__)
TEST_CASE("streamed rotate_each: every offset of the outputs from a cache line, every short tail",
          "[elementwise]") {
    // The streaming paths (called directly here, whatever this machine's threshold) store plainly
    // up to a 64-byte boundary of the output, then stream; the struct-of-arrays one streams whole
    // vectors where all three output arrays are aligned to one, 16-byte pieces where they are
    // aligned to 16 bytes, and stores plainly otherwise (the test below sets which way it sweeps).
    quat::test::random_rotations random;
    const std::vector<quaternion<float>> q = random_rotations<float>(random, 3000);
    const std::vector<vec3<float>> p = random_points<float>(random, 3000);
    const component_arrays<float> rotations(q);
    std::vector<float> px(3000), py(3000), pz(3000);
    for (std::size_t i = 0; i < 3000; ++i) px[i] = p[i].x, py[i] = p[i].y, pz[i] = p[i].z;
    const float sentinel = 9;
    for (std::size_t offset = 0; offset < 16; ++offset) {
        for (const std::size_t count : {0u, 1u, 7u, 8u, 15u, 16u, 17u, 31u, 33u, 257u, 2999u}) {
            INFO("offset " << offset << ", " << count << " elements");
            std::vector<vec3<float>> buffer(3100, vec3<float>{sentinel, sentinel, sentinel});
            vec3<float>* out = buffer.data() + offset;
            quat::detail::rotate_each_streaming(q.data(), p.data(), out, count);
            CHECK(failures(count, [&](std::size_t i) { return is_rotate(out[i], q[i], p[i]); }) ==
                  0);
            CHECK(out[count].x == sentinel);  // nothing written past the end
            // y and z as far from a line as x, 4 floats further (16-byte pieces with AVX-512) or 1
            // (plain): the three output arrays carved from one buffer at 64-byte boundaries.
            for (const std::size_t skew : {0u, 4u, 1u}) {
                constexpr std::size_t stride = 3200;  // floats: 200 cache lines
                std::vector<float> buffer_soa(3 * stride + 16, sentinel);
                float* const base =
                    buffer_soa.data() + quat::detail::elements_before_line(buffer_soa.data(), 16);
                const soa_points<float> soa_out{base + 3 * offset,
                                                base + stride + 3 * offset + skew,
                                                base + 2 * stride + 3 * offset + skew, count};
                quat::detail::rotate_each_soa_streaming(
                    soa_quaternions<const float>{rotations.w.data(), rotations.x.data(),
                                                 rotations.y.data(), rotations.z.data(), count},
                    soa_points<const float>{px.data(), py.data(), pz.data(), count}, soa_out);
                CHECK(failures(count, [&](std::size_t i) {
                          return is_rotate(vec3<float>{soa_out.x[i], soa_out.y[i], soa_out.z[i]},
                                           q[i], p[i]);
                      }) == 0);
                CHECK((soa_out.x[count] == sentinel && soa_out.y[count] == sentinel &&
                       soa_out.z[count] == sentinel));
            }
        }
    }
}

// The ten arrays of a struct-of-arrays rotate_each (w, x, y, z, px, py, pz, then the outputs), each
// at a byte offset from a 4096-byte boundary, 16 KiB apart in one buffer; an output given as -1 - k
// is input array k (in place).
struct page_layout {
    const char* name;
    std::ptrdiff_t offsets[10];
    quat::detail::sweep way;
};

TEST_CASE("streamed struct-of-arrays rotate_each sweeps as its arrays' page offsets allow",
          "[elementwise]") {
    using quat::detail::sweep;
    // Each layout gives the same answer at both builds' reach: 256 bytes (AVX2), 512 (AVX-512).
    const page_layout layouts[] = {
        {"outputs 16 to 144 bytes past the inputs: downward",
         {0, 16, 32, 48, 64, 80, 96, 112, 128, 144},
         sweep::downward},
        {"outputs 16 to 144 bytes before the inputs: upward",
         {48, 64, 80, 96, 112, 128, 144, 0, 16, 32},
         sweep::upward},
        {"outputs line-aligned, 64 bytes past the inputs: downward, whole vectors",
         {0, 0, 0, 0, 0, 0, 0, 64, 64, 64},
         sweep::downward},
        {"outputs line-aligned, 1 KiB or more from the inputs: upward, whole vectors",
         {0, 0, 0, 0, 0, 0, 0, 1024, 2048, 3072},
         sweep::upward},
        {"an output 128 bytes past one input and 128 before another: neither, plain stores",
         {0, 0, 0, 0, 256, 256, 256, 128, 128, 128},
         sweep::neither},
        {"in place, the arrays 512 bytes or more apart: upward",
         {512, 1536, 2560, 3584, 0, 1024, 2048, -5, -6, -7},
         sweep::upward},
        {"in place, w 64 bytes before output x: downward",
         {4032, 1536, 2560, 3584, 0, 1024, 2048, -5, -6, -7},
         sweep::downward},
    };
    quat::test::random_rotations random;
    constexpr std::size_t n = 2999, region = 4096;  // floats: 16 KiB
    const std::vector<quaternion<float>> q = random_rotations<float>(random, n);
    const std::vector<vec3<float>> p = random_points<float>(random, n);
    const float sentinel = 9;
    for (const page_layout& layout : layouts) {
        for (const std::size_t count : {0u, 1u, 15u, 16u, 17u, 33u, 257u, 2999u}) {
            INFO(layout.name << ", " << count << " elements");
            std::vector<float> buffer(11 * region, sentinel);
            const auto address = reinterpret_cast<std::uintptr_t>(buffer.data());
            float* const base = buffer.data() + (4096 - address % 4096) % 4096 / sizeof(float);
            REQUIRE(quat::detail::is_aligned(base, 4096));
            float* arrays[10];
            for (std::size_t k = 0; k < 10; ++k) {
                const std::ptrdiff_t at = layout.offsets[k];
                arrays[k] =
                    at < 0 ? arrays[-1 - at] : base + k * region + static_cast<std::size_t>(at) / 4;
            }
            for (std::size_t i = 0; i < count; ++i) {
                arrays[0][i] = q[i].w, arrays[1][i] = q[i].x;
                arrays[2][i] = q[i].y, arrays[3][i] = q[i].z;
                arrays[4][i] = p[i].x, arrays[5][i] = p[i].y, arrays[6][i] = p[i].z;
            }
            const float* const inputs[] = {arrays[0], arrays[1], arrays[2], arrays[3],
                                           arrays[4], arrays[5], arrays[6]};
            const float* const outputs[] = {arrays[7], arrays[8], arrays[9]};
            CHECK(quat::detail::sweep_clear_of_aliasing(inputs, outputs, 256) == layout.way);
            CHECK(quat::detail::sweep_clear_of_aliasing(inputs, outputs, 512) == layout.way);
            const soa_points<float> out{arrays[7], arrays[8], arrays[9], count};
            quat::detail::rotate_each_soa_streaming(
                soa_quaternions<const float>{arrays[0], arrays[1], arrays[2], arrays[3], count},
                soa_points<const float>{arrays[4], arrays[5], arrays[6], count}, out);
            CHECK(failures(count, [&](std::size_t i) {
                      return is_rotate(vec3<float>{out.x[i], out.y[i], out.z[i]}, q[i], p[i]);
                  }) == 0);
            CHECK((out.x[count] == sentinel && out.y[count] == sentinel &&
                   out.z[count] == sentinel));  // nothing written past the end
        }
    }
}
#endif

TEMPLATE_TEST_CASE("compose_each is a[i] * b[i], also in place", "[elementwise]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (const std::size_t n : counts()) {
        const std::vector<quaternion<T>> a = random_rotations<T>(random, n);
        const std::vector<quaternion<T>> b = random_rotations<T>(random, n);
        std::vector<quaternion<T>> out(n);
        quat::compose_each(a.data(), b.data(), out.data(), n);
        for (std::size_t i = 0; i < n; ++i)
            CHECK(max_difference(out[i], a[i] * b[i]) <= contraction<T>);
        std::vector<quaternion<T>> in_a = a, in_b = b;
        quat::compose_each(in_a, b, in_a);  // output == a
        quat::compose_each(a, in_b, in_b);  // output == b
        CHECK(in_a == out);
        CHECK(in_b == out);
        std::vector<quaternion<T>> squares = a, expected(n);
        quat::compose_each(a, a, expected);
        quat::compose_each(squares, squares, squares);  // output == a == b
        CHECK(squares == expected);
    }
}

TEMPLATE_TEST_CASE("to_matrix_each and to_quaternion_each equal the scalar conversions",
                   "[elementwise]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    for (const std::size_t n : counts()) {
        std::vector<quaternion<T>> q = random_rotations<T>(random, n);
        // Every case of Shepperd's method: near-identity, and half turns about each axis.
        if (n > 3) q[0] = quaternion<T>::identity(), q[1] = {0, 1, 0, 0}, q[2] = {0, 0, 1, 0};
        if (n > 3) q[3] = {0, 0, 0, 1};
        std::vector<rotation_matrix<T>> m(n);
        quat::to_matrix_each(q.data(), m.data(), n);
        for (std::size_t i = 0; i < n; ++i)
            CHECK(max_difference(m[i], quat::to_matrix(q[i])) <= contraction<T>);
        std::vector<quaternion<T>> back(n);
        quat::to_quaternion_each(m, back);
        for (std::size_t i = 0; i < n; ++i)
            CHECK(max_difference(back[i], quat::to_quaternion(m[i])) <= contraction<T>);
    }
}

TEST_CASE("the container forms accept std::vector, std::array and C arrays", "[elementwise]") {
    const quat::quatd quarter_z =
        quat::to_quaternion(quat::axis_angle<double>{{0, 0, 1}, 1.5707963267948966});
    const std::array<quat::quatd, 2> q{{quarter_z, quat::quatd::identity()}};
    const vec3<double> p[2] = {{1, 0, 0}, {0, 1, 0}};
    std::vector<vec3<double>> out(2);
    quat::rotate_each(q, p, out);
    CHECK(max_difference(out[0], vec3<double>{0, 1, 0}) <= 1e-15);
    CHECK(out[1] == p[1]);
    quat::quatd products[2];
    quat::compose_each(q, q, products);
    CHECK(max_difference(products[0], quarter_z * quarter_z) <= contraction<double>);
    std::array<rotation_matrix<double>, 2> m{};
    quat::to_matrix_each(q, m);
    CHECK(m[1] == rotation_matrix<double>::identity());
    std::vector<quat::quatd> back(2);
    quat::to_quaternion_each(m, back);
    CHECK(back[1] == quat::quatd::identity());
}

namespace {

// Detects whether to_matrix / to_quaternion accept (input, output) arrays: they must not, since the
// element-wise conversions are spelled to_matrix_each and to_quaternion_each.
template <class Input, class Output, class = void>
struct plain_to_matrix_takes_arrays : std::false_type {};
template <class Input, class Output>
struct plain_to_matrix_takes_arrays<
    Input, Output,
    std::void_t<decltype(quat::to_matrix(std::declval<Input>(), std::declval<Output>()))>>
    : std::true_type {};
template <class Input, class Output, class = void>
struct plain_to_quaternion_takes_arrays : std::false_type {};
template <class Input, class Output>
struct plain_to_quaternion_takes_arrays<
    Input, Output,
    std::void_t<decltype(quat::to_quaternion(std::declval<Input>(), std::declval<Output>()))>>
    : std::true_type {};
template <class Input, class Output, class = void>
struct to_matrix_each_accepts : std::false_type {};
template <class Input, class Output>
struct to_matrix_each_accepts<
    Input, Output,
    std::void_t<decltype(quat::to_matrix_each(std::declval<Input>(), std::declval<Output>()))>>
    : std::true_type {};

using quaternions = std::vector<quat::quatd>;
using matrices = std::vector<rotation_matrix<double>>;
// One spelling: element i of the output from element i of the input is _each.
static_assert(to_matrix_each_accepts<const quaternions&, matrices&>::value);
static_assert(!plain_to_matrix_takes_arrays<const quaternions&, matrices&>::value);
static_assert(!plain_to_quaternion_takes_arrays<const matrices&, quaternions&>::value);
// The container forms take only containers of the element type they convert.
static_assert(!to_matrix_each_accepts<const std::vector<vec3<double>>&, matrices&>::value);
static_assert(!to_matrix_each_accepts<const quaternions&, std::vector<quat::quatd>&>::value);

}  // namespace

TEMPLATE_TEST_CASE("NaN in one element gives NaN in that element only", "[elementwise]", float,
                   double) {
    using T = TestType;
    const T nan = std::numeric_limits<T>::quiet_NaN();
    quat::test::random_rotations random;
    const std::size_t n = 40;
    std::vector<quaternion<T>> q = random_rotations<T>(random, n);
    std::vector<vec3<T>> p = random_points<T>(random, n);
    q[5].x = nan;
    p[17].y = nan;
    std::vector<vec3<T>> out(n);
    quat::rotate_each(q, p, out);
    std::vector<quaternion<T>> products(n);
    quat::compose_each(q, q, products);
    std::vector<rotation_matrix<T>> m(n);
    quat::to_matrix_each(q, m);
    m[9](2, 1) = nan;
    std::vector<quaternion<T>> back(n);
    quat::to_quaternion_each(m, back);
    for (std::size_t i = 0; i < n; ++i) {
        INFO("element " << i);
        CHECK(std::isnan(out[i].x + out[i].y + out[i].z) == (i == 5 || i == 17));
        CHECK(std::isnan(quat::dot(products[i], products[i])) == (i == 5));
        CHECK(std::isnan(quat::dot(back[i], back[i])) == (i == 5 || i == 9));
    }
}

TEMPLATE_TEST_CASE("to_quaternion_each off its precondition gives to_quaternion's result",
                   "[elementwise]", float, double) {
    using T = TestType;
    const T inf = std::numeric_limits<T>::infinity(), huge = std::numeric_limits<T>::max() / 4;
    quat::test::random_rotations random;
    const std::size_t n = 40;  // two whole groups of 16 in AVX-512 builds, and a tail
    std::vector<rotation_matrix<T>> m(n);
    for (auto& r : m) r = quat::to_matrix(random.unit_quaternion<T>());
    rotation_matrix<T> scaled_up = m[3], scaled_down = m[4];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) scaled_up(r, c) *= huge, scaled_down(r, c) *= T(1e-30);
    rotation_matrix<T> infinite = m[5];
    infinite(0, 2) = inf;
    const rotation_matrix<T> zero{};
    // A bad matrix in the first group, and one group later left all valid.
    m[3] = scaled_up, m[4] = scaled_down, m[5] = infinite, m[6] = zero, m[36] = scaled_up;
    std::vector<quaternion<T>> out(n);
    quat::to_quaternion_each(m, out);
    for (std::size_t i = 0; i < n; ++i) {
        INFO("element " << i);
        const quaternion<T> expected = quat::to_quaternion(m[i]);
        const bool expected_nan = std::isnan(quat::dot(expected, expected));
        CHECK(std::isnan(quat::dot(out[i], out[i])) == expected_nan);
        if (!expected_nan) CHECK(max_difference(out[i], expected) <= contraction<T>);
    }
}

TEMPLATE_TEST_CASE("struct-of-arrays rotate_each in place: the writable views are also the inputs",
                   "[elementwise]", float, double) {
    using T = TestType;
    quat::test::random_rotations random;
    const std::size_t n = 23;
    std::vector<T> w(n), x(n), y(n), z(n), px(n), py(n), pz(n);
    std::vector<vec3<T>> expected(n);
    for (std::size_t i = 0; i < n; ++i) {
        const quaternion<T> q = random.unit_quaternion<T>();
        w[i] = q.w, x[i] = q.x, y[i] = q.y, z[i] = q.z;
        px[i] = T(i), py[i] = -T(i), pz[i] = T(1);
        expected[i] = quat::rotate(q, vec3<T>{px[i], py[i], pz[i]});
    }
    // soa_quaternions<T> and soa_points<T> convert to their const forms.
    static_assert(std::is_convertible_v<soa_quaternions<T>, soa_quaternions<const T>>);
    static_assert(!std::is_convertible_v<soa_quaternions<const T>, soa_quaternions<T>>);
    const soa_quaternions<T> rotations{w.data(), x.data(), y.data(), z.data(), n};
    const soa_points<T> points{px.data(), py.data(), pz.data(), n};
    quat::rotate_each(rotations, points, points);
    for (std::size_t i = 0; i < n; ++i)
        CHECK(max_difference(vec3<T>{px[i], py[i], pz[i]}, expected[i]) <=
              rotate_each_vs_rotate<T> * T(i + 1));  // |p| <= i + 1
}

}  // namespace test_elementwise
