#include "vm/vm.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "vm/opcodes.h"

namespace nq::vm {

namespace {

float as_float(uint32_t w) {
    return std::bit_cast<float>(w);
}
uint32_t as_word(float f) {
    return std::bit_cast<uint32_t>(f);
}
uint32_t as_word(bool b) {
    return as_word(b ? 1.0f : 0.0f);
}

// QuakeC's (int) conversion for BITAND/BITOR, saturating where C++ would be undefined.
int32_t to_int(float f) {
    if (std::isnan(f)) return 0;
    if (f >= 2147483647.0f) return INT32_MAX;
    if (f <= -2147483648.0f) return INT32_MIN;
    return int32_t(f);
}

// Largest entity memory whose byte offsets still fit an int32 entity value.
constexpr uint64_t kMaxEntityBytes = uint64_t(1) << 31;

}  // namespace

std::string VmError::to_string() const {
    std::string s = message;
    if (stack.empty()) return s;
    s += " (in ";
    for (size_t i = 0; i < stack.size(); ++i) {
        if (i) s += " <- ";
        s += stack[i];
    }
    return s + ")";
}

Vm::Vm(Progs progs, VmLimits limits)
    : progs_(std::move(progs)), limits_(limits), strings_(progs_.strings) {
    globals_ = progs_.globals;
    stride_words_ = std::max<uint32_t>(progs_.entity_fields, 1);
    stride_bytes_ = stride_words_ * 4;
    max_edicts_ = uint32_t(std::min<uint64_t>(limits_.max_edicts, kMaxEntityBytes / stride_bytes_));
    max_edicts_ = std::max<uint32_t>(max_edicts_, 1);
    edicts_.assign(size_t(max_edicts_) * stride_words_, 0);
    limits_.max_call_depth = std::clamp(limits_.max_call_depth, 1, 1 << 16);
    frames_.resize(size_t(limits_.max_call_depth) + 1);
    local_stack_.resize(limits_.local_stack);

    const Def* self = progs_.find_global("self");
    const Def* time = progs_.find_global("time");
    const Def* nextthink = progs_.find_field("nextthink");
    const Def* frame = progs_.find_field("frame");
    const Def* think = progs_.find_field("think");
    if (self && time && nextthink && frame && think) {
        state_ = {true,          self->offset, time->offset, nextthink->offset,
                  frame->offset, think->offset};
    }
}

void Vm::set_builtins(std::span<const Builtin> table, void* host) {
    builtins_ = table;
    host_ = host;
}

// ---------------------------------------------------------------- globals and fields

float Vm::global_float(uint32_t ofs) const {
    return as_float(global_word(ofs));
}
void Vm::set_global_float(uint32_t ofs, float v) {
    set_global_word(ofs, as_word(v));
}

Vec3f Vm::global_vector(uint32_t ofs) const {
    return {global_float(ofs), global_float(ofs + 1), global_float(ofs + 2)};
}

void Vm::set_global_vector(uint32_t ofs, const Vec3f& v) {
    for (uint32_t i = 0; i < 3; ++i) set_global_float(ofs + i, v[i]);
}

std::optional<uint32_t> Vm::edict_of(uint32_t value) const {
    if (value % stride_bytes_ != 0) return std::nullopt;
    const uint32_t n = value / stride_bytes_;
    if (n >= num_edicts_) return std::nullopt;
    return n;
}

std::span<uint32_t> Vm::edict_words(uint32_t edict) {
    if (edict >= max_edicts_) return {};
    return {edicts_.data() + size_t(edict) * stride_words_, progs_.entity_fields};
}

std::span<const uint32_t> Vm::edict_words(uint32_t edict) const {
    if (edict >= max_edicts_) return {};
    return {edicts_.data() + size_t(edict) * stride_words_, progs_.entity_fields};
}

void Vm::clear_edict(uint32_t edict) {
    std::span<uint32_t> words = edict_words(edict);
    std::fill(words.begin(), words.end(), 0u);
}

float Vm::field_float(uint32_t edict, uint32_t field) const {
    return as_float(uint32_t(field_int(edict, field)));
}

void Vm::set_field_float(uint32_t edict, uint32_t field, float v) {
    set_field_int(edict, field, int32_t(as_word(v)));
}

Vec3f Vm::field_vector(uint32_t edict, uint32_t field) const {
    return {field_float(edict, field), field_float(edict, field + 1),
            field_float(edict, field + 2)};
}

void Vm::set_field_vector(uint32_t edict, uint32_t field, const Vec3f& v) {
    for (uint32_t i = 0; i < 3; ++i) set_field_float(edict, field + i, v[i]);
}

int32_t Vm::field_int(uint32_t edict, uint32_t field) const {
    std::span<const uint32_t> words = edict_words(edict);
    return field < words.size() ? int32_t(words[field]) : 0;
}

void Vm::set_field_int(uint32_t edict, uint32_t field, int32_t v) {
    std::span<uint32_t> words = edict_words(edict);
    if (field < words.size()) words[field] = uint32_t(v);
}

// ---------------------------------------------------------------- builtin helpers

uint32_t Vm::param_edict(int i) {
    const uint32_t value = uint32_t(param_int(i));
    const std::optional<uint32_t> edict = edict_of(value);
    if (!edict)
        fail("bad entity value " + std::to_string(value) + " in parameter " +
             std::to_string(i + 1));
    return *edict;
}

std::string_view Vm::param_string(int i) {
    return string(param_int(i));
}

std::string_view Vm::string(int32_t value) {
    const std::optional<std::string_view> s = strings_.get(value);
    if (!s) fail("bad string value " + std::to_string(value));
    return *s;
}

// ---------------------------------------------------------------- errors

std::vector<std::string> Vm::call_stack() const {
    std::vector<std::string> stack;
    auto name_of = [&](int32_t f) {
        const std::string_view name = progs_.function_name(f);
        return name.empty() ? "function #" + std::to_string(f) : std::string(name);
    };
    if (current_function_ > 0) stack.push_back(name_of(current_function_));
    for (int d = depth_ - 1; d >= 1; --d) {
        if (frames_[size_t(d)].function > 0) stack.push_back(name_of(frames_[size_t(d)].function));
    }
    return stack;
}

void Vm::fail(std::string message) {
    if (!error_) {
        const std::string at = " at statement " + std::to_string(current_statement_);
        error_ = VmError{progs_.name + ": " + message + (depth_ > 0 ? at : ""), call_stack()};
    }
    throw Abort{};
}

void Vm::clear_error() {
    error_.reset();
    depth_ = 0;
    locals_used_ = 0;
    current_function_ = 0;
}

// ---------------------------------------------------------------- calls

bool Vm::execute(int32_t function) {
    if (error_) return false;
    const int exit_depth = depth_;
    const uint32_t exit_locals = locals_used_;
    const int32_t caller = current_function_;
    const int32_t caller_statement = current_statement_;
    if (depth_ == 0) nested_budget_ = limits_.runaway_nested;
    try {
        if (function <= 0 || size_t(function) >= progs_.functions.size()) {
            fail("call of function " + std::to_string(function) + " (of " +
                 std::to_string(progs_.functions.size()) + ")");
        }
        run(function, exit_depth);
        return true;
    } catch (const Abort&) {
        // Unwind to where this call began; the outer program, if any, stops when the builtin
        // that called us returns.
        depth_ = exit_depth;
        locals_used_ = exit_locals;
        current_function_ = caller;
        current_statement_ = caller_statement;
        return false;
    }
}

int32_t Vm::enter(int32_t function) {
    const Function& f = progs_.functions[size_t(function)];
    if (depth_ >= limits_.max_call_depth) {
        fail("stack overflow (more than " + std::to_string(limits_.max_call_depth) +
             " nested calls)");
    }
    if (uint64_t(locals_used_) + uint32_t(f.locals) > local_stack_.size()) {
        fail("locals stack overflow");
    }
    frames_[size_t(depth_)] = {current_statement_, current_function_};
    ++depth_;
    // Save the callee's locals (recursion reuses the same globals), then copy the arguments in.
    std::copy_n(globals_.begin() + f.parm_start, f.locals, local_stack_.begin() + locals_used_);
    locals_used_ += uint32_t(f.locals);
    uint32_t to = uint32_t(f.parm_start);
    for (int i = 0; i < f.num_parms; ++i) {
        for (uint32_t j = 0; j < f.parm_size[size_t(i)]; ++j) {
            globals_[to++] = globals_[kOfsParm0 + uint32_t(i) * kParmWords + j];
        }
    }
    current_function_ = function;
    return f.first_statement;
}

int32_t Vm::leave() {
    const Function& f = progs_.functions[size_t(current_function_)];
    locals_used_ -= uint32_t(f.locals);
    std::copy_n(local_stack_.begin() + locals_used_, f.locals, globals_.begin() + f.parm_start);
    --depth_;
    current_function_ = frames_[size_t(depth_)].function;
    return frames_[size_t(depth_)].statement;
}

void Vm::call(uint16_t op, uint32_t function_value, int32_t& statement) {
    if (function_value == 0 || function_value >= progs_.functions.size()) {
        fail(function_value == 0 ? "call of a null function"
                                 : "call of function " + std::to_string(function_value) + " (of " +
                                       std::to_string(progs_.functions.size()) + ")");
    }
    argc_ = op - kOpCall0;
    const Function& f = progs_.functions[function_value];
    if (!f.builtin()) {
        statement = enter(int32_t(function_value));
        return;
    }
    const int64_t number = -int64_t(f.first_statement);
    if (size_t(number) >= builtins_.size() || !builtins_[size_t(number)].call) {
        fail("call of unknown builtin #" + std::to_string(number) + " (" +
             std::string(progs_.function_name(int32_t(function_value))) + ")");
    }
    builtins_[size_t(number)].call(*this, host_);
    if (error_) throw Abort{};  // a nested execute() failed inside the builtin
    ++statement;
}

// ---------------------------------------------------------------- entity memory checks

uint32_t Vm::checked_edict_word(uint32_t entity, uint32_t field, uint32_t words) {
    const std::optional<uint32_t> edict = edict_of(entity);
    if (!edict) fail("bad entity value " + std::to_string(entity));
    if (uint64_t(field) + words > progs_.entity_fields) {
        fail("bad field offset " + std::to_string(int32_t(field)) + " (entities have " +
             std::to_string(progs_.entity_fields) + " words)");
    }
    return *edict * stride_words_ + field;
}

uint32_t Vm::checked_pointer(uint32_t pointer, uint32_t words) {
    if (pointer % 4 != 0 || uint64_t(pointer / 4) + words > uint64_t(num_edicts_) * stride_words_) {
        fail("bad pointer " + std::to_string(int32_t(pointer)));
    }
    return pointer / 4;
}

void Vm::execute_state(uint32_t frame_word, uint32_t think_word) {
    if (!state_.found) fail("OP_STATE in a progs without self, time, nextthink, frame or think");
    const uint32_t self = globals_[state_.self];
    const uint32_t base = checked_edict_word(self, 0, 0);
    for (uint32_t f : {state_.nextthink, state_.frame, state_.think}) {
        if (f >= progs_.entity_fields) fail("bad field offset " + std::to_string(f));
    }
    edicts_[base + state_.nextthink] = as_word(as_float(globals_[state_.time]) + 0.1f);
    edicts_[base + state_.frame] = frame_word;
    edicts_[base + state_.think] = think_word;
}

// ---------------------------------------------------------------- the interpreter

void Vm::run(int32_t function, int exit_depth) {
    const std::vector<Statement>& code = progs_.statements;
    const int32_t end = int32_t(code.size());
    uint32_t* g = globals_.data();
    auto f = [&](uint16_t i) { return as_float(g[i]); };
    auto set = [&](uint16_t i, float v) { g[i] = as_word(v); };
    auto set_bool = [&](uint16_t i, bool v) { g[i] = as_word(v); };

    int32_t st = enter(function);
    int32_t budget = limits_.runaway;
    for (;;) {
        if (st < 0 || st >= end) {
            current_statement_ = st;
            fail("ran off the end of the statements");
        }
        if (--budget < 0 || --nested_budget_ < 0) {
            current_statement_ = st;
            fail("runaway loop error (" +
                 std::to_string(budget < 0 ? limits_.runaway : limits_.runaway_nested) +
                 " statements)");
        }
        ++statements_run_;
        current_statement_ = st;
        const Statement& s = code[size_t(st)];
        const uint16_t a = s.a, b = s.b, c = s.c;
        switch (s.op) {
            case kOpAddF:
                set(c, f(a) + f(b));
                break;
            case kOpAddV:
                for (int i = 0; i < 3; ++i)
                    set(uint16_t(c + i), f(uint16_t(a + i)) + f(uint16_t(b + i)));
                break;
            case kOpSubF:
                set(c, f(a) - f(b));
                break;
            case kOpSubV:
                for (int i = 0; i < 3; ++i)
                    set(uint16_t(c + i), f(uint16_t(a + i)) - f(uint16_t(b + i)));
                break;
            case kOpMulF:
                set(c, f(a) * f(b));
                break;
            case kOpMulV:
                set(c, f(a) * f(b) + f(uint16_t(a + 1)) * f(uint16_t(b + 1)) +
                           f(uint16_t(a + 2)) * f(uint16_t(b + 2)));
                break;
            case kOpMulFV: {
                const float k = f(a);
                for (int i = 0; i < 3; ++i) set(uint16_t(c + i), k * f(uint16_t(b + i)));
                break;
            }
            case kOpMulVF: {
                const float k = f(b);
                for (int i = 0; i < 3; ++i) set(uint16_t(c + i), k * f(uint16_t(a + i)));
                break;
            }
            case kOpDivF:
                set(c, f(a) / f(b));
                break;
            case kOpBitAnd:
                set(c, float(to_int(f(a)) & to_int(f(b))));
                break;
            case kOpBitOr:
                set(c, float(to_int(f(a)) | to_int(f(b))));
                break;
            case kOpGe:
                set_bool(c, f(a) >= f(b));
                break;
            case kOpLe:
                set_bool(c, f(a) <= f(b));
                break;
            case kOpGt:
                set_bool(c, f(a) > f(b));
                break;
            case kOpLt:
                set_bool(c, f(a) < f(b));
                break;
            case kOpAnd:
                set_bool(c, f(a) != 0 && f(b) != 0);
                break;  // both sides already ran
            case kOpOr:
                set_bool(c, f(a) != 0 || f(b) != 0);
                break;
            case kOpNotF:
                set_bool(c, f(a) == 0);
                break;
            case kOpNotV:
                set_bool(c, f(a) == 0 && f(uint16_t(a + 1)) == 0 && f(uint16_t(a + 2)) == 0);
                break;
            case kOpNotS:
                set_bool(c, g[a] == 0 || string(int32_t(g[a])).empty());
                break;
            case kOpNotFnc:
            case kOpNotEnt:
                set_bool(c, g[a] == 0);
                break;
            case kOpEqF:
                set_bool(c, f(a) == f(b));
                break;
            case kOpEqV:
                set_bool(c, f(a) == f(b) && f(uint16_t(a + 1)) == f(uint16_t(b + 1)) &&
                                f(uint16_t(a + 2)) == f(uint16_t(b + 2)));
                break;
            case kOpEqS:
                set_bool(c, string(int32_t(g[a])) == string(int32_t(g[b])));
                break;
            case kOpEqE:
            case kOpEqFnc:
                set_bool(c, g[a] == g[b]);
                break;
            case kOpNeF:
                set_bool(c, f(a) != f(b));
                break;
            case kOpNeV:
                set_bool(c, f(a) != f(b) || f(uint16_t(a + 1)) != f(uint16_t(b + 1)) ||
                                f(uint16_t(a + 2)) != f(uint16_t(b + 2)));
                break;
            case kOpNeS:
                set_bool(c, string(int32_t(g[a])) != string(int32_t(g[b])));
                break;
            case kOpNeE:
            case kOpNeFnc:
                set_bool(c, g[a] != g[b]);
                break;

            case kOpStoreF:
            case kOpStoreS:
            case kOpStoreEnt:
            case kOpStoreFld:
            case kOpStoreFnc:
                g[b] = g[a];
                break;
            case kOpStoreV:
                g[b] = g[a];
                g[b + 1] = g[a + 1];
                g[b + 2] = g[a + 2];
                break;
            case kOpStorePF:
            case kOpStorePS:
            case kOpStorePEnt:
            case kOpStorePFld:
            case kOpStorePFnc:
                edicts_[checked_pointer(g[b], 1)] = g[a];
                break;
            case kOpStorePV: {
                const uint32_t p = checked_pointer(g[b], 3);
                std::copy_n(g + a, 3, edicts_.begin() + p);
                break;
            }
            case kOpAddress: {
                const uint32_t word = checked_edict_word(g[a], g[b], 1);
                if (word < stride_words_ && !world_writable_) fail("assignment to world entity");
                g[c] = word * 4;
                break;
            }
            case kOpLoadF:
            case kOpLoadS:
            case kOpLoadEnt:
            case kOpLoadFld:
            case kOpLoadFnc:
                g[c] = edicts_[checked_edict_word(g[a], g[b], 1)];
                break;
            case kOpLoadV: {
                const uint32_t word = checked_edict_word(g[a], g[b], 3);
                std::copy_n(edicts_.begin() + word, 3, g + c);
                break;
            }

            case kOpIfNot:
                if (g[a] == 0) {  // raw bits: -0.0 counts as true, as in Quake
                    st += int16_t(b);
                    continue;
                }
                break;
            case kOpIf:
                if (g[a] != 0) {
                    st += int16_t(b);
                    continue;
                }
                break;
            case kOpGoto:
                st += int16_t(a);
                continue;

            case kOpCall0:
            case kOpCall1:
            case kOpCall2:
            case kOpCall3:
            case kOpCall4:
            case kOpCall5:
            case kOpCall6:
            case kOpCall7:
            case kOpCall8:
                call(s.op, g[a], st);
                continue;

            case kOpDone:
            case kOpReturn:
                g[kOfsReturn] = g[a];
                g[kOfsReturn + 1] = g[a + 1];
                g[kOfsReturn + 2] = g[a + 2];
                st = leave();
                if (depth_ == exit_depth) return;
                break;  // on to the statement after the caller's CALL

            case kOpState:
                execute_state(g[a], g[b]);
                break;

            default:
                fail("bad opcode " + std::to_string(s.op));
        }
        ++st;
    }
}

}  // namespace nq::vm
