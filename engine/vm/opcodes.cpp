#include "vm/opcodes.h"

#include <array>

namespace nq::vm {

namespace {

constexpr Operand U = Operand::unused, S = Operand::scalar, V = Operand::vector, J = Operand::jump;

constexpr std::array<OpcodeInfo, kOpCount> kOpcodes = {{
    {"DONE", V, U, U},       {"MUL_F", S, S, S},      {"MUL_V", V, V, S},
    {"MUL_FV", S, V, V},     {"MUL_VF", V, S, V},     {"DIV_F", S, S, S},
    {"ADD_F", S, S, S},      {"ADD_V", V, V, V},      {"SUB_F", S, S, S},
    {"SUB_V", V, V, V},      {"EQ_F", S, S, S},       {"EQ_V", V, V, S},
    {"EQ_S", S, S, S},       {"EQ_E", S, S, S},       {"EQ_FNC", S, S, S},
    {"NE_F", S, S, S},       {"NE_V", V, V, S},       {"NE_S", S, S, S},
    {"NE_E", S, S, S},       {"NE_FNC", S, S, S},     {"LE", S, S, S},
    {"GE", S, S, S},         {"LT", S, S, S},         {"GT", S, S, S},
    {"LOAD_F", S, S, S},     {"LOAD_V", S, S, V},     {"LOAD_S", S, S, S},
    {"LOAD_ENT", S, S, S},   {"LOAD_FLD", S, S, S},   {"LOAD_FNC", S, S, S},
    {"ADDRESS", S, S, S},    {"STORE_F", S, S, U},    {"STORE_V", V, V, U},
    {"STORE_S", S, S, U},    {"STORE_ENT", S, S, U},  {"STORE_FLD", S, S, U},
    {"STORE_FNC", S, S, U},  {"STOREP_F", S, S, U},   {"STOREP_V", V, S, U},
    {"STOREP_S", S, S, U},   {"STOREP_ENT", S, S, U}, {"STOREP_FLD", S, S, U},
    {"STOREP_FNC", S, S, U}, {"RETURN", V, U, U},     {"NOT_F", S, U, S},
    {"NOT_V", V, U, S},      {"NOT_S", S, U, S},      {"NOT_ENT", S, U, S},
    {"NOT_FNC", S, U, S},    {"IF", S, J, U},         {"IFNOT", S, J, U},
    {"CALL0", S, U, U},      {"CALL1", S, U, U},      {"CALL2", S, U, U},
    {"CALL3", S, U, U},      {"CALL4", S, U, U},      {"CALL5", S, U, U},
    {"CALL6", S, U, U},      {"CALL7", S, U, U},      {"CALL8", S, U, U},
    {"STATE", S, S, U},      {"GOTO", J, U, U},       {"AND", S, S, S},
    {"OR", S, S, S},         {"BITAND", S, S, S},     {"BITOR", S, S, S},
}};

constexpr OpcodeInfo kBadOpcode{"BAD", U, U, U};

}  // namespace

const OpcodeInfo& opcode_info(uint16_t op) {
    return op < kOpCount ? kOpcodes[op] : kBadOpcode;
}

}  // namespace nq::vm
