// Built with -march=x86-64-v3 (see CMakeLists.txt): AVX2 and FMA.
#include "isa_mix_compute.hpp"

#if !defined(__AVX2__) || !defined(__FMA__) || defined(__AVX512F__)
#error "this translation unit must be compiled with -march=x86-64-v3"
#endif

void isa_mix_avx2(isa_mix_results& results) noexcept { isa_mix_compute(results); }
