// Counts every allocation of the test program that includes it, in `allocations`: the global
// operator new replaced, or, under AddressSanitizer (which owns operator new), the sanitizer's
// allocation hook installed. Include it from exactly one source file of an executable.
#ifndef QUAT_TESTS_SUPPORT_ALLOCATION_COUNTER_HPP_INCLUDED
#define QUAT_TESTS_SUPPORT_ALLOCATION_COUNTER_HPP_INCLUDED

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define QUAT_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define QUAT_TEST_ASAN 1
#endif
#endif

namespace {
std::atomic<long> allocations{0};
}  // namespace

#if defined(QUAT_TEST_ASAN)
// AddressSanitizer owns the global operator new (replacing it there mixes the sanitizer's allocator
// with malloc: alloc-dealloc-mismatch), but its allocator calls a hook on every allocation, new and
// malloc alike. The hook API is the sanitizers' public interface (<sanitizer/allocator_interface.h>
// in clang; declared here because g++ 12 does not install that header, though its libasan has it).
// NOLINTNEXTLINE(bugprone-reserved-identifier): the sanitizer runtime's own name.
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*,
                                                                             std::size_t),
                                                         void (*free_hook)(const volatile void*));
namespace {
void count_allocation(const volatile void*, std::size_t) {
    allocations.fetch_add(1, std::memory_order_relaxed);
}
void ignore_free(const volatile void*) {}
[[maybe_unused]] const int hooks_installed =
    __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_free);
}  // namespace
#else
// Replacing the global allocation functions is the standard way to observe every allocation; the
// replacements forward to malloc and free, which valgrind still tracks.
[[gnu::noinline]] void* operator new(std::size_t size) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
// Never inlined: valgrind replaces the out-of-line operator new and delete of this program with its
// own, and a delete inlined as free() would pair its new with malloc's free (g++ 12 also warns
// about that pairing, -Wmismatched-new-delete, once both are inlined into one caller).
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif

#endif  // QUAT_TESTS_SUPPORT_ALLOCATION_COUNTER_HPP_INCLUDED
