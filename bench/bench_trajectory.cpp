// trajectory/so3_bspline.hpp and se3_bspline.hpp: one evaluation of the value, the body velocity
// and its derivative with the Jacobians of all three with respect to the K control points
// (jacobian/quat/<spline>_k<K>/double: the analytic O(K) recurrences) against the same three
// Jacobians by automatic differentiation with ceres::Jet (jacobian/jet/<spline>_k<K>/double: the
// spline evaluated on Jets over the 3K (SO(3)) or 6K (SE(3)) right-tangent perturbations of the
// control points, the value's derivatives read into its tangent as bench_lie.cpp does), for K = 4,
// 5, 6; the value, velocity, acceleration and jerk without Jacobians, by the O(K) recurrences
// (derivatives/quat/<spline>_k<K>/double) and by the O(K^2)-and-more product rule that the tests
// hold them to (derivatives/textbook/<spline>_k<K>/double, tests/support/bspline_reference.hpp,
// weights included in both); and evaluation over 1024 sorted times of a 64-point spline, the value alone and with every
// Jacobian (bspline_batch/quat/<spline>_k<K>_{value,jacobians}/double/1024: items are times).
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <quat/trajectory/se3_bspline.hpp>
#include <quat/trajectory/so3_bspline.hpp>

#include "../tests/support/bspline_reference.hpp"
#include "common.hpp"
#include "jet_tangents.hpp"

namespace bench {
namespace {

using quat::matrix;
using quat::quatd;
using quat::vec3;
using dq = quat::dual_quaternion<double>;

/// K control points of one segment (t0 = 0, dt = 1, the domain [0, 1]) and a time in it. Each
/// point is a small random step from the previous one, as a fitted trajectory's are.
template <class Point, std::size_t K>
struct segment {
    std::array<Point, K> points;
    double t;
};
quatd step_rotation(random_source& r, const quatd& from) {
    return from * quat::from_rotation_vector(quat::normalize(r.vector()) * r.uniform(0.05, 0.8));
}
template <std::size_t K>
segment<quatd, K> rotations(random_source& r) {
    segment<quatd, K> s{};
    s.points[0] = r.rotation();
    for (std::size_t m = 1; m < K; ++m) s.points[m] = step_rotation(r, s.points[m - 1]);
    s.t = r.uniform(0, 1);
    return s;
}
template <std::size_t K>
segment<dq, K> motions(random_source& r) {
    const segment<quatd, K> q = rotations<K>(r);
    segment<dq, K> s{};
    vec3<double> p = r.vector();
    for (std::size_t m = 0; m < K; ++m) {
        s.points[m] = quat::to_dual_quaternion(q.points[m], p);
        p += r.vector() * 0.3;
    }
    s.t = q.t;
    return s;
}

/// A sample and its three Jacobians, returned whole so that nothing is optimized away.
template <class Sample, class Blocks>
struct sample_with_jacobians {
    Sample sample;
    Blocks J_value, J_velocity, J_acceleration;
};
template <class Value, class Rate>
struct jet_jacobians {
    Value J_value;
    Rate J_velocity, J_acceleration;
};

template <class Make, class F>
void add(const std::string& name, Make make, F f) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [make, f](benchmark::State& state) { cycle(state, make, f); });
}

template <std::size_t K>
void register_order() {
    const std::string k = "_k" + std::to_string(K);
    static constexpr int N3 = static_cast<int>(3 * K), N6 = static_cast<int>(6 * K);
    using so3 = quat::so3_bspline<double, K>;
    using se3 = quat::se3_bspline<double, K>;
    add("jacobian/quat/so3_bspline" + k + "/double", rotations<K>, [](const segment<quatd, K>& s) {
        sample_with_jacobians<quat::so3_bspline_sample<double>, typename so3::jacobian_blocks> r{};
        r.sample = so3(s.points.data(), K, 0.0, 1.0)
                       .evaluate(s.t, &r.J_value, &r.J_velocity, &r.J_acceleration);
        return r;
    });
    add("jacobian/jet/so3_bspline" + k + "/double", rotations<K>, [](const segment<quatd, K>& s) {
        std::array<quat::quaternion<jet<N3>>, K> points;
        for (int m = 0; m < static_cast<int>(K); ++m)
            points[static_cast<std::size_t>(m)] =
                first_order_plus<N3>(s.points[static_cast<std::size_t>(m)], 3 * m);
        const auto sample = quat::so3_bspline<jet<N3>, K>(points.data(), K, jet<N3>(0), jet<N3>(1))
                                .evaluate(jet<N3>(s.t));
        return jet_jacobians<matrix<double, 3, N3>, matrix<double, 3, N3>>{
            tangent(sample.rotation), partials(sample.angular_velocity),
            partials(sample.angular_acceleration)};
    });
    add("jacobian/quat/se3_bspline" + k + "/double", motions<K>, [](const segment<dq, K>& s) {
        sample_with_jacobians<quat::se3_bspline_sample<double>, typename se3::jacobian_blocks> r{};
        r.sample = se3(s.points.data(), K, 0.0, 1.0)
                       .evaluate(s.t, &r.J_value, &r.J_velocity, &r.J_acceleration);
        return r;
    });
    add("jacobian/jet/se3_bspline" + k + "/double", motions<K>, [](const segment<dq, K>& s) {
        std::array<quat::dual_quaternion<jet<N6>>, K> points;
        for (int m = 0; m < static_cast<int>(K); ++m)
            points[static_cast<std::size_t>(m)] =
                first_order_plus<N6>(s.points[static_cast<std::size_t>(m)], 6 * m);
        const auto sample = quat::se3_bspline<jet<N6>, K>(points.data(), K, jet<N6>(0), jet<N6>(1))
                                .evaluate(jet<N6>(s.t));
        return jet_jacobians<matrix<double, 6, N6>, matrix<double, 6, N6>>{
            tangent(sample.motion), partials(sample.velocity), partials(sample.acceleration)};
    });
}

/// Value, velocity, acceleration and jerk: the library's recurrences against the textbook product
/// rule, both from the same segment and time.
template <std::size_t K>
void register_textbook() {
    const std::string k = "_k" + std::to_string(K);
    add("derivatives/quat/so3_bspline" + k + "/double", rotations<K>,
        [](const segment<quatd, K>& s) {
            return quat::so3_bspline<double, K>(s.points.data(), K, 0.0, 1.0).evaluate(s.t);
        });
    add("derivatives/textbook/so3_bspline" + k + "/double", rotations<K>,
        [](const segment<quatd, K>& s) {
            return quat::test::textbook_bspline<quat::test::so3_reference<double>, double, K>(
                s.points.data(), quat::detail::cumulative_weights_at<double, K>(s.t, 1.0));
        });
    add("derivatives/quat/se3_bspline" + k + "/double", motions<K>, [](const segment<dq, K>& s) {
        return quat::se3_bspline<double, K>(s.points.data(), K, 0.0, 1.0).evaluate(s.t);
    });
    add("derivatives/textbook/se3_bspline" + k + "/double", motions<K>,
        [](const segment<dq, K>& s) {
            return quat::test::textbook_bspline<quat::test::se3_reference<double>, double, K>(
                s.points.data(), quat::detail::cumulative_weights_at<double, K>(s.t, 1.0));
        });
}

/// 64 control points in a chain of small steps, and 1024 sorted times over the whole domain.
template <class Point>
struct batch_input {
    std::vector<Point> points;
    std::vector<double> times;
};
template <class Point, std::size_t K>
batch_input<Point> make_batch(random_source& r) {
    constexpr std::size_t count = 64, times = 1024;
    batch_input<Point> b;
    quatd q = r.rotation();
    vec3<double> p = r.vector();
    for (std::size_t i = 0; i < count; ++i) {
        if constexpr (std::is_same_v<Point, quatd>) b.points.push_back(q);
        else b.points.push_back(quat::to_dual_quaternion(q, p));
        q = step_rotation(r, q);
        p += r.vector() * 0.3;
    }
    const double end = double(count - K + 1);
    for (std::size_t i = 0; i < times; ++i) b.times.push_back(r.uniform(0, end));
    std::sort(b.times.begin(), b.times.end());
    return b;
}

template <template <class, std::size_t> class Spline, class Point, std::size_t K>
void register_batch(const std::string& spline_name) {
    const std::string prefix = "bspline_batch/quat/" + spline_name + "_k" + std::to_string(K);
    benchmark::RegisterBenchmark(
        (prefix + "_value/double/1024").c_str(), [](benchmark::State& state) {
            random_source random;
            const batch_input<Point> b = make_batch<Point, K>(random);
            const Spline<double, K> spline(b.points, 0.0, 1.0);
            for (auto _ : state) {
                for (const double t : b.times) {
                    auto value = spline(t);
                    benchmark::DoNotOptimize(value);
                }
            }
            state.SetItemsProcessed(state.iterations() *
                                    static_cast<benchmark::IterationCount>(b.times.size()));
        });
    benchmark::RegisterBenchmark(
        (prefix + "_jacobians/double/1024").c_str(), [](benchmark::State& state) {
            random_source random;
            const batch_input<Point> b = make_batch<Point, K>(random);
            const Spline<double, K> spline(b.points, 0.0, 1.0);
            typename Spline<double, K>::jacobian_blocks J_value{}, J_velocity{}, J_acceleration{};
            for (auto _ : state) {
                for (const double t : b.times) {
                    auto sample = spline.evaluate(t, &J_value, &J_velocity, &J_acceleration);
                    benchmark::DoNotOptimize(sample);
                    benchmark::DoNotOptimize(J_value);
                    benchmark::DoNotOptimize(J_velocity);
                    benchmark::DoNotOptimize(J_acceleration);
                }
            }
            state.SetItemsProcessed(state.iterations() *
                                    static_cast<benchmark::IterationCount>(b.times.size()));
        });
}

}  // namespace

void register_trajectory() {
    register_order<4>();
    register_order<5>();
    register_order<6>();
    register_textbook<4>();
    register_textbook<5>();
    register_textbook<6>();
    register_batch<quat::so3_bspline, quatd, 4>("so3");
    register_batch<quat::se3_bspline, dq, 4>("se3");
    register_batch<quat::so3_bspline, quatd, 6>("so3");
    register_batch<quat::se3_bspline, dq, 6>("se3");
}

}  // namespace bench
