// QuakeC opcodes of progs version 6 and what each operand of a statement means, so the loader
// can check every operand once and the interpreter need not check them again.
#pragma once

#include <cstdint>

namespace nq::vm {

enum Opcode : uint16_t {
    kOpDone,
    kOpMulF,
    kOpMulV,
    kOpMulFV,
    kOpMulVF,
    kOpDivF,
    kOpAddF,
    kOpAddV,
    kOpSubF,
    kOpSubV,
    kOpEqF,
    kOpEqV,
    kOpEqS,
    kOpEqE,
    kOpEqFnc,
    kOpNeF,
    kOpNeV,
    kOpNeS,
    kOpNeE,
    kOpNeFnc,
    kOpLe,
    kOpGe,
    kOpLt,
    kOpGt,
    kOpLoadF,
    kOpLoadV,
    kOpLoadS,
    kOpLoadEnt,
    kOpLoadFld,
    kOpLoadFnc,
    kOpAddress,
    kOpStoreF,
    kOpStoreV,
    kOpStoreS,
    kOpStoreEnt,
    kOpStoreFld,
    kOpStoreFnc,
    kOpStorePF,
    kOpStorePV,
    kOpStorePS,
    kOpStorePEnt,
    kOpStorePFld,
    kOpStorePFnc,
    kOpReturn,
    kOpNotF,
    kOpNotV,
    kOpNotS,
    kOpNotEnt,
    kOpNotFnc,
    kOpIf,
    kOpIfNot,
    kOpCall0,
    kOpCall1,
    kOpCall2,
    kOpCall3,
    kOpCall4,
    kOpCall5,
    kOpCall6,
    kOpCall7,
    kOpCall8,
    kOpState,
    kOpGoto,
    kOpAnd,
    kOpOr,
    kOpBitAnd,
    kOpBitOr,
    kOpCount
};

// What one operand of a statement is.
enum class Operand : uint8_t {
    unused,  // ignored by the interpreter (compilers leave 0 there)
    scalar,  // a global word: float, string, entity, field or function
    vector,  // three consecutive global words
    jump,    // a signed statement offset relative to this statement
};

struct OpcodeInfo {
    const char* name;
    Operand a, b, c;
};

// Operand kinds for every opcode below kOpCount.
const OpcodeInfo& opcode_info(uint16_t op);

}  // namespace nq::vm
