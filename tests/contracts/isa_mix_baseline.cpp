// Built with -march=x86-64 (see CMakeLists.txt): no AVX.
#include "isa_mix_compute.hpp"

#if defined(__AVX__)
#error "this translation unit must be compiled without AVX"
#endif

void isa_mix_baseline(isa_mix_results& results) noexcept { isa_mix_compute(results); }
