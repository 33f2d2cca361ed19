// progs.dat, version 6: compiled QuakeC. A 60-byte header of (offset, count) pairs, then
// statements (8 bytes: opcode and three 16-bit operands), global and field definitions (8 bytes),
// functions (36 bytes), a string table and the initial global values (4 bytes each).
//
// parse_progs checks everything the interpreter would otherwise have to check at every step:
// opcodes, the global operands of every statement (vectors need three words), jump targets,
// function entry points, parameter and local ranges, and every string index in the tables. What
// can only be known at run time (entity, field and pointer values, function values, builtin
// numbers) the interpreter checks itself.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace nq::vm {

inline constexpr int32_t kProgsVersion = 6;
inline constexpr size_t kProgsHeaderBytes = 60;
// The CRC of id's progdefs.h: progs with this value use Quake's standard system globals and fields.
inline constexpr int32_t kStandardProgsCrc = 5927;

// Reserved global words: the return value and eight 3-word parameters (Quake's OFS_*).
inline constexpr uint32_t kOfsReturn = 1;
inline constexpr uint32_t kOfsParm0 = 4;
inline constexpr uint32_t kParmWords = 3;
inline constexpr int kMaxParms = 8;
inline constexpr uint32_t kReservedGlobals = kOfsParm0 + kMaxParms * kParmWords;  // 28

enum class DefType : uint16_t {
    void_,
    string,
    float_,
    vector,
    entity,
    field,
    function,
    pointer,
};
inline constexpr uint16_t kDefSaveGlobal = 1 << 15;  // set on globals a save game keeps

struct Statement {
    uint16_t op = 0;
    uint16_t a = 0, b = 0, c = 0;  // global indices, or signed jump offsets (see opcodes.h)
};

struct Def {
    uint16_t type = 0;  // DefType, plus kDefSaveGlobal on globals
    uint16_t offset = 0;
    int32_t name = 0;  // string index
    DefType def_type() const { return static_cast<DefType>(type & ~kDefSaveGlobal); }
    bool saved() const { return (type & kDefSaveGlobal) != 0; }
};

struct Function {
    int32_t first_statement = 0;  // < 0: builtin number -first_statement
    int32_t parm_start = 0;       // first global word of the parameters and locals
    int32_t locals = 0;           // words from parm_start saved across a call
    int32_t profile = 0;
    int32_t name = 0;  // string index
    int32_t file = 0;  // string index
    int32_t num_parms = 0;
    std::array<uint8_t, kMaxParms> parm_size{};  // words per parameter (1 or 3)
    bool builtin() const { return first_statement < 0; }
};

struct Progs {
    std::string name;  // file name, for messages
    int32_t crc = 0;
    std::vector<Statement> statements;
    std::vector<Def> global_defs;
    std::vector<Def> field_defs;
    std::vector<Function> functions;
    std::vector<char> strings;      // always ends with a NUL, so every index reads a C string
    std::vector<uint32_t> globals;  // initial values, raw words
    uint32_t entity_fields = 0;     // words per entity

    // The string at table index `index`, or empty when it is out of range.
    std::string_view string_at(int32_t index) const;
    // The function's name ("" when stripped or out of range).
    std::string_view function_name(int32_t function) const;
    const Def* find_global(std::string_view name) const;
    const Def* find_field(std::string_view name) const;
    int32_t find_function(std::string_view name) const;  // 0 when absent
};

// The header fields in file order (offsets and counts of each table), as stored.
struct ProgsHeader {
    int32_t version = 0, crc = 0;
    int32_t ofs_statements = 0, num_statements = 0;
    int32_t ofs_global_defs = 0, num_global_defs = 0;
    int32_t ofs_field_defs = 0, num_field_defs = 0;
    int32_t ofs_functions = 0, num_functions = 0;
    int32_t ofs_strings = 0, num_strings = 0;
    int32_t ofs_globals = 0, num_globals = 0;
    int32_t entity_fields = 0;
};

Result<Progs> parse_progs(std::span<const uint8_t> data, const std::string& name);

}  // namespace nq::vm
