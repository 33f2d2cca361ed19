// The QuakeC interpreter: global memory, entity memory laid out by the progs' fields, strings,
// and execution of QuakeC functions with calls into engine builtins.
//
// Values follow Quake: every global and field word is a float, an int32 string value, an entity
// value (a byte offset into entity memory: edict n is n * entity_fields * 4, so world is 0), a
// field offset (in words), a function index, or a pointer (a byte offset into entity memory).
//
// Errors: a bad opcode value at run time, a bad entity, field, pointer, string, function or
// builtin, a stack overflow, or more than 100,000 statements in one call stop the program.
// execute() returns false and error() names the problem and the QuakeC call stack; every later
// execute() refuses to run until clear_error(), so the engine can end the level cleanly. Builtins
// report errors with fail(). Nothing here aborts the process or reads outside its memory.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vm/progs.h"
#include "vm/string_table.h"

namespace nq::vm {

class Vm;

// An engine function QuakeC calls as builtin #number. `host` is what set_builtins was given.
struct Builtin {
    const char* name = nullptr;
    void (*call)(Vm& vm, void* host) = nullptr;
};

struct VmLimits {
    uint32_t max_edicts = 8192;
    int max_call_depth = 64;      // QuakeSpasm's MAX_STACK_DEPTH
    uint32_t local_stack = 2048;  // words of saved locals (LOCALSTACK_SIZE)
    // Statements per execute() before "runaway loop": QuakeSpasm's 0x1000000, since real mods
    // run past Quake's original 100,000 in one call (big spawn functions, bot waypoint loops).
    int32_t runaway = 0x1000000;
    // Statements of an outermost execute() and every call nested in it: nested calls each get
    // their own `runaway`, so without this a hostile progs could nest loops into hours.
    int64_t runaway_nested = 4 * int64_t(0x1000000);
};

struct VmError {
    std::string message;             // e.g. "runaway loop error"
    std::vector<std::string> stack;  // QuakeC functions, innermost first
    std::string to_string() const;   // "runaway loop error (in ai_run <- ai_walk <- think)"
};

using Vec3f = std::array<float, 3>;

class Vm {
  public:
    explicit Vm(Progs progs, VmLimits limits = {});
    Vm(const Vm&) = delete;
    Vm& operator=(const Vm&) = delete;

    const Progs& progs() const { return progs_; }
    StringTable& strings() { return strings_; }
    void set_builtins(std::span<const Builtin> table, void* host);

    // ---- execution ----
    // Runs function `function` (an index into progs().functions). False when it (or any earlier
    // call since clear_error) failed. Builtins may call execute() again (touch functions).
    bool execute(int32_t function);
    const std::optional<VmError>& error() const { return error_; }
    void clear_error();
    // For builtins: stops the running QuakeC program with `message`.
    [[noreturn]] void fail(std::string message);
    // Arguments the running builtin was called with (the N of OP_CALLN).
    int argc() const { return argc_; }
    // Statements executed since construction (for profiling and tests).
    uint64_t statements_run() const { return statements_run_; }
    // While false (the default), QuakeC may not take the address of a world field: Quake forbids
    // assignments to world once the level runs; the engine allows them while spawning.
    void set_world_writable(bool writable) { world_writable_ = writable; }

    // ---- globals ----
    uint32_t global_count() const { return uint32_t(globals_.size()); }
    uint32_t global_word(uint32_t ofs) const { return ofs < globals_.size() ? globals_[ofs] : 0; }
    void set_global_word(uint32_t ofs, uint32_t v) {
        if (ofs < globals_.size()) globals_[ofs] = v;
    }
    float global_float(uint32_t ofs) const;
    void set_global_float(uint32_t ofs, float v);
    Vec3f global_vector(uint32_t ofs) const;
    void set_global_vector(uint32_t ofs, const Vec3f& v);
    // Restores every global to the progs' initial values.
    void reset_globals() { globals_ = progs_.globals; }

    // ---- builtin parameters and return value ----
    float param_float(int i) const { return global_float(kOfsParm0 + uint32_t(i) * kParmWords); }
    Vec3f param_vector(int i) const { return global_vector(kOfsParm0 + uint32_t(i) * kParmWords); }
    int32_t param_int(int i) const {
        return int32_t(global_word(kOfsParm0 + uint32_t(i) * kParmWords));
    }
    // The edict number of entity parameter i; fail()s on a bad entity value.
    uint32_t param_edict(int i);
    // The string parameter i; fail()s on a bad string value.
    std::string_view param_string(int i);
    void return_float(float v) { set_global_float(kOfsReturn, v); }
    void return_vector(const Vec3f& v) { set_global_vector(kOfsReturn, v); }
    void return_edict(uint32_t edict) { set_global_word(kOfsReturn, entity_value(edict)); }
    void return_int(int32_t v) { set_global_word(kOfsReturn, uint32_t(v)); }
    void return_temp_string(std::string_view text) { return_int(strings_.make_temp(text)); }

    // ---- strings ----
    // The string a value names; fail()s on a bad value (use inside builtins).
    std::string_view string(int32_t value);
    // The string a value names, or "" (use outside execution).
    std::string_view string_or_empty(int32_t value) const {
        return strings_.get(value).value_or(std::string_view{});
    }

    // ---- entities ----
    uint32_t entity_fields() const { return progs_.entity_fields; }
    uint32_t max_edicts() const { return max_edicts_; }
    // Edicts 0..num_edicts-1 exist; QuakeC may only name those.
    uint32_t num_edicts() const { return num_edicts_; }
    void set_num_edicts(uint32_t n) { num_edicts_ = n < max_edicts_ ? n : max_edicts_; }
    void clear_edict(uint32_t edict);
    uint32_t entity_value(uint32_t edict) const { return edict * stride_bytes_; }
    // The edict an entity value names, or nothing when it is not one (or not allocated).
    std::optional<uint32_t> edict_of(uint32_t value) const;
    // Raw field words of edict `edict` (entity_fields() of them); empty past max_edicts.
    std::span<uint32_t> edict_words(uint32_t edict);
    std::span<const uint32_t> edict_words(uint32_t edict) const;

    // Field access for the engine: `field` is a word offset resolved at load; out-of-range
    // edicts or fields read 0 and ignore writes.
    float field_float(uint32_t edict, uint32_t field) const;
    void set_field_float(uint32_t edict, uint32_t field, float v);
    Vec3f field_vector(uint32_t edict, uint32_t field) const;
    void set_field_vector(uint32_t edict, uint32_t field, const Vec3f& v);
    int32_t field_int(uint32_t edict, uint32_t field) const;
    void set_field_int(uint32_t edict, uint32_t field, int32_t v);

  private:
    struct Frame {
        int32_t statement = 0;  // the caller's statement (the CALL) to return to
        int32_t function = 0;   // the caller
    };
    struct Abort {};  // thrown inside execution only, caught by execute()

    void run(int32_t function, int exit_depth);
    int32_t enter(int32_t function);
    int32_t leave();
    void call(uint16_t op, uint32_t function_value, int32_t& statement);
    uint32_t checked_edict_word(uint32_t entity, uint32_t field, uint32_t words);
    uint32_t checked_pointer(uint32_t pointer, uint32_t words);
    void execute_state(uint32_t frame_word, uint32_t think_word);
    std::vector<std::string> call_stack() const;

    Progs progs_;
    VmLimits limits_;
    StringTable strings_;
    std::vector<uint32_t> globals_;
    std::vector<uint32_t> edicts_;
    uint32_t max_edicts_ = 0;
    uint32_t num_edicts_ = 0;
    uint32_t stride_words_ = 1;  // words per edict in edicts_ (at least 1)
    uint32_t stride_bytes_ = 4;

    std::span<const Builtin> builtins_;
    void* host_ = nullptr;

    std::vector<Frame> frames_;
    std::vector<uint32_t> local_stack_;
    int depth_ = 0;
    uint32_t locals_used_ = 0;
    int32_t current_function_ = 0;
    int32_t current_statement_ = 0;
    int argc_ = 0;
    bool world_writable_ = false;
    uint64_t statements_run_ = 0;
    int64_t nested_budget_ = 0;  // left of runaway_nested in the current outermost call
    std::optional<VmError> error_;

    // OP_STATE's globals and fields, found by name at load (0 when the progs lacks them).
    struct StateOffsets {
        bool found = false;
        uint32_t self = 0, time = 0, nextthink = 0, frame = 0, think = 0;
    } state_;
};

}  // namespace nq::vm
