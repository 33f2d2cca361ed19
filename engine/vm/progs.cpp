#include "vm/progs.h"

#include <algorithm>
#include <cstring>

#include "common/byte_reader.h"
#include "vm/opcodes.h"

namespace nq::vm {

namespace {

constexpr size_t kStatementBytes = 8, kDefBytes = 8, kFunctionBytes = 36;
// Limits far above any real progs (Quake's biggest mods stay under a million of each); they keep
// a lying count from asking for gigabytes.
constexpr int32_t kMaxEntityFields = 1 << 16;

ProgsHeader read_header(ByteReader& r) {
    ProgsHeader h;
    h.version = r.i32();
    h.crc = r.i32();
    for (int32_t* field :
         {&h.ofs_statements, &h.num_statements, &h.ofs_global_defs, &h.num_global_defs,
          &h.ofs_field_defs, &h.num_field_defs, &h.ofs_functions, &h.num_functions, &h.ofs_strings,
          &h.num_strings, &h.ofs_globals, &h.num_globals, &h.entity_fields}) {
        *field = r.i32();
    }
    return h;
}

// A reader over table `what`: count records of record_size bytes at offset.
ByteReader table(const ByteReader& r, int32_t offset, int32_t count, size_t record_size,
                 std::string_view what) {
    if (offset < 0) r.fail_at(0, std::string(what) + " offset is negative");
    if (count < 0) r.fail_at(0, std::string(what) + " count is negative");
    const uint64_t bytes = uint64_t(count) * record_size;
    if (uint64_t(offset) > r.size() || bytes > r.size() - uint64_t(offset)) {
        r.fail_at(0, std::string(what) + " (" + std::to_string(count) + " x " +
                         std::to_string(record_size) + " bytes at offset " +
                         std::to_string(offset) + ") extends past the end of the file");
    }
    return r.sub(size_t(offset), size_t(bytes), what);
}

std::vector<Def> read_defs(ByteReader r, int32_t count) {
    std::vector<Def> defs(static_cast<size_t>(count));
    for (Def& d : defs) {
        d.type = r.u16();
        d.offset = r.u16();
        d.name = r.i32();
    }
    return defs;
}

class Validator {
  public:
    Validator(const Progs& p, const ByteReader& file, const ProgsHeader& h)
        : p_(p), file_(file), h_(h) {}

    void run() {
        if (p_.globals.size() < kReservedGlobals) {
            fail(h_.ofs_globals, "only " + std::to_string(p_.globals.size()) +
                                     " globals; the return value and parameters need " +
                                     std::to_string(kReservedGlobals));
        }
        if (p_.functions.empty()) fail(h_.ofs_functions, "no functions (entry 0 is reserved)");
        for (size_t i = 0; i < p_.statements.size(); ++i) statement(i);
        for (size_t i = 0; i < p_.functions.size(); ++i) function(i);
        defs(p_.global_defs, p_.globals.size(), h_.ofs_global_defs, "global");
        defs(p_.field_defs, p_.entity_fields, h_.ofs_field_defs, "field");
    }

  private:
    [[noreturn]] void fail(int64_t offset, std::string message) const {
        throw FormatError(Error{file_.file(), uint64_t(offset), std::move(message)});
    }

    void string_index(int32_t s, int64_t offset, std::string_view what) const {
        if (s < 0 || size_t(s) >= p_.strings.size()) {
            fail(offset, std::string(what) + " names string " + std::to_string(s) +
                             ", outside the " + std::to_string(p_.strings.size()) +
                             "-byte string table");
        }
    }

    void statement(size_t i) const {
        const Statement& s = p_.statements[i];
        const int64_t at = h_.ofs_statements + int64_t(i * kStatementBytes);
        if (s.op >= kOpCount) {
            fail(at,
                 "statement " + std::to_string(i) + " has unknown opcode " + std::to_string(s.op));
        }
        const OpcodeInfo& info = opcode_info(s.op);
        operand(i, at, info.name, info.a, s.a, 'a');
        operand(i, at, info.name, info.b, s.b, 'b');
        operand(i, at, info.name, info.c, s.c, 'c');
    }

    void operand(size_t i, int64_t at, const char* op, Operand kind, uint16_t value,
                 char which) const {
        const std::string where =
            "statement " + std::to_string(i) + " (" + op + ") operand " + which;
        switch (kind) {
            case Operand::unused:
                return;
            case Operand::scalar:
            case Operand::vector: {
                const size_t words = kind == Operand::vector ? 3 : 1;
                if (size_t(value) + words > p_.globals.size()) {
                    fail(at, where + " reads global " + std::to_string(value) + " of " +
                                 std::to_string(p_.globals.size()));
                }
                return;
            }
            case Operand::jump: {
                const int64_t target = int64_t(i) + int16_t(value);
                if (target < 0 || target >= int64_t(p_.statements.size())) {
                    fail(at, where + " jumps to statement " + std::to_string(target) + " of " +
                                 std::to_string(p_.statements.size()));
                }
                return;
            }
        }
    }

    void function(size_t i) const {
        const Function& f = p_.functions[i];
        const int64_t at = h_.ofs_functions + int64_t(i * kFunctionBytes);
        const std::string what = "function " + std::to_string(i);
        string_index(f.name, at, what);
        string_index(f.file, at, what + " file");
        if (f.num_parms < 0 || f.num_parms > kMaxParms) {
            fail(at, what + " has " + std::to_string(f.num_parms) + " parameters (at most 8)");
        }
        if (f.builtin()) return;
        if (i == 0) return;  // the reserved null function is never entered
        if (size_t(f.first_statement) >= p_.statements.size()) {
            fail(at, what + " starts at statement " + std::to_string(f.first_statement) + " of " +
                         std::to_string(p_.statements.size()));
        }
        int64_t words = 0;
        for (int k = 0; k < f.num_parms; ++k) words += f.parm_size[k];
        // fteqcc may give a function fewer locals than parameter words (an unused parameter):
        // the arguments are still copied in, so both ranges must fit.
        if (f.parm_start < 0 || f.locals < 0 ||
            int64_t(f.parm_start) + std::max<int64_t>(f.locals, words) >
                int64_t(p_.globals.size())) {
            fail(at, what + " keeps locals " + std::to_string(f.parm_start) + " + " +
                         std::to_string(f.locals) + " (parameters " + std::to_string(words) +
                         " words) outside the " + std::to_string(p_.globals.size()) + " globals");
        }
        for (int k = 0; k < f.num_parms; ++k) {
            if (f.parm_size[k] > kParmWords) {
                fail(at, what + " parameter " + std::to_string(k) + " is " +
                             std::to_string(f.parm_size[k]) + " words (at most 3)");
            }
        }
    }

    void defs(const std::vector<Def>& list, size_t space, int64_t base, const char* kind) const {
        for (size_t i = 0; i < list.size(); ++i) {
            const Def& d = list[i];
            const int64_t at = base + int64_t(i * kDefBytes);
            const std::string what = std::string(kind) + " definition " + std::to_string(i);
            string_index(d.name, at, what);
            const size_t words = d.def_type() == DefType::vector ? 3 : 1;
            if (size_t(d.offset) + words > space) {
                fail(at, what + " (" + std::string(p_.string_at(d.name)) + ") at word " +
                             std::to_string(d.offset) + " is outside the " + std::to_string(space) +
                             " words");
            }
        }
    }

    const Progs& p_;
    const ByteReader& file_;
    const ProgsHeader& h_;
};

Progs read_progs(std::span<const uint8_t> data, const std::string& name) {
    ByteReader r(data, name);
    const ProgsHeader h = read_header(r);
    if (h.version != kProgsVersion) {
        r.fail_at(0, "progs version " + std::to_string(h.version) + " (only version 6 is known)");
    }
    if (h.entity_fields < 0 || h.entity_fields > kMaxEntityFields) {
        r.fail_at(56, "implausible entity size of " + std::to_string(h.entity_fields) + " words");
    }
    Progs p;
    p.name = name;
    p.crc = h.crc;
    p.entity_fields = uint32_t(h.entity_fields);

    ByteReader st = table(r, h.ofs_statements, h.num_statements, kStatementBytes, "statements");
    p.statements.resize(size_t(h.num_statements));
    for (Statement& s : p.statements) {
        s.op = st.u16();
        s.a = st.u16();
        s.b = st.u16();
        s.c = st.u16();
    }
    p.global_defs =
        read_defs(table(r, h.ofs_global_defs, h.num_global_defs, kDefBytes, "global definitions"),
                  h.num_global_defs);
    p.field_defs =
        read_defs(table(r, h.ofs_field_defs, h.num_field_defs, kDefBytes, "field definitions"),
                  h.num_field_defs);

    ByteReader fr = table(r, h.ofs_functions, h.num_functions, kFunctionBytes, "functions");
    p.functions.resize(size_t(h.num_functions));
    for (Function& f : p.functions) {
        f.first_statement = fr.i32();
        f.parm_start = fr.i32();
        f.locals = fr.i32();
        f.profile = fr.i32();
        f.name = fr.i32();
        f.file = fr.i32();
        f.num_parms = fr.i32();
        for (uint8_t& size : f.parm_size) size = fr.u8();
    }

    ByteReader sr = table(r, h.ofs_strings, h.num_strings, 1, "strings");
    const auto bytes = sr.bytes(size_t(h.num_strings));
    p.strings.assign(bytes.begin(), bytes.end());
    p.strings.push_back('\0');  // an unterminated last string still ends

    ByteReader gr = table(r, h.ofs_globals, h.num_globals, 4, "globals");
    p.globals.resize(size_t(h.num_globals));
    for (uint32_t& g : p.globals) g = gr.u32();

    Validator(p, r, h).run();
    return p;
}

}  // namespace

std::string_view Progs::string_at(int32_t index) const {
    if (index < 0 || size_t(index) >= strings.size()) return {};
    return std::string_view(strings.data() + index);
}

std::string_view Progs::function_name(int32_t function) const {
    if (function < 0 || size_t(function) >= functions.size()) return {};
    return string_at(functions[size_t(function)].name);
}

const Def* Progs::find_global(std::string_view wanted) const {
    for (const Def& d : global_defs) {
        if (string_at(d.name) == wanted) return &d;
    }
    return nullptr;
}

const Def* Progs::find_field(std::string_view wanted) const {
    for (const Def& d : field_defs) {
        if (string_at(d.name) == wanted) return &d;
    }
    return nullptr;
}

int32_t Progs::find_function(std::string_view wanted) const {
    for (size_t i = 1; i < functions.size(); ++i) {
        if (string_at(functions[i].name) == wanted) return int32_t(i);
    }
    return 0;
}

Result<Progs> parse_progs(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&] { return read_progs(data, name); });
}

}  // namespace nq::vm
