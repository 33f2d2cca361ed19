// Fuzz target: progs.dat loading and execution. Seeds: synthetic_progs_seeds() plus the game's
// progs.dat. A program that loads runs its first functions against stub builtins (spawning,
// strings, nested calls, entity fields) under small limits, so hostile code paths are executed,
// not only parsed.
#include <algorithm>
#include <array>
#include <utility>

#include "fuzz_target.h"
#include "support/synth_progs.h"
#include "vm/progs.h"
#include "vm/vm.h"

namespace {

using nq::vm::Builtin;
using nq::vm::Vm;

// Builtin number n does one of four things, picked by n % 4.
template <int N>
void stub(Vm& vm, void*) {
    switch (N % 4) {
        case 0:
            if (vm.num_edicts() < vm.max_edicts()) {
                vm.clear_edict(vm.num_edicts());
                vm.set_num_edicts(vm.num_edicts() + 1);
            }
            vm.return_edict(vm.num_edicts() - 1);
            break;
        case 1:
            vm.return_temp_string(vm.param_string(0));
            break;
        case 2:
            vm.execute(vm.param_int(0));
            break;
        case 3:
            vm.set_field_float(vm.param_edict(0), 0, vm.param_float(1));
            break;
    }
}

template <size_t... I>
constexpr std::array<Builtin, sizeof...(I)> make_builtins(std::index_sequence<I...>) {
    return {Builtin{"stub", &stub<int(I)>}...};
}

constexpr auto kBuiltins = make_builtins(std::make_index_sequence<96>());

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_progs_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto progs = nq::vm::parse_progs({data, size}, "fuzz.dat");
    if (!progs) {
        volatile size_t sink = progs.error().to_string().size();
        (void)sink;
        return 0;
    }
    nq::vm::VmLimits limits;
    limits.max_edicts = 32;
    limits.runaway = 5000;
    limits.runaway_nested = 50000;
    const size_t functions = progs->functions.size();
    Vm vm(std::move(*progs), limits);
    vm.set_builtins(kBuiltins, nullptr);
    vm.set_num_edicts(1);
    int ran = 0;
    for (size_t f = 1; f < functions && ran < 8; ++f) {
        if (vm.progs().functions[f].builtin()) continue;
        ++ran;
        if (!vm.execute(int32_t(f))) {
            volatile size_t sink = vm.error()->to_string().size();
            (void)sink;
            vm.clear_error();
        }
    }
    return 0;
}
