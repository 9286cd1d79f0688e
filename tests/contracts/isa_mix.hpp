// The interface between quat_isa_mix's translation units: plain arrays only, so that the units
// share no inline code but quat's (a std::vector here would bring its own, which the linker
// also merges across -m flags, and quat cannot key that).
#ifndef QUAT_TESTS_ISA_MIX_HPP
#define QUAT_TESTS_ISA_MIX_HPP

#include <cstddef>

/// What each unit computes with quat, as plain numbers.
struct isa_mix_results {
    using any_function = void (*)();
    any_function to_matrix;     // &quat::to_matrix<double> (scalar) as this unit sees it
    any_function batch_rotate;  // &quat::rotate<float> (pointer + count) as this unit sees it
    static constexpr std::size_t samples = 16;
    double rotated[samples][3];        // batch rotate, float, beyond 16 MiB (the streaming branch)
    double rotated_soa[samples][3];    // struct-of-arrays batch rotate, float
    double transformed[samples][3];    // rigid batch transform, double
    double rotated_each[samples][3];   // rotate_each, float
    double matrix[9];                  // scalar to_matrix, double
    double slerped[4];                 // scalar slerp, float
    double slerped_batch[samples][4];  // batch slerp, float
    double between[4];                 // rotation_between, double (difference_of_products)
    double looking[4];                 // look_rotation, double
    double propagated[6][6];           // J C J^T of matrix<double, 6, 6> (zero, identity, (i, j))
    char printed[1024];                // operator<< (io.hpp) of a quaternion and that matrix
};

/// The same computation in a unit built with the compiler's default flags (-march=x86-64), ...
void isa_mix_baseline(isa_mix_results& results) noexcept;
/// ... with -march=x86-64-v3 (AVX2 and FMA), ...
void isa_mix_avx2(isa_mix_results& results) noexcept;
/// ... and with -march=skylake-avx512.
void isa_mix_avx512(isa_mix_results& results) noexcept;

#endif
