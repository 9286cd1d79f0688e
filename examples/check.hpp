// Self-checks for quat's examples: each example states what its picture shows and exits non-zero
// (failing its CTest test) if the library does not do it.
#pragma once

#include <cstdio>

namespace example {

/// Counts failed expectations; main returns failures() != 0.
inline int& failures() {
    static int count = 0;
    return count;
}

/// Prints "ok" or "FAILED" beside the claim.
inline void expect(bool holds, const char* claim) {
    std::printf("  [%s] %s\n", holds ? "ok" : "FAILED", claim);
    if (!holds) ++failures();
}

}  // namespace example
