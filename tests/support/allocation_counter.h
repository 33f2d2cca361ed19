// Counts every global operator new of a test executable, to check that per-frame code allocates
// nothing: read nq::test::g_allocations before and after the code. The replacement allocation
// functions live in allocation_counter.cpp (one definition per executable); using the counter
// links them in.
#pragma once

#include <atomic>

namespace nq::test {
extern std::atomic<long> g_allocations;
}
