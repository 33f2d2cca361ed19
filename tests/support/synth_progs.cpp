#include "support/synth_progs.h"

#include <bit>

#include "support/synth_mdl.h"
#include "vm/opcodes.h"
#include "vm/progs.h"

namespace nq::test {

using namespace nq::vm;

SynthProgs::SynthProgs() {
    strings.push_back('\0');
    functions.push_back({});
    globals.assign(kReservedGlobals, 0);
}

int32_t SynthProgs::string(std::string_view s) {
    const int32_t index = int32_t(strings.size());
    strings.append(s);
    strings.push_back('\0');
    return index;
}

uint16_t SynthProgs::global_word(uint32_t word) {
    globals.push_back(word);
    return uint16_t(globals.size() - 1);
}

uint16_t SynthProgs::global(float value) {
    return global_word(std::bit_cast<uint32_t>(value));
}

uint16_t SynthProgs::global_vector(float x, float y, float z) {
    const uint16_t at = global(x);
    global(y);
    global(z);
    return at;
}

uint16_t SynthProgs::global_string(std::string_view s) {
    return global_word(uint32_t(string(s)));
}

uint16_t SynthProgs::global_function(int32_t function) {
    return global_word(uint32_t(function));
}

void SynthProgs::name_global(std::string_view name, uint16_t type, uint16_t offset) {
    global_defs.push_back({type, offset, string(name)});
}

uint16_t SynthProgs::field(std::string_view name, uint16_t type, uint16_t words) {
    const uint16_t offset = uint16_t(entity_fields);
    field_defs.push_back({type, offset, string(name)});
    entity_fields += words;
    return offset;
}

int32_t SynthProgs::function(std::string_view name, int32_t num_parms, int32_t locals,
                             uint16_t parm_start, std::array<uint8_t, 8> parm_size) {
    Function f;
    f.first_statement = here();
    f.parm_start = parm_start;
    f.locals = locals;
    f.name = string(name);
    f.file = string("synth.qc");
    f.num_parms = num_parms;
    f.parm_size = parm_size;
    functions.push_back(f);
    return int32_t(functions.size() - 1);
}

int32_t SynthProgs::builtin(std::string_view name, int32_t number) {
    Function f;
    f.first_statement = -number;
    f.name = string(name);
    f.file = string("synth.qc");
    functions.push_back(f);
    return int32_t(functions.size() - 1);
}

void SynthProgs::op(uint16_t code, uint16_t a, uint16_t b, uint16_t c) {
    statements.push_back({code, a, b, c});
}

std::vector<uint8_t> SynthProgs::bytes() const {
    const int32_t ofs_statements = int32_t(kProgsHeaderBytes);
    const int32_t ofs_global_defs = ofs_statements + int32_t(statements.size() * 8);
    const int32_t ofs_field_defs = ofs_global_defs + int32_t(global_defs.size() * 8);
    const int32_t ofs_funcs = ofs_field_defs + int32_t(field_defs.size() * 8);
    const int32_t ofs_strings = ofs_funcs + int32_t(functions.size() * 36);
    const int32_t ofs_globals = ofs_strings + int32_t(strings.size());

    LeWriter w;
    w.i32(version);
    w.i32(crc);
    w.i32(ofs_statements);
    w.i32(num_statements.value_or(int32_t(statements.size())));
    w.i32(ofs_global_defs);
    w.i32(int32_t(global_defs.size()));
    w.i32(ofs_field_defs);
    w.i32(int32_t(field_defs.size()));
    w.i32(ofs_functions.value_or(ofs_funcs));
    w.i32(int32_t(functions.size()));
    w.i32(ofs_strings);
    w.i32(num_strings.value_or(int32_t(strings.size())));
    w.i32(ofs_globals);
    w.i32(num_globals.value_or(int32_t(globals.size())));
    w.i32(int32_t(entity_fields));
    auto u16 = [&](uint16_t v) {
        w.u8(uint8_t(v & 0xff));
        w.u8(uint8_t(v >> 8));
    };
    for (const Statement& s : statements) {
        for (uint16_t v : {s.op, s.a, s.b, s.c}) u16(v);
    }
    for (const auto* list : {&global_defs, &field_defs}) {
        for (const Def& d : *list) {
            u16(d.type);
            u16(d.offset);
            w.i32(d.name);
        }
    }
    for (const Function& f : functions) {
        for (int32_t v :
             {f.first_statement, f.parm_start, f.locals, f.profile, f.name, f.file, f.num_parms}) {
            w.i32(v);
        }
        for (uint8_t size : f.parm_size) w.u8(size);
    }
    w.text(strings);
    for (uint32_t g : globals) w.u32(g);
    return w.take();
}

std::vector<SeedFile> synthetic_progs_seeds() {
    std::vector<SeedFile> seeds;
    {  // sum = 0; for (i = 10; i; i = i - 1) sum = sum + i; report(sum)
        SynthProgs p;
        const uint16_t sum = p.global(0), i = p.global(10), one = p.global(1);
        const int32_t report = p.builtin("report", 1);
        const uint16_t report_fn = p.global_function(report);
        p.function("main");
        p.op(kOpIfNot, i, 4);
        p.op(kOpAddF, sum, i, sum);
        p.op(kOpSubF, i, one, i);
        p.op(kOpGoto, uint16_t(-3));
        p.op(kOpStoreF, sum, kOfsParm0);
        p.op(kOpCall1, report_fn);
        p.op(kOpDone);
        seeds.push_back({"loop.dat", p.bytes()});
    }
    {  // an entity with a vector field, STATE, and a recursive call
        SynthProgs p;
        const uint16_t self = p.global_word(0), time = p.global(1);
        p.name_global("self", uint16_t(DefType::entity), self);
        p.name_global("time", uint16_t(DefType::float_), time);
        const uint16_t origin = p.field("origin", uint16_t(DefType::vector), 3);
        const uint16_t nextthink = p.field("nextthink", uint16_t(DefType::float_));
        const uint16_t frame = p.field("frame", uint16_t(DefType::float_));
        const uint16_t think = p.field("think", uint16_t(DefType::function));
        (void)nextthink;
        (void)frame;
        (void)think;
        const uint16_t origin_field = p.global_word(origin);
        const uint16_t v = p.global_vector(1, 2, 3), pointer = p.global(),
                       back = p.global_vector(0, 0, 0);
        const uint16_t frame_no = p.global(7);
        const int32_t spawn = p.builtin("spawn", 2);
        const uint16_t spawn_fn = p.global_function(spawn);
        const int32_t main = p.function("main");
        const uint16_t main_fn = p.global_function(main);
        p.op(kOpCall0, spawn_fn);
        p.op(kOpStoreEnt, kOfsReturn, self);
        p.op(kOpAddress, self, origin_field, pointer);
        p.op(kOpStorePV, v, pointer);
        p.op(kOpLoadV, self, origin_field, back);
        p.op(kOpState, frame_no, main_fn);
        p.op(kOpMulV, v, back, back);
        p.op(kOpReturn, back);
        seeds.push_back({"entity.dat", p.bytes()});
    }
    return seeds;
}

}  // namespace nq::test
