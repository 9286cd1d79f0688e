// The widest floating-point type this platform's compiler offers, for the tests' reference values:
// one type per platform, chosen here, so that a test file names `quat::test::wide` rather than
// __float128 (which g++ has on x86-64 but not on AArch64).
//   - long double where it is IEEE binary128 (LDBL_MANT_DIG >= 113: AArch64 Linux, and other
//     targets whose long double is quad);
//   - else __float128 where the compiler has it (g++ and clang++ on x86-64: 113 bits);
//   - else long double as it is (64 bits on x86-64 without __float128, 53 where it is double).
// With 113 bits a product of two doubles is exact. wide_mantissa_digits says which one was chosen.
#pragma once

#include <cfloat>

namespace quat::test {

#if LDBL_MANT_DIG >= 113
using wide = long double;
inline constexpr int wide_mantissa_digits = LDBL_MANT_DIG;
#elif defined(__SIZEOF_FLOAT128__)
__extension__ typedef __float128 wide;
inline constexpr int wide_mantissa_digits = 113;
#else
using wide = long double;
inline constexpr int wide_mantissa_digits = LDBL_MANT_DIG;
#endif

}  // namespace quat::test
