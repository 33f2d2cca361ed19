// All cvars of one engine instance, looked up by case-insensitive name.
//
// Cvars are never removed: a Cvar& / Cvar* / value_ptr() obtained from this registry stays
// valid, at the same address, for the registry's whole lifetime, however many cvars are
// registered later and whether or not the plugin that registered it is still loaded.
// Not thread-safe: use it from the thread that runs the command system.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "host/cvar.h"

namespace nq {

// Who asks for a change. The user (console, config files, command line, key bindings) cannot
// change read-only cvars; engine code can.
enum class CvarSource { kEngine, kUser };

enum class CvarSetResult {
    kChanged,      // the value is now the requested one
    kUnchanged,    // it already was
    kClamped,      // accepted, but clamped into the cvar's range
    kReadOnly,     // refused: a read-only cvar set by the user
    kNotNumeric,   // refused: a numeric cvar given text that is not a number
    kNotFound,     // refused: no cvar of that name
    kInvalidName,  // refused: the name cannot be a cvar name
};

bool set_accepted(CvarSetResult result);

class CvarRegistry {
  public:
    CvarRegistry() = default;
    CvarRegistry(const CvarRegistry&) = delete;
    CvarRegistry& operator=(const CvarRegistry&) = delete;

    // Creates the cvar, or registers an existing one again (a plugin reloaded, or a cvar the
    // user created with `set` before its plugin was loaded). Registering again updates the
    // default, description, flags, range and owner but keeps the current value when it
    // differs from the previous default (the user's choice, validated against the new range);
    // otherwise the value becomes the new default. A read-only cvar always starts at its
    // default. Returns nullptr for an invalid name, a range with min > max or a NaN bound,
    // or a numeric cvar whose default is not a number.
    Cvar* register_cvar(const CvarSpec& spec, OwnerId owner = kEngineOwner);

    Cvar* find(std::string_view name);
    const Cvar* find(std::string_view name) const;

    CvarSetResult set(std::string_view name, std::string_view value,
                      CvarSource source = CvarSource::kEngine);
    CvarSetResult set(Cvar& cvar, std::string_view value, CvarSource source = CvarSource::kEngine);
    // What the `set` and `seta` commands do: an unknown name becomes a user-created cvar
    // (kept, and applied when code registers that name later). `extra_flags` may hold
    // kCvarArchive (`seta`), which is added when the value is accepted.
    CvarSetResult set_or_create(std::string_view name, std::string_view value, uint32_t extra_flags,
                                CvarSource source = CvarSource::kUser);
    CvarSetResult reset(Cvar& cvar, CvarSource source = CvarSource::kEngine);

    // `fn` runs after every change of the cvar's value. Changes made from inside one of the
    // cvar's own callbacks are applied but do not call its callbacks again.
    CvarCallbackId add_callback(Cvar& cvar, CvarCallback fn, OwnerId owner = kEngineOwner);
    bool remove_callback(CvarCallbackId id);
    // A plugin is being unloaded: drops its callbacks; its cvars stay, with their values,
    // unowned (kNoOwner) until registered again.
    void release_owner(OwnerId owner);

    // Sorted by lower-case name; only names starting with `prefix` (case-insensitive).
    std::vector<const Cvar*> list(std::string_view prefix = {}) const;
    size_t size() const { return cvars_.size(); }

  private:
    Cvar& create(std::string_view name);
    // The value a cvar would take for `text`: validated and clamped against its range.
    CvarSetResult normalize(const Cvar& cvar, std::string_view text, std::string& out) const;
    // Stores `text` and, when it differs from the current value, counts and announces it.
    bool apply(Cvar& cvar, std::string text);
    void notify(Cvar& cvar);
    static bool valid_range(const CvarSpec& spec);

    std::vector<std::unique_ptr<Cvar>> cvars_;  // owns every node; nodes never move
    std::map<std::string, Cvar*> by_name_;      // key: lower-case name
    CvarCallbackId next_callback_id_ = 1;
};

}  // namespace nq
