// The replaced global allocation functions behind nq::test::g_allocations (allocation_counter.h).
// They live beside the counter, so any executable that reads it counts every operator new.
#include "support/allocation_counter.h"

#include <cstdlib>
#include <new>

namespace nq::test {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t n) {
    ++nq::test::g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
    ++nq::test::g_allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
// The nothrow forms too (std::stable_sort's buffer, LLVM inside Mesa): their memory comes back
// through the plain operator delete below, so it must come from malloc as well.
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    ++nq::test::g_allocations;
    return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    ++nq::test::g_allocations;
    return std::malloc(n ? n : 1);
}
// GCC 12 inlines these replacements where a `new` expression's pointer is deleted and then
// reports free() on memory from operator new; here both sides are malloc/free by design.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
