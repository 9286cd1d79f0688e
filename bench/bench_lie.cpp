// lie/so3.hpp and lie/se3.hpp: each analytic Jacobian (jacobian/quat/<op>/double, the value and its
// Jacobians in one call) against the same Jacobian by automatic differentiation with ceres::Jet
// (jacobian/jet/<op>/double: the function evaluated on Jets, its ambient derivatives read into the
// tangent Jacobian of the right plus and minus, as tests/test_so3.cpp and test_se3.cpp check them),
// and so3/se3 exp, log, plus and minus without Jacobians (exp and log beside from_rotation_vector
// and to_rotation_vector); the pose-graph relative-pose errors of lie/relative_pose.hpp in both
// forms, with the Jacobians for both poses, against Jet through the same functions.
#include <string>
#include <tuple>
#include <utility>

#include <quat/lie/relative_pose.hpp>
#include <quat/lie/se3.hpp>
#include <quat/lie/so3.hpp>

#include "common.hpp"
#include "jet_tangents.hpp"

namespace bench {
namespace {

using quat::matrix;
using quat::matrix3;
using quat::matrix6;
using quat::quatd;
using quat::vec3;
using dq = quat::dual_quaternion<double>;
using twist = quat::se3::twist<double>;
template <int N>
using residual_of = matrix<jet<N>, 6, 1>;

// Inputs: rotation vectors with angles in [0, pi), unit quaternions, twists and rigid motions.
vec3<double> rotation_vector(random_source& r) {
    return quat::normalize(r.vector()) * r.uniform(0, 3.14159);
}
twist random_twist(random_source& r) {
    const vec3<double> linear = r.vector();
    return {linear, rotation_vector(r)};
}
dq motion(random_source& r) {
    const quatd q = r.rotation();
    return quat::to_dual_quaternion(q, r.vector());
}

/// A value and its Jacobians, returned whole so that nothing is optimized away.
template <class V, class... J>
struct with_jacobians {
    V value;
    std::tuple<J...> jacobians;
};

template <class Make, class F>
void add(const std::string& name, Make make, F f) {
    benchmark::RegisterBenchmark(name.c_str(),
                                 [make, f](benchmark::State& state) { cycle(state, make, f); });
}

}  // namespace

void register_lie() {
    namespace so3 = quat::so3;
    namespace se3 = quat::se3;
    const auto pair = [](random_source& r) {
        const quatd a = r.rotation();
        return std::pair<quatd, quatd>{a, r.rotation()};
    };
    const auto act_input = [](random_source& r) {
        const quatd q = r.rotation();
        return std::pair<quatd, vec3<double>>{q, r.vector()};
    };
    const auto motions = [](random_source& r) {
        const dq a = motion(r);
        return std::pair<dq, dq>{a, motion(r)};
    };
    const auto rotation = [](random_source& r) { return r.rotation(); };

    // SO(3) exp and log, with and without Jacobians, beside the conversions they are.
    add("so3/exp/double", rotation_vector, [](const vec3<double>& w) { return so3::exp(w); });
    add("so3/from_rotation_vector/double", rotation_vector,
        [](const vec3<double>& w) { return quat::from_rotation_vector(w); });
    add("so3/log/double", rotation, [](const quatd& q) { return so3::log(q); });
    add("so3/to_rotation_vector/double", rotation,
        [](const quatd& q) { return quat::to_rotation_vector(q); });
    add("se3/exp/double", random_twist, [](const twist& t) { return se3::exp(t); });
    add("se3/log/double", motion, [](const dq& x) { return se3::log(x); });
    const auto step = [](random_source& r) {
        const quatd q = r.rotation();
        return std::pair<quatd, vec3<double>>{q, rotation_vector(r)};
    };
    const auto rigid_step = [](random_source& r) {
        const dq x = motion(r);
        return std::pair<dq, twist>{x, random_twist(r)};
    };
    add("so3/plus/double", step,
        [](const std::pair<quatd, vec3<double>>& p) { return so3::plus(p.first, p.second); });
    add("so3/minus/double", pair,
        [](const std::pair<quatd, quatd>& p) { return so3::minus(p.first, p.second); });
    add("se3/plus/double", rigid_step,
        [](const std::pair<dq, twist>& p) { return se3::plus(p.first, p.second); });
    add("se3/minus/double", motions,
        [](const std::pair<dq, dq>& p) { return se3::minus(p.first, p.second); });

    add("jacobian/quat/so3_exp/double", rotation_vector, [](const vec3<double>& w) {
        with_jacobians<quatd, matrix3<double>> r{};
        r.value = so3::exp(w, &std::get<0>(r.jacobians));
        return r;
    });
    add("jacobian/jet/so3_exp/double", rotation_vector, [](const vec3<double>& w) {
        const auto q = quat::from_rotation_vector(variables<3>(w, 0));
        return tangent(q);
    });
    add("jacobian/quat/so3_log/double", rotation, [](const quatd& q) {
        with_jacobians<vec3<double>, matrix3<double>> r{};
        r.value = so3::log(q, &std::get<0>(r.jacobians));
        return r;
    });
    add("jacobian/jet/so3_log/double", rotation, [](const quatd& q) {
        const vec3<jet<3>> w = quat::to_rotation_vector(first_order_plus<3>(q, 0));
        const jet<3> outputs[3] = {w.x, w.y, w.z};
        return partials(outputs);
    });
    add("jacobian/quat/so3_compose/double", pair, [](const std::pair<quatd, quatd>& p) {
        with_jacobians<quatd, matrix3<double>, matrix3<double>> r{};
        r.value =
            so3::compose(p.first, p.second, &std::get<0>(r.jacobians), &std::get<1>(r.jacobians));
        return r;
    });
    add("jacobian/jet/so3_compose/double", pair, [](const std::pair<quatd, quatd>& p) {
        return tangent(first_order_plus<6>(p.first, 0) * first_order_plus<6>(p.second, 3));
    });
    add("jacobian/quat/so3_act/double", act_input, [](const std::pair<quatd, vec3<double>>& p) {
        with_jacobians<vec3<double>, matrix3<double>, matrix3<double>> r{};
        r.value = so3::act(p.first, p.second, &std::get<0>(r.jacobians), &std::get<1>(r.jacobians));
        return r;
    });
    add("jacobian/jet/so3_act/double", act_input, [](const std::pair<quatd, vec3<double>>& p) {
        const vec3<jet<6>> v =
            quat::rotate(first_order_plus<6>(p.first, 0), variables<6>(p.second, 3));
        const jet<6> outputs[3] = {v.x, v.y, v.z};
        return partials(outputs);
    });

    add("jacobian/quat/se3_exp/double", random_twist, [](const twist& t) {
        with_jacobians<dq, matrix6<double>> r{};
        r.value = se3::exp(t, &std::get<0>(r.jacobians));
        return r;
    });
    add("jacobian/jet/se3_exp/double", random_twist, [](const twist& t) {
        return tangent(
            se3::exp(se3::twist<jet<6>>{variables<6>(t.linear, 0), variables<6>(t.angular, 3)}));
    });
    add("jacobian/quat/se3_log/double", motion, [](const dq& x) {
        with_jacobians<twist, matrix6<double>> r{};
        r.value = se3::log(x, &std::get<0>(r.jacobians));
        return r;
    });
    add("jacobian/jet/se3_log/double", motion, [](const dq& x) {
        const se3::twist<jet<6>> t = se3::log(first_order_plus<6>(x, 0));
        const jet<6> outputs[6] = {t.linear.x,  t.linear.y,  t.linear.z,
                                   t.angular.x, t.angular.y, t.angular.z};
        return partials(outputs);
    });
    add("jacobian/quat/se3_between/double", motions, [](const std::pair<dq, dq>& p) {
        with_jacobians<dq, matrix6<double>, matrix6<double>> r{};
        r.value =
            se3::between(p.first, p.second, &std::get<0>(r.jacobians), &std::get<1>(r.jacobians));
        return r;
    });
    add("jacobian/jet/se3_between/double", motions, [](const std::pair<dq, dq>& p) {
        return tangent(
            se3::between(first_order_plus<12>(p.first, 0), first_order_plus<12>(p.second, 6)));
    });

    // A pose-graph edge: poses a, b and a measurement near between(a, b).
    const auto edge = [](random_source& r) {
        const dq a = motion(r), b = motion(r);
        return std::tuple<dq, dq, dq>{a, b, se3::plus(se3::between(a, b), random_twist(r) * 0.01)};
    };
    using edge_type = std::tuple<dq, dq, dq>;
    using residual = matrix<double, 6, 1>;
    // The error of either form and both Jacobians by Jet: 12 variables, a's tangent then b's.
    const auto jet_error = [](auto error, const edge_type& e) {
        const residual_of<12> r =
            error(first_order_plus<12>(std::get<0>(e), 0), first_order_plus<12>(std::get<1>(e), 6),
                  quat::dual_quaternion<jet<12>>(std::get<2>(e)));
        const jet<12> outputs[6] = {r(0, 0), r(1, 0), r(2, 0), r(3, 0), r(4, 0), r(5, 0)};
        return partials(outputs);
    };
    add("jacobian/quat/relative_pose_so3xr3/double", edge, [](const edge_type& e) {
        with_jacobians<residual, matrix6<double>, matrix6<double>> r{};
        r.value =
            quat::so3xr3::relative_pose_error(std::get<0>(e), std::get<1>(e), std::get<2>(e),
                                              &std::get<0>(r.jacobians), &std::get<1>(r.jacobians));
        return r;
    });
    add("jacobian/jet/relative_pose_so3xr3/double", edge, [jet_error](const edge_type& e) {
        return jet_error([](const auto& a, const auto& b,
                            const auto& z) { return quat::so3xr3::relative_pose_error(a, b, z); },
                         e);
    });
    add("jacobian/quat/relative_pose_se3/double", edge, [](const edge_type& e) {
        with_jacobians<residual, matrix6<double>, matrix6<double>> r{};
        r.value = se3::relative_pose_error(std::get<0>(e), std::get<1>(e), std::get<2>(e),
                                           &std::get<0>(r.jacobians), &std::get<1>(r.jacobians));
        return r;
    });
    add("jacobian/jet/relative_pose_se3/double", edge, [jet_error](const edge_type& e) {
        return jet_error([](const auto& a, const auto& b,
                            const auto& z) { return se3::relative_pose_error(a, b, z); },
                         e);
    });
}

}  // namespace bench
