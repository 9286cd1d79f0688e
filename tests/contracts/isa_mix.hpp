// Two translation units of quat_isa_mix compile the batch rotation with different -m flags.
#ifndef QUAT_TESTS_ISA_MIX_HPP
#define QUAT_TESTS_ISA_MIX_HPP

#include <cstddef>

#include <quat/batch.hpp>

using rotate_function = void (*)(const quat::rotation_matrix<float>&, const quat::vec3<float>*,
                                 quat::vec3<float>*, std::size_t) noexcept;

/// quat::rotate<float> (pointer + count) as a translation unit with the default flags sees it.
rotate_function baseline_rotate();
/// The same function as a translation unit compiled with -mavx512f -mavx2 -mfma sees it.
rotate_function avx512_rotate();

#endif
