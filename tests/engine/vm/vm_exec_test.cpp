// QuakeC execution: a conformance program compiled by fteqcc (tests/qc/conformance) reports
// values whose expected results are written next to each report; hand-assembled programs pin the
// semantics a compiler may hide (raw-bit IF, AND/OR without short-circuit, entity values as byte
// offsets); hostile programs (runaway loops, deep recursion, bad values) stop with an error that
// names the QuakeC call stack, and the VM refuses to run again until the error is cleared.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <memory>
#include <variant>

#include "common/file_io.h"
#include "support/synth_progs.h"
#include "support/test_data.h"
#include "vm/opcodes.h"
#include "vm/vm.h"

namespace nq::vm {
namespace {

using test::SynthProgs;
using Report = std::variant<float, std::string, Vec3f>;

struct Host {
    std::vector<Report> reports;
    uint32_t spawned = 0;
};

Host& host_of(void* h) {
    return *static_cast<Host*>(h);
}

const Builtin kBuiltins[] = {
    {},
    {"report", [](Vm& vm, void* h) { host_of(h).reports.emplace_back(vm.param_float(0)); }},
    {"spawn",
     [](Vm& vm, void* h) {
         const uint32_t e = vm.num_edicts();
         if (e >= vm.max_edicts()) vm.fail("no free edicts");
         vm.set_num_edicts(e + 1);
         vm.clear_edict(e);
         ++host_of(h).spawned;
         vm.return_edict(e);
     }},
    {"report_string",
     [](Vm& vm, void* h) { host_of(h).reports.emplace_back(std::string(vm.param_string(0))); }},
    {"report_vector", [](Vm& vm, void* h) { host_of(h).reports.emplace_back(vm.param_vector(0)); }},
    {"ftos",
     [](Vm& vm, void*) {
         const float f = vm.param_float(0);
         char text[64];
         if (f == std::floor(f)) {
             std::snprintf(text, sizeof text, "%d", int(f));
         } else {
             std::snprintf(text, sizeof text, "%5.1f", double(f));
         }
         vm.return_temp_string(text);
     }},
    {"callback",
     [](Vm& vm, void*) {
         // Nested execution, as touch functions run from inside walkmove.
         vm.execute(vm.param_int(0));
     }},
    {"error", [](Vm& vm, void*) { vm.fail("error: " + std::string(vm.param_string(0))); }},
};

std::unique_ptr<Vm> load(std::vector<uint8_t> bytes, Host& host, VmLimits limits = {}) {
    auto progs = parse_progs(bytes, "test.dat");
    if (!progs) {
        ADD_FAILURE() << progs.error().to_string();
        return nullptr;
    }
    auto vm = std::make_unique<Vm>(std::move(*progs), limits);
    vm->set_builtins(kBuiltins, &host);
    vm->set_num_edicts(1);  // world
    return vm;
}

std::unique_ptr<Vm> load_conformance(Host& host) {
    const std::string path = std::string(NQ_QC_DIR) + "/conformance.dat";
    auto bytes = read_file(path);
    if (!bytes) {
        ADD_FAILURE() << "missing " << path;
        return nullptr;
    }
    return load(std::move(*bytes), host);
}

bool run(Vm& vm, std::string_view function) {
    const int32_t f = vm.progs().find_function(function);
    EXPECT_GT(f, 0) << function;
    return vm.execute(f);
}

TEST(VmExec, ConformanceProgramReportsWhatQuakeCComputes) {
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    ASSERT_TRUE(run(*vm, "main")) << vm->error()->to_string();
    const float next_think = 10.0f + 0.1f;  // time + 0.1 in float arithmetic, as OP_STATE does
    const std::vector<Report> expected = {
        // arithmetic and comparisons
        9.f, 5.f, 14.f, 3.5f, 3.f, 15.f, 1.f, 0.f, 1.f, 0.f, 1.f, 0.f, 0.f, 1.f,
        // vectors
        Vec3f{5, 7, 9}, Vec3f{3, 3, 3}, 32.f, Vec3f{2, 4, 6}, Vec3f{8, 10, 12}, Vec3f{-1, -2, -3},
        1.f, 1.f, 0.f, 1.f, 5.f,
        // calls and loops
        720.f, 123.f, 4950.f, -5.f,
        // strings
        1.f, 1.f, 1.f, 0.f, std::string("12"), std::string("hello"),
        // entities
        42.f, Vec3f{10, 20, 30}, std::string("ogre"), 7.f, 0.f, 1.f, 0.f, 1.f, 31.f,
        // OP_STATE and function values
        5.f, next_think, 99.f, 1.f,
        // nested execution
        40.f, 41.f, 42.f, -1.f};
    ASSERT_EQ(host.reports.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(host.reports[i], expected[i]) << "report " << i;
    }
    EXPECT_EQ(host.spawned, 3u);
}

TEST(VmExec, EntityValuesAreByteOffsets) {
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    ASSERT_TRUE(run(*vm, "test_state"));
    const Def* self = vm->progs().find_global("self");
    ASSERT_NE(self, nullptr);
    // The one spawned entity is edict 1: its value is one entity's size in bytes.
    EXPECT_EQ(vm->global_word(self->offset), vm->entity_fields() * 4);
    EXPECT_EQ(vm->edict_of(vm->entity_fields() * 4), 1u);
    EXPECT_FALSE(vm->edict_of(vm->entity_fields() * 4 + 4));
    const Def* frame = vm->progs().find_field("frame");
    EXPECT_EQ(vm->field_float(1, frame->offset), 5.0f);
}

TEST(VmExec, RunawayLoopStopsAfterQuakeSpasmsStatementLimit) {
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    const uint64_t before = vm->statements_run();
    EXPECT_FALSE(run(*vm, "runaway"));
    ASSERT_TRUE(vm->error());
    const std::string text = vm->error()->to_string();
    EXPECT_NE(text.find("runaway loop"), std::string::npos) << text;
    EXPECT_NE(text.find("(in runaway)"), std::string::npos) << text;
    EXPECT_EQ(vm->statements_run() - before, 16777216u);  // QuakeSpasm's 0x1000000
    // Refuses to run until the error is cleared.
    EXPECT_FALSE(run(*vm, "test_arith"));
    EXPECT_TRUE(host.reports.empty());
    vm->clear_error();
    EXPECT_TRUE(run(*vm, "test_arith"));
    EXPECT_EQ(host.reports.size(), 14u);
}

TEST(VmExec, ALoopPastQuakesOldLimitRunsToItsEnd) {
    // Quake's 100,000 statements a call stopped real mods; QuakeSpasm's limit lets this run.
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    const uint64_t before = vm->statements_run();
    ASSERT_TRUE(run(*vm, "long_loop")) << vm->error()->to_string();
    EXPECT_GT(vm->statements_run() - before, 1000000u);
    ASSERT_EQ(host.reports.size(), 1u);
    EXPECT_EQ(host.reports[0], Report(250000.f));
}

TEST(VmExec, InfiniteRecursionIsAStackOverflow) {
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    EXPECT_FALSE(run(*vm, "deep"));
    const std::string text = vm->error()->to_string();
    EXPECT_NE(text.find("stack overflow"), std::string::npos) << text;
    EXPECT_EQ(vm->error()->stack.size(), 64u);  // every frame is `deep`
    EXPECT_EQ(vm->error()->stack.front(), "deep");
}

TEST(VmExec, NullFunctionWorldWriteAndBuiltinErrorsNameTheFunction) {
    for (const auto& [function, message] :
         {std::pair<const char*, const char*>{"null_call", "null function"},
          {"world_write", "assignment to world"},
          {"bad_builtin", "error: from QuakeC"}}) {
        Host host;
        auto vm = load_conformance(host);
        ASSERT_TRUE(vm);
        EXPECT_FALSE(run(*vm, function));
        ASSERT_TRUE(vm->error());
        EXPECT_NE(vm->error()->message.find(message), std::string::npos)
            << vm->error()->to_string();
        EXPECT_EQ(vm->error()->stack.front(), function);
    }
}

TEST(VmExec, ErrorInsideANestedCallStopsTheOuterProgram) {
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    EXPECT_FALSE(run(*vm, "nested_error"));
    // The statement after the builtin never ran, and the stack shows both programs.
    EXPECT_TRUE(host.reports.empty());
    ASSERT_TRUE(vm->error());
    const std::vector<std::string>& stack = vm->error()->stack;
    ASSERT_EQ(stack.size(), 2u) << vm->error()->to_string();
    EXPECT_EQ(stack[0], "null_call");
    EXPECT_EQ(stack[1], "nested_error");
    vm->clear_error();
    EXPECT_TRUE(run(*vm, "test_nested"));
}

TEST(VmExec, WorldIsWritableWhileSpawning) {
    Host host;
    auto vm = load_conformance(host);
    ASSERT_TRUE(vm);
    vm->set_world_writable(true);
    EXPECT_TRUE(run(*vm, "world_write"));
    EXPECT_EQ(vm->field_float(0, vm->progs().find_field("health")->offset), 1.0f);
}

// ---- hand-assembled programs: semantics a compiler may hide

struct Assembled {
    SynthProgs p;
    uint16_t report_fn = 0;
    Assembled() { report_fn = p.global_function(p.builtin("report", 1)); }
    void report(uint16_t global) {
        p.op(kOpStoreF, global, uint16_t(kOfsParm0));
        p.op(kOpCall1, report_fn);
    }
};

TEST(VmExec, IfTestsRawBitsSoNegativeZeroIsTrue) {
    Assembled a;
    const uint16_t neg_zero = a.p.global(-0.0f), yes = a.p.global(1), no = a.p.global(0);
    a.p.function("main");
    a.p.op(kOpIf, neg_zero, 3);  // taken: -0.0 is not all zero bits
    a.report(no);
    a.report(yes);
    a.p.op(kOpIfNot, neg_zero, 2);  // not taken
    a.report(yes);
    a.p.op(kOpNotF, neg_zero, 0, neg_zero);  // but !-0.0 is 1, a float comparison
    a.report(neg_zero);
    a.p.op(kOpDone);
    Host host;
    auto vm = load(a.p.bytes(), host);
    ASSERT_TRUE(vm);
    ASSERT_TRUE(vm->execute(2)) << vm->error()->to_string();
    const std::vector<Report> expected = {1.f, 1.f, 1.f};
    EXPECT_EQ(host.reports, expected);
}

TEST(VmExec, AndOrCombineFloatsWithoutShortCircuit) {
    Assembled a;
    const uint16_t zero = a.p.global(0), half = a.p.global(0.5f), r = a.p.global();
    const uint16_t big = a.p.global(1e30f), nan = a.p.global(std::nanf(""));
    a.p.function("main");
    for (auto [x, y, code] : {std::tuple{zero, half, kOpAnd},
                              {half, half, kOpAnd},
                              {zero, half, kOpOr},
                              {zero, zero, kOpOr}}) {
        a.p.op(code, x, y, r);
        a.report(r);
    }
    a.p.op(kOpBitAnd, big, half, r);  // (int)1e30 saturates instead of being undefined
    a.report(r);
    a.p.op(kOpBitOr, nan, half, r);
    a.report(r);
    a.p.op(kOpDone);
    Host host;
    auto vm = load(a.p.bytes(), host);
    ASSERT_TRUE(vm);
    ASSERT_TRUE(vm->execute(2)) << vm->error()->to_string();
    const std::vector<Report> expected = {0.f, 1.f, 1.f, 0.f, 0.f, 0.f};
    EXPECT_EQ(host.reports, expected);
}

TEST(VmExec, BadEntityFieldAndPointerValuesStopTheProgram) {
    struct Case {
        const char* what;
        uint32_t entity, field;
        uint16_t op;
    };
    for (const Case& c : {Case{"bad entity value", 3, 0, kOpLoadF},        // not a multiple
                          Case{"bad entity value", 8 * 100, 0, kOpLoadF},  // not spawned
                          Case{"bad field offset", 0, 2, kOpLoadF},
                          Case{"bad field offset", 0, 0, kOpLoadV},  // 3 words from a 2-word entity
                          Case{"bad pointer", 0, 1, kOpStorePF}}) {
        SynthProgs p;
        p.field("a", uint16_t(DefType::float_));
        p.field("b", uint16_t(DefType::float_));
        const uint16_t e = p.global_word(c.entity), f = p.global_word(c.field),
                       out = p.global_vector(0, 0, 0);
        const uint16_t pointer = p.global_word(1000 * 4);
        p.function("main");
        if (c.op == kOpStorePF) {
            p.op(kOpStorePF, out, pointer);
        } else {
            p.op(c.op, e, f, out);
        }
        p.op(kOpDone);
        Host host;
        auto vm = load(p.bytes(), host);
        ASSERT_TRUE(vm);
        EXPECT_FALSE(vm->execute(1));
        ASSERT_TRUE(vm->error());
        EXPECT_NE(vm->error()->message.find(c.what), std::string::npos) << vm->error()->to_string();
    }
}

TEST(VmExec, RunningOffTheEndOfTheCodeIsAnError) {
    SynthProgs p;
    const uint16_t x = p.global(1);
    p.function("main");
    p.op(kOpAddF, x, x, x);  // no RETURN or DONE after it
    Host host;
    auto vm = load(p.bytes(), host);
    ASSERT_TRUE(vm);
    EXPECT_FALSE(vm->execute(1));
    EXPECT_NE(vm->error()->message.find("ran off the end"), std::string::npos);
}

TEST(VmExec, UnknownBuiltinIsAnError) {
    SynthProgs p;
    const uint16_t fn = p.global_function(p.builtin("missing", 500));
    p.function("main");
    p.op(kOpCall0, fn);
    p.op(kOpDone);
    Host host;
    auto vm = load(p.bytes(), host);
    ASSERT_TRUE(vm);
    EXPECT_FALSE(vm->execute(2));
    EXPECT_NE(vm->error()->message.find("unknown builtin #500 (missing)"), std::string::npos)
        << vm->error()->to_string();
}

TEST(VmExec, TemporaryStringsAreARingOfFixedBuffers) {
    SynthProgs p;
    auto progs = parse_progs(p.bytes(), "s.dat");
    ASSERT_TRUE(progs);
    Vm vm(std::move(*progs));
    StringTable& strings = vm.strings();
    const int32_t first = strings.make_temp("first");
    for (int i = 1; i < StringTable::kTempStrings; ++i) strings.make_temp("other");
    EXPECT_EQ(vm.string_or_empty(first), "first");  // 15 later temps leave it alone
    strings.make_temp("reused");
    EXPECT_EQ(vm.string_or_empty(first), "reused");  // the 16th reuses its buffer
    const int32_t kept = strings.make_level("kept");
    EXPECT_EQ(vm.string_or_empty(kept), "kept");
    EXPECT_FALSE(strings.get(kept - 1));
    EXPECT_EQ(vm.string_or_empty(int32_t(std::string(2000, 'x').size())), "");
    EXPECT_EQ(strings.get(strings.make_temp(std::string(5000, 'y')))->size(),
              StringTable::kTempLength - 1);
}

}  // namespace
}  // namespace nq::vm
