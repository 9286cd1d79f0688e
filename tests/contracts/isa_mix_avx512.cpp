// Built with -march=skylake-avx512 (see CMakeLists.txt).
#include "isa_mix_compute.hpp"

#if !defined(__AVX512F__)
#error "this translation unit must be compiled with -march=skylake-avx512"
#endif

void isa_mix_avx512(isa_mix_results& results) noexcept { isa_mix_compute(results); }
