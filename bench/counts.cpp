// `quat_bench --counts`: the thesis's Tables 3.1 and 3.2 beside what quat's own templates do,
// counted by running them on quat::counted<double>.
#include <cstdio>

#include "common.hpp"
#include "count_cases.hpp"
#include "counted.hpp"

namespace bench {
namespace {

struct thesis_row {
    long add, mul, div, trig;
};

void print_row(const char* what, const quat::operation_counts& c) {
    std::printf("  %-52s %5lld %5lld %5lld %5lld %5lld\n", what, static_cast<long long>(c.add),
                static_cast<long long>(c.mul), static_cast<long long>(c.div),
                static_cast<long long>(c.sqrt), static_cast<long long>(c.trig));
}
void print_thesis(const char* what, thesis_row t) {
    std::printf("  %-52s %5ld %5ld %5ld %5s %5ld\n", what, t.add, t.mul, t.div, "-", t.trig);
}
void header(const char* title) {
    std::printf("\n%s\n  %-52s %5s %5s %5s %5s %5s\n", title, "", "add", "mul", "div", "sqrt",
                "trig");
}

}  // namespace

int print_counts() {
    using namespace count_cases;
    std::printf(
        "Operation counts of quat's templates, run on quat::counted<double> (bench/counted.hpp).\n"
        "add = additions and subtractions; negations and comparisons are free; the thesis (Kivi "
        "2019,\n"
        "MATLAB) did not count square roots.\n");

    header("Table 3.1: build the rotation, then rotate one point once");
    print_thesis("matrix from Euler angles (thesis)", {10, 25, 0, 6});
    print_row("matrix from Euler angles (quat)", matrix_from_euler());
    print_thesis("quaternion from Euler angles (thesis)", {25, 42, 0, 6});
    print_row("quaternion from Euler angles (quat)", quaternion_from_euler());
    print_row("quaternion from Euler angles, naive q p q* (quat)", quaternion_from_euler_naive());
    print_thesis("matrix from axis + angle (thesis)", {16, 30, 0, 2});
    print_row("matrix from axis + angle (quat)", matrix_from_axis_angle());
    print_thesis("quaternion from axis + angle (thesis)", {21, 31, 0, 2});
    print_row("quaternion from axis + angle (quat)", quaternion_from_axis_angle());
    std::printf(
        "  why they differ:\n"
        "  - matrix from Euler: to_matrix(euler) serves all 24 conventions: it starts from the "
        "first\n"
        "    axis rotation and turns two columns for each of the other two (12 mul, 6 add each); "
        "the\n"
        "    thesis multiplied out the z-y-x product by hand and exploited its zeros.\n"
        "  - quaternion from Euler: to_quaternion(euler) is a closed-form product of the three\n"
        "    half-angle quaternions (no multiplications by zero, half angles by * 0.5), and "
        "rotate(q, v)\n"
        "    is M v with M built from q and its norm correction (25 mul, 23 add, 16 and 17 of "
        "them on q\n"
        "    alone) instead of the thesis's two full Hamilton products q p q* (32 mul, 24 add, "
        "the naive\n"
        "    row); v + w t + u x t would be 18 mul, 12 add but keeps |v| only to 5.4 eps "
        "for q from normalize.\n"
        "  - quaternion from axis + angle: the half angle costs one multiplication that the "
        "thesis's\n"
        "    (wrong) full-angle formula 2.26 skipped; the rotation itself is again rotate(q, "
        "v).\n"
        "  - matrix from axis + angle: Rodrigues' formula with the products shared (xk, xs, "
        "...).\n");

    header("Rotating a point (rotation already built)");
    print_row("quaternion, naive q (0, v) q*: two Hamilton products", rotate_naive());
    print_row("quaternion, rotate(q, v): M v, M from q and |q|", rotate_quaternion());
    print_row("matrix, rotate(m, v) = M v", rotate_matrix());
    print_row("quaternion batch, per point over 1024 points", rotate_batch_per_point(1024));

    header("Composing two rotations");
    print_row("quaternion product a * b", compose_quaternions());
    print_row("matrix product A * B", compose_matrices());
    print_row("to_matrix(q) (to apply a composed quaternion as M v)", quaternion_to_matrix());

    std::printf("\nTable 3.2: numbers stored per rotation\n  %-32s %7s %14s %14s\n", "", "thesis",
                "quat float", "quat double");
    const struct {
        const char* name;
        int thesis;
        std::size_t f, d;
    } storage[] = {
        {"Euler angles", 3, sizeof(quat::euler<float>), sizeof(quat::euler<double>)},
        {"axis + angle", 4, sizeof(quat::axis_angle<float>), sizeof(quat::axis_angle<double>)},
        {"rotation matrix", 9, sizeof(quat::rotation_matrix<float>),
         sizeof(quat::rotation_matrix<double>)},
        {"quaternion", 4, sizeof(quat::quaternion<float>), sizeof(quat::quaternion<double>)},
    };
    for (const auto& s : storage)
        std::printf("  %-32s %7d %5zu (%2zu B) %5zu (%2zu B)\n", s.name, s.thesis,
                    s.f / sizeof(float), s.f, s.d / sizeof(double), s.d);
    std::printf(
        "  The types hold exactly the thesis's numbers: no padding, no cached values; the Euler "
        "type\n"
        "  carries its axis sequence and frame in the type, not in memory.\n");

    header("Rigid motion: build from rotation + translation, then move one point once");
    print_row("4x4 matrix: build, to_matrix(q) + t column", rigid_build_matrix());
    print_row("4x4 matrix: point, full 4x4 x (x, y, z, 1)", rigid_point_matrix_full());
    print_row("4x4 matrix: point, transform(m, p)", rigid_point_matrix());
    print_row("4x4 matrix: total, full 4x4 product", rigid_once_matrix_full());
    print_row("4x4 matrix: total, transform(m, p)", rigid_once_matrix());
    print_row("dual quaternion: build, to_dual_quaternion(q, t)", rigid_build_dual());
    print_row("dual quaternion: point, transform(dq, p)", rigid_point_dual());
    print_row("dual quaternion: total", rigid_once_dual());
    print_row("(q, t) pair: build, nothing to compute", rigid_build_pair());
    print_row("(q, t) pair: point, rotate(q, p) + t", rigid_point_pair());
    print_row("(q, t) pair: total", rigid_once_pair());

    header("Rigid motion: per additional point (motion already built)");
    print_row("4x4 matrix, full 4x4 x (x, y, z, 1)", rigid_point_matrix_full());
    print_row("4x4 matrix, transform(m, p): last row not read", rigid_point_matrix());
    print_row("dual quaternion, transform(dq, p)", rigid_point_dual());
    print_row("dual quaternion batch, per point over 1024 points",
              rigid_batch_dual_per_point(1024));
    print_row("(q, t) pair, rotate(q, p) + t", rigid_point_pair());
    std::printf(
        "  why they differ:\n"
        "  - 4x4 build: to_matrix(q) (9 mul, 15 add); t and the last row (0, 0, 0, 1) are copied.\n"
        "  - full 4x4 x (x, y, z, 1): M p + t (9 mul, 9 add) plus t times the known 1 (3 mul) "
        "and the\n"
        "    last row, 0 x + 0 y + 0 z + 1 1 = 1 (4 mul, 3 add); the thesis's R(M u^) (definition "
        "3.1)\n"
        "    would then divide by that 1 as well (3 div). transform(m, p) skips all of it.\n"
        "  - dual quaternion: to_dual_quaternion(q, t) is (0, t/2) q (3 + 16 mul, 12 add); "
        "transform(dq, p)\n"
        "    is rotate(q, p) (25 mul, 23 add) plus t, the vector part of 2 dual real*, read back "
        "on\n"
        "    every call (12 mul, 12 add), plus 3 add. The batch transform converts once with\n"
        "    to_homogeneous and then costs what the matrix does per point.\n"
        "  - (q, t) pair: nothing to build; each point is rotate(q, p) + t.\n");

    header("Rigid motion: composing two");
    print_row("4x4 matrix product A * B, full", rigid_compose_matrix_full());
    print_row("4x4 product, last row (0,0,0,1) known (3x4 affine)", rigid_compose_affine());
    print_row("dual quaternion product a * b", rigid_compose_dual());
    print_row("(q, t) pair: (q_a q_b, rotate(q_a, t_b) + t_a)", rigid_compose_pair());
    print_row("to_homogeneous(dq) (to move points as R p + t)", dual_to_homogeneous());
    std::printf(
        "  why they differ:\n"
        "  - 4x4 full: 16 dot products of length 4; over the 3x4 product, rows 0-2 spend 12 mul, "
        "9 add on\n"
        "    B's last row (0, 0, 0, 1), and the last row, known to be (0, 0, 0, 1), costs 16 mul, "
        "12 add.\n"
        "  - 3x4 affine: R_a R_b (27 mul, 18 add), R_a t_b (9 mul, 6 add), + t_a (3 add).\n"
        "  - dual quaternion: three Hamilton products (16 mul, 12 add each) and one quaternion "
        "sum.\n"
        "  - pair: one Hamilton product, rotate(q_a, t_b) (25 mul, 23 add) and 3 add; the "
        "accurate\n"
        "    rotate(q, v) is what puts it above the 3x4 affine product.\n");

    std::printf("\nTable 3.2 for rigid motions: numbers stored per motion\n  %-32s %7s %14s %14s\n",
                "", "scalars", "quat float", "quat double");
    const struct {
        const char* name;
        int scalars;
        std::size_t f, d;  // sizeof of quat's type, 0 where quat has none
    } rigid_storage[] = {
        {"4x4 homogeneous matrix", 16, sizeof(quat::homogeneous_matrix<float>),
         sizeof(quat::homogeneous_matrix<double>)},
        {"3x4 affine (rotation + column)", 12, 0, 0},
        {"dual quaternion", 8, sizeof(quat::dual_quaternion<float>),
         sizeof(quat::dual_quaternion<double>)},
        {"quaternion + translation", 7, sizeof(quat::quaternion<float>) + sizeof(quat::vec3<float>),
         sizeof(quat::quaternion<double>) + sizeof(quat::vec3<double>)},
    };
    for (const auto& s : rigid_storage) {
        if (s.f == 0) std::printf("  %-32s %7d %14s %14s\n", s.name, s.scalars, "-", "-");
        else
            std::printf("  %-32s %7d %6zu (%3zu B) %6zu (%3zu B)\n", s.name, s.scalars,
                        s.f / sizeof(float), s.f, s.d / sizeof(double), s.d);
    }
    std::printf(
        "  quat has no 3x4 type (homogeneous_matrix stores the last row); the pair is a "
        "quaternion and\n"
        "  a vec3 side by side.\n");
    return 0;
}

}  // namespace bench
