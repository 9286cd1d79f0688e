// The body of each quat_isa_mix unit, with internal linkage: every unit has its own copy, so the
// only functions the units could share are quat's (and the few of the standard library's that
// quat's code and the printing below call: std::ostringstream and std::string).
#ifndef QUAT_TESTS_ISA_MIX_COMPUTE_HPP
#define QUAT_TESTS_ISA_MIX_COMPUTE_HPP

#include <cstddef>
#include <cstring>
#include <sstream>
#include <string>

#include <quat/io.hpp>
#include <quat/quat.hpp>

#include "isa_mix.hpp"

namespace {

constexpr std::size_t big_count = std::size_t(3) << 19;  // 18 MiB of vec3<float>
quat::vec3<float> big_input[big_count], big_output[big_count];

void isa_mix_compute(isa_mix_results& r) noexcept {
    const quat::quatf qf = quat::normalize(quat::quatf{0.3f, -0.5f, 0.7f, 0.2f});
    const quat::quatd qd = quat::normalize(quat::quatd{0.3, -0.5, 0.7, 0.2});
    constexpr std::size_t n = isa_mix_results::samples;
    using any_function = isa_mix_results::any_function;
    using to_matrix_type = quat::rotation_matrix<double> (*)(const quat::quatd&) noexcept;
    using rotate_type = void (*)(const quat::quaternion<float>&, const quat::vec3<float>*,
                                 quat::vec3<float>*, std::size_t) noexcept;
    r.to_matrix =
        reinterpret_cast<any_function>(static_cast<to_matrix_type>(&quat::to_matrix<double>));
    r.batch_rotate = reinterpret_cast<any_function>(static_cast<rotate_type>(&quat::rotate<float>));

    for (std::size_t i = 0; i < big_count; ++i) {
        const float f = static_cast<float>(i % 1000);
        big_input[i] = {f, 1 - f, 0.5f * f};
    }
    quat::rotate(qf, big_input, big_output, big_count);
    for (std::size_t i = 0; i < n; ++i) {
        const quat::vec3<float>& p = big_output[i * 997];
        r.rotated[i][0] = p.x, r.rotated[i][1] = p.y, r.rotated[i][2] = p.z;
    }

    float x[n], y[n], z[n];
    for (std::size_t i = 0; i < n; ++i)
        x[i] = float(i), y[i] = 1 - float(i), z[i] = 0.25f * float(i);
    quat::rotate(qf, quat::soa_points<const float>{x, y, z, n},
                 quat::soa_points<float>{x, y, z, n});
    for (std::size_t i = 0; i < n; ++i)
        r.rotated_soa[i][0] = x[i], r.rotated_soa[i][1] = y[i], r.rotated_soa[i][2] = z[i];

    quat::vec3<double> points[n];
    for (std::size_t i = 0; i < n; ++i) points[i] = {double(i), -double(i), 2.0};
    const quat::dual_quaternion<double> motion =
        quat::to_dual_quaternion(qd, quat::vec3<double>{1, 2, 3});
    quat::transform(motion, points, points);
    for (std::size_t i = 0; i < n; ++i)
        r.transformed[i][0] = points[i].x, r.transformed[i][1] = points[i].y,
        r.transformed[i][2] = points[i].z;

    quat::quatf rotations[n];
    quat::vec3<float> vectors[n];
    for (std::size_t i = 0; i < n; ++i) {
        rotations[i] = quat::slerp(quat::quatf::identity(), qf, float(i) / float(n));
        vectors[i] = {1, float(i), -2};
    }
    quat::rotate_each(rotations, vectors, vectors);
    for (std::size_t i = 0; i < n; ++i)
        r.rotated_each[i][0] = vectors[i].x, r.rotated_each[i][1] = vectors[i].y,
        r.rotated_each[i][2] = vectors[i].z;

    const quat::rotation_matrix<double> m = quat::to_matrix(qd);
    for (int i = 0; i < 9; ++i) r.matrix[i] = m(i / 3, i % 3);

    const quat::quatf s = quat::slerp(qf, quat::quatf{0, 1, 0, 0}, 0.3f);
    r.slerped[0] = s.w, r.slerped[1] = s.x, r.slerped[2] = s.y, r.slerped[3] = s.z;

    float ts[n];
    quat::quatf slerped[n];
    for (std::size_t i = 0; i < n; ++i) ts[i] = float(i) / float(n - 1);
    quat::slerp(qf, quat::quatf{0, 1, 0, 0}, ts, slerped);
    for (std::size_t i = 0; i < n; ++i)
        r.slerped_batch[i][0] = slerped[i].w, r.slerped_batch[i][1] = slerped[i].x,
        r.slerped_batch[i][2] = slerped[i].y, r.slerped_batch[i][3] = slerped[i].z;

    // Nearly opposite directions: the compensated cross product (difference_of_products) runs.
    const quat::quatd b =
        quat::rotation_between(quat::vec3<double>{1, 1e-9, 0}, quat::vec3<double>{-1, 0, 1e-9});
    r.between[0] = b.w, r.between[1] = b.x, r.between[2] = b.y, r.between[3] = b.z;
    const quat::quatd l =
        quat::look_rotation(quat::vec3<double>{1, 0, 1e-7}, quat::vec3<double>{1, 1e-9, 0});
    r.looking[0] = l.w, r.looking[1] = l.x, r.looking[2] = l.y, r.looking[3] = l.z;

    // The value types' own members (matrix's zero, identity and element access): not keyed, so at
    // -O0 each call reaches whichever copy the linker kept unless the call is inlined. Halves and
    // small integers: every product is exact, so the units agree to the last bit, FMA or not.
    // Assigned, not initialized: g++ evaluates a constant initializer at compile time, calling
    // nothing.
    quat::matrix<double, 6, 6> jacobian;
    jacobian = quat::matrix<double, 6, 6>::identity();
    for (int i = 0; i < 6; ++i) jacobian((i + 1) % 6, i) = 0.5 * double(i);
    quat::matrix<double, 6, 6> covariance;
    covariance = quat::matrix<double, 6, 6>::zero();
    for (int i = 0; i < 6; ++i) covariance(i, i) = double(i + 1);
    const quat::matrix<double, 6, 6> propagated = jacobian * covariance * transpose(jacobian);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) r.propagated[i][j] = propagated(i, j);

    std::ostringstream text;
    text << quat::quatd{0.5, -0.5, 0.5, 0.5} << ' ' << propagated;
    const std::string printed = text.str();
    const std::size_t length = printed.size() < sizeof r.printed ? printed.size() : 0;
    std::memcpy(r.printed, printed.data(), length);
    r.printed[length] = '\0';
}

}  // namespace

#endif
