// Instantiates every public function template of quat for float, double and long double, so that
// the strict warning flags users compile with (-Wconversion, -Wsign-conversion, -Wdouble-promotion,
// -Wshadow, -Wold-style-cast, ...) see the library's template code, not only its declarations.
// Compiled, not run, by the strict_warnings CTest test (cmake/strict-warnings.cmake).
#include <array>
#include <sstream>
#include <vector>

#include <quat/io.hpp>
#include <quat/quat.hpp>

namespace {

template <class T, quat::sequence S, quat::frame F>
T euler_functions(const quat::quaternion<T>& q) {
    const quat::euler<T, S, F> e = quat::to_euler<S, F>(q);
    const auto [a0, a1, a2] = e;
    const quat::euler<float, S, F> single{e};
    const auto extraction = quat::extract_euler<S, F>(q);
    return a0 + a1 + a2 + static_cast<T>(single[0]) + quat::to_quaternion(e).w +
           quat::to_matrix(e)(0, 0) + quat::to_axis_angle(e).angle + extraction.angles[1] +
           quat::to_euler<quat::sequence::zyx>(e)[0] + quat::to_euler<S, F>(quat::to_matrix(q))[0] +
           quat::to_euler<S, F>(quat::to_axis_angle(q))[0];
}

template <class T>
T everything() {
    using namespace quat;
    quaternion<T> q = normalize(quaternion<T>{1, 2, 3, 4});
    const quaternion<T> r = rotation_x(T(0.5)) * rotation_y(T(0.25)) * rotation_z(T(1));
    vec3<T> v{1, 2, 3};
    v += v * 2;
    v -= 2 * v;
    v *= 3;
    v /= 4;
    v = v / 2 + cross(v, v) - (-v);
    q *= r;
    q *= 2;
    q /= 2;
    q += r;
    q -= r;
    q = normalize(q * 2 + 2 * q - q / 2);
    const quaternion<float> single{q};
    const vec3<float> single_v{v};
    T sum = dot(v, v) + squared_norm(v) + norm(v) + normalize(v).x + try_normalize(v)->y +
            static_cast<T>(single.w) + static_cast<T>(single_v.x);
    sum += conjugate(q).w + dot(q, r) + squared_norm(q) + norm(q) + try_normalize(q)->w +
           inverse(q).x + try_inverse(q)->y + rotate(q, v).z + angle_between(q, r) +
           T(approx_equal(q, r, T(0.1)) + is_unit(q, T(1e-3)) + (q == r) + (q != r) + (v == v) +
             (v != v));
    rotation_matrix<T> m = to_matrix(q);
    m *= to_matrix(r);
    const rotation_matrix<float> single_m{m};
    sum += row(m, 0).x + column(m, 1).y + (m * transpose(m))(2, 2) + rotate(m, v).x +
           determinant(m) + orthogonality_error(m) + static_cast<T>(single_m(0, 0)) + T(m == m) +
           T(m != m) + rotation_matrix<T>::identity()(1, 1) +
           rotation_matrix<T>::from_rows(v, v, v)(0, 0) +
           rotation_matrix<T>::from_columns(v, v, v)(0, 0);
    sum += to_quaternion(m).w + try_to_quaternion(m)->x + try_to_quaternion(m, T(0.5))->x +
           default_orthogonality_tolerance<T>() + nearest_rotation(m)(0, 0) +
           try_nearest_rotation(m).value_or(m)(1, 1);
    const axis_angle<T> aa = to_axis_angle(q);
    const axis_angle<float> single_aa{aa};
    sum += to_quaternion(aa).w + try_to_quaternion(aa)->w + to_matrix(aa)(0, 1) +
           to_axis_angle(m).angle + static_cast<T>(single_aa.angle) + from_rotation_vector(v).w +
           to_rotation_vector(q).x;
    sum += euler_functions<T, sequence::zyx, frame::intrinsic>(q) +
           euler_functions<T, sequence::xzx, frame::extrinsic>(q);
    sum += slerp(q, r, T(0.3)).w + slerp(q, r, T(1.5)).x + nlerp(q, r, T(0.3)).y +
           slerp_fast(q, r, T(0.3)).z + corrected_nlerp(q, r, T(0.3)).w;

    std::vector<vec3<T>> points(64, v), out(64);
    rotate(q, points, out);
    rotate(m, points, out);
    rotate(q, points.data(), out.data(), points.size());
    std::array<T, 8> x{}, y{}, z{};
    rotate(q, soa_points<const T>{x.data(), y.data(), z.data(), x.size()},
           soa_points<T>{x.data(), y.data(), z.data(), x.size()});
    const std::vector<quaternion<T>> factors(16, q);
    std::vector<T> ts(16, T(0.5));
    std::vector<quaternion<T>> slerped(16);
    slerp(q, r, ts, slerped);
    sum += compose(factors).w + compose(factors.data(), factors.size()).x + slerped[3].w + out[5].x;
    std::ostringstream text;
    text << q << v << m << aa << to_euler<sequence::zxz>(q) << extract_euler<sequence::xyz>(q);
    return sum + numbers::pi_v<T> + T(numbers::pi) + T(text.str().size());
}

}  // namespace

int main() {
    return everything<float>() + static_cast<float>(everything<double>()) +
                       static_cast<float>(everything<long double>()) >
                   0
               ? 0
               : 1;
}
