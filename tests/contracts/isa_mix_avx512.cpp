// Compiled with -mavx512f -mavx2 -mfma (see CMakeLists.txt).
#include "isa_mix.hpp"

#if !defined(__AVX512F__)
#error "this translation unit must be compiled with -mavx512f"
#endif

rotate_function avx512_rotate() { return &quat::rotate<float>; }
