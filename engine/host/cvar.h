// One console variable: a named text value with its number forms, flags, a default and a
// one-line description. Created and changed only through CvarRegistry.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "host/cvar_value.h"
#include "host/owner.h"

namespace nq {

enum CvarFlag : uint32_t {
    kCvarArchive = 1u << 0,      // saved to config.cfg
    kCvarReadOnly = 1u << 1,     // only the engine may change it, never the user
    kCvarPlugin = 1u << 2,       // registered by a renderer plugin
    kCvarUserCreated = 1u << 3,  // made by `set`/`seta` and not (yet) registered by code
};

// What code passes to CvarRegistry::register_cvar.
struct CvarSpec {
    std::string name;
    std::string default_value;
    uint32_t flags = 0;  // CvarFlag bits; kCvarUserCreated is ignored here
    std::string description;
    // A numeric cvar: values outside [min, max] are clamped, non-numbers refused.
    std::optional<float> min_value;
    std::optional<float> max_value;
};

using CvarCallbackId = uint64_t;  // 0 is never a valid id
class Cvar;
using CvarCallback = std::function<void(const Cvar&)>;

class Cvar {
  public:
    Cvar(const Cvar&) = delete;
    Cvar& operator=(const Cvar&) = delete;

    // Spelled as by the latest registration (or as first typed, for a user-created cvar).
    const std::string& name() const { return name_; }
    const std::string& string() const { return string_; }
    float value() const { return view_.value; }
    int32_t integer() const { return view_.integer; }
    uint32_t modified_count() const { return view_.modified_count; }
    // Stable for the registry's lifetime; see cvar_value.h for the exact guarantee.
    const CvarValue* value_ptr() const { return &view_; }

    uint32_t flags() const { return flags_; }
    bool has_flag(CvarFlag flag) const { return (flags_ & flag) != 0; }
    const std::string& default_value() const { return default_; }
    const std::string& description() const { return description_; }
    std::optional<float> min_value() const { return min_; }
    std::optional<float> max_value() const { return max_; }
    bool is_numeric() const { return min_ || max_; }
    OwnerId owner() const { return owner_; }

  private:
    friend class CvarRegistry;
    struct Callback {
        CvarCallbackId id;
        OwnerId owner;
        CvarCallback fn;
    };

    explicit Cvar(std::string name) : name_(std::move(name)) { store(""); }
    // Sets the text and the number forms; does not count a change or notify anyone.
    void store(std::string text);

    std::string name_;
    std::string string_;
    std::string default_;
    std::string description_;
    uint32_t flags_ = 0;
    OwnerId owner_ = kNoOwner;
    std::optional<float> min_;
    std::optional<float> max_;
    bool user_archived_ = false;  // `seta` asked for archiving; survives re-registration
    bool notifying_ = false;      // inside its own change callbacks
    std::vector<Callback> callbacks_;
    CvarValue view_{sizeof(CvarValue), 0.0f, 0, "", 0};
};

// "between 0 and 10", "of at least 0", "of at most 10"; empty for a non-numeric cvar.
std::string describe_range(const Cvar& cvar);

}  // namespace nq
