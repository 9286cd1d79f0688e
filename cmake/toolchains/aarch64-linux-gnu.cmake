# Cross-building quat's unit tests for AArch64 Linux with Debian's g++-aarch64-linux-gnu, and running
# them under qemu-user (Debian qemu-user): CTest prefixes each test command with the emulator.
#   cmake --preset ci-aarch64   (or -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/aarch64-linux-gnu.cmake)
# Catch2, Eigen and GLM are header-only and used from the host's /usr/include; nothing from the
# host is linked. libceres (tests/interop) is not available for AArch64 and is not built.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

# The AArch64 run-time (loader, libc, libstdc++) is in /usr/aarch64-linux-gnu on Debian.
set(QUAT_AARCH64_SYSROOT "/usr/aarch64-linux-gnu" CACHE PATH "AArch64 libraries for qemu-aarch64 -L")
set(CMAKE_CROSSCOMPILING_EMULATOR "qemu-aarch64;-L;${QUAT_AARCH64_SYSROOT}")

# The preset ci-aarch64 adds -ffp-contract=off: g++ contracts a * b + c into fma by default on
# AArch64, and with that, tests that check documented bit-for-bit equalities fail under qemu
# (measured 2026-11-27, g++ 12.2: test_align "rotation_between of exactly parallel ... vectors"
# gets nonzero x/y/z for a and a * k; test_so3 hat * b != cross and log/minus Jacobians != their
# right_jacobian_inverse; test_se3 exp Jacobian != right_jacobian; the keyframe-path rules'
# endpoint equalities; test_readme_example roll == 0). With contraction off they pass.
