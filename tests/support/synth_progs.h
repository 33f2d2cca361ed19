// A small assembler for synthetic progs.dat files (version 6): test fixtures for the QuakeC VM
// and fuzz seeds. Statements are written by opcode, so tests can pin exact VM semantics (raw-bit
// IF, non-short-circuit AND) whatever a compiler would emit, and build every malformed case.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "support/seed_file.h"

namespace nq::test {

class SynthProgs {
  public:
    struct Statement {
        uint16_t op = 0, a = 0, b = 0, c = 0;
    };
    struct Def {
        uint16_t type = 0, offset = 0;
        int32_t name = 0;
    };
    struct Function {
        int32_t first_statement = 0, parm_start = 0, locals = 0, profile = 0, name = 0, file = 0;
        int32_t num_parms = 0;
        std::array<uint8_t, 8> parm_size{};
    };

    SynthProgs();  // string 0 is "", function 0 is the null function, globals 0..27 reserved

    int32_t string(std::string_view s);   // index into the string table
    uint16_t global(float value = 0);     // a new float global
    uint16_t global_word(uint32_t word);  // a new raw global
    uint16_t global_vector(float x, float y, float z);
    uint16_t global_string(std::string_view s);  // a global holding a string value
    void name_global(std::string_view name, uint16_t type, uint16_t offset);
    uint16_t field(std::string_view name, uint16_t type, uint16_t words = 1);  // its word offset
    // A function whose code starts at the next statement; returns its index.
    int32_t function(std::string_view name, int32_t num_parms = 0, int32_t locals = 0,
                     uint16_t parm_start = 0, std::array<uint8_t, 8> parm_size = {});
    int32_t builtin(std::string_view name, int32_t number);
    uint16_t global_function(int32_t function);  // a global holding a function value
    void op(uint16_t op, uint16_t a = 0, uint16_t b = 0, uint16_t c = 0);
    // Index of the next statement (for jumps).
    int32_t here() const { return int32_t(statements.size()); }

    std::vector<uint8_t> bytes() const;

    int32_t version = 6, crc = 5927;
    std::vector<Statement> statements;
    std::vector<Def> global_defs, field_defs;
    std::vector<Function> functions;
    std::string strings;
    std::vector<uint32_t> globals;
    uint32_t entity_fields = 0;
    // Header overrides, to write lying counts and offsets.
    std::optional<int32_t> num_statements, num_globals, ofs_functions, num_strings;
};

// A few valid programs (arithmetic, a loop, a call, entity fields) for fuzz seeds.
std::vector<SeedFile> synthetic_progs_seeds();

}  // namespace nq::test
