// Instantiates the per-element batches (batch/elementwise.hpp) for float, double and long double
// under the strict warning flags: every overload of rotate_each, compose_each, to_matrix_each and
// to_quaternion_each, through pointers, std::vector, std::array and C arrays. Compiled, not run, by
// the strict_warnings CTest test.
#include <array>
#include <vector>

#include <quat/batch/elementwise.hpp>

namespace {

template <class T>
T elementwise() {
    using namespace quat;
    const quaternion<T> q = normalize(quaternion<T>{1, 2, 3, 4});
    const std::vector<quaternion<T>> rotations(5, q);
    std::vector<vec3<T>> points(5, vec3<T>{1, -2, 3}), out(5);
    rotate_each(rotations.data(), points.data(), out.data(), points.size());
    rotate_each(rotations, points, out);
    rotate_each(rotations, points, points);
    const std::array<quaternion<T>, 2> pair{{q, q}};
    const vec3<T> two[2] = {{1, 0, 0}, {0, 1, 0}};
    vec3<T> turned[2];
    rotate_each(pair, two, turned);
    std::vector<T> w(5, T(1)), x(5, T(0)), y(5, T(2)), z(5, T(3));
    rotate_each(soa_quaternions<const T>{w.data(), x.data(), x.data(), x.data(), 5},
                soa_points<const T>{x.data(), y.data(), z.data(), 5},
                soa_points<T>{x.data(), y.data(), z.data(), 5});
    std::vector<quaternion<T>> products(5);
    compose_each(rotations.data(), rotations.data(), products.data(), rotations.size());
    compose_each(rotations, rotations, products);
    compose_each(products, rotations, products);
    quaternion<T> pair_products[2];
    compose_each(pair, pair, pair_products);
    std::vector<rotation_matrix<T>> matrices(5);
    to_matrix_each(rotations.data(), matrices.data(), rotations.size());
    to_matrix_each(rotations, matrices);
    to_quaternion_each(matrices.data(), products.data(), matrices.size());
    to_quaternion_each(matrices, products);
    std::array<rotation_matrix<T>, 2> pair_matrices{};
    to_matrix_each(pair, pair_matrices);
    to_quaternion_each(pair_matrices, pair_products);
    return out[4].x + points[3].y + turned[1].z + z[2] + products[1].w + pair_products[0].x +
           matrices[2](1, 1);
}

}  // namespace

int main() {
    return elementwise<float>() + static_cast<float>(elementwise<double>()) +
                       static_cast<float>(elementwise<long double>()) >
                   0
               ? 0
               : 1;
}
