#include "host/cvar_registry.h"

#include <algorithm>
#include <cmath>

#include "host/number_text.h"
#include "host/text_util.h"

namespace nq {

bool set_accepted(CvarSetResult result) {
    return result == CvarSetResult::kChanged || result == CvarSetResult::kUnchanged ||
           result == CvarSetResult::kClamped;
}

bool CvarRegistry::valid_range(const CvarSpec& spec) {
    if (spec.min_value && std::isnan(*spec.min_value)) return false;
    if (spec.max_value && std::isnan(*spec.max_value)) return false;
    if (spec.min_value && spec.max_value && *spec.min_value > *spec.max_value) return false;
    return true;
}

Cvar* CvarRegistry::register_cvar(const CvarSpec& spec, OwnerId owner) {
    if (!is_valid_name(spec.name) || !valid_range(spec)) return nullptr;
    bool numeric = spec.min_value || spec.max_value;
    if (numeric && !parse_number_exact(spec.default_value)) return nullptr;

    Cvar* existing = find(spec.name);
    Cvar& cvar = existing ? *existing : create(spec.name);
    std::string previous_default = cvar.default_;
    bool user_created = cvar.has_flag(kCvarUserCreated);

    cvar.name_ = spec.name;
    cvar.description_ = spec.description;
    cvar.min_ = spec.min_value;
    cvar.max_ = spec.max_value;
    cvar.owner_ = owner;
    cvar.flags_ = (spec.flags & ~uint32_t{kCvarUserCreated}) |
                  (cvar.user_archived_ ? uint32_t{kCvarArchive} : 0u);

    // The default itself is clamped too, so that a cvar never holds an out-of-range value.
    std::string clamped_default;
    normalize(cvar, spec.default_value, clamped_default);
    cvar.default_ = clamped_default;

    if (!existing) {
        cvar.store(clamped_default);  // a new cvar starts at its default: not a change
        return &cvar;
    }
    bool keep_value =
        !cvar.has_flag(kCvarReadOnly) && (user_created || cvar.string_ != previous_default);
    std::string value = clamped_default;
    if (keep_value && !set_accepted(normalize(cvar, cvar.string_, value))) value = clamped_default;
    apply(cvar, std::move(value));
    return &cvar;
}

Cvar& CvarRegistry::create(std::string_view name) {
    cvars_.push_back(std::unique_ptr<Cvar>(new Cvar(std::string(name))));
    Cvar& cvar = *cvars_.back();
    by_name_[to_lower_ascii(name)] = &cvar;
    return cvar;
}

Cvar* CvarRegistry::find(std::string_view name) {
    auto it = by_name_.find(to_lower_ascii(name));
    return it == by_name_.end() ? nullptr : it->second;
}

const Cvar* CvarRegistry::find(std::string_view name) const {
    auto it = by_name_.find(to_lower_ascii(name));
    return it == by_name_.end() ? nullptr : it->second;
}

CvarSetResult CvarRegistry::normalize(const Cvar& cvar, std::string_view text,
                                      std::string& out) const {
    if (!cvar.is_numeric()) {
        out = std::string(text);
        return CvarSetResult::kChanged;
    }
    std::optional<float> number = parse_number_exact(text);
    if (!number) return CvarSetResult::kNotNumeric;
    float clamped = *number;
    if (cvar.min_) clamped = std::max(clamped, *cvar.min_);
    if (cvar.max_) clamped = std::min(clamped, *cvar.max_);
    if (clamped == *number) {
        out = std::string(text);  // keep the user's spelling ("0.50" stays "0.50")
        return CvarSetResult::kChanged;
    }
    out = format_number(clamped);
    return CvarSetResult::kClamped;
}

CvarSetResult CvarRegistry::set(std::string_view name, std::string_view value, CvarSource source) {
    Cvar* cvar = find(name);
    if (!cvar) return CvarSetResult::kNotFound;
    return set(*cvar, value, source);
}

CvarSetResult CvarRegistry::set(Cvar& cvar, std::string_view value, CvarSource source) {
    if (source == CvarSource::kUser && cvar.has_flag(kCvarReadOnly)) {
        return CvarSetResult::kReadOnly;
    }
    std::string text;
    CvarSetResult result = normalize(cvar, value, text);
    if (!set_accepted(result)) return result;
    bool changed = apply(cvar, std::move(text));
    if (result == CvarSetResult::kClamped) return result;
    return changed ? CvarSetResult::kChanged : CvarSetResult::kUnchanged;
}

CvarSetResult CvarRegistry::set_or_create(std::string_view name, std::string_view value,
                                          uint32_t extra_flags, CvarSource source) {
    Cvar* cvar = find(name);
    if (!cvar) {
        if (!is_valid_name(name)) return CvarSetResult::kInvalidName;
        cvar = &create(name);
        cvar->flags_ = kCvarUserCreated;
    }
    CvarSetResult result = set(*cvar, value, source);
    if (set_accepted(result) && (extra_flags & kCvarArchive)) {
        cvar->flags_ |= kCvarArchive;
        cvar->user_archived_ = true;
    }
    return result;
}

CvarSetResult CvarRegistry::reset(Cvar& cvar, CvarSource source) {
    return set(cvar, cvar.default_, source);
}

bool CvarRegistry::apply(Cvar& cvar, std::string text) {
    if (text == cvar.string_) return false;
    cvar.store(std::move(text));
    ++cvar.view_.modified_count;
    notify(cvar);
    return true;
}

void CvarRegistry::notify(Cvar& cvar) {
    if (cvar.notifying_ || cvar.callbacks_.empty()) return;
    struct Guard {
        bool& flag;
        ~Guard() { flag = false; }
    } guard{cvar.notifying_};
    cvar.notifying_ = true;
    // A callback may add or remove callbacks (a plugin unloading itself): iterate a copy and
    // skip the ones removed meanwhile.
    std::vector<Cvar::Callback> snapshot = cvar.callbacks_;
    for (const Cvar::Callback& callback : snapshot) {
        bool still_registered =
            std::any_of(cvar.callbacks_.begin(), cvar.callbacks_.end(),
                        [&](const Cvar::Callback& c) { return c.id == callback.id; });
        if (still_registered) callback.fn(cvar);
    }
}

CvarCallbackId CvarRegistry::add_callback(Cvar& cvar, CvarCallback fn, OwnerId owner) {
    if (!fn) return 0;
    CvarCallbackId id = next_callback_id_++;
    cvar.callbacks_.push_back({id, owner, std::move(fn)});
    return id;
}

bool CvarRegistry::remove_callback(CvarCallbackId id) {
    for (auto& cvar : cvars_) {
        auto& list = cvar->callbacks_;
        auto it = std::find_if(list.begin(), list.end(),
                               [&](const Cvar::Callback& c) { return c.id == id; });
        if (it != list.end()) {
            list.erase(it);
            return true;
        }
    }
    return false;
}

void CvarRegistry::release_owner(OwnerId owner) {
    for (auto& cvar : cvars_) {
        std::erase_if(cvar->callbacks_, [&](const Cvar::Callback& c) { return c.owner == owner; });
        if (cvar->owner_ == owner) cvar->owner_ = kNoOwner;
    }
}

std::vector<const Cvar*> CvarRegistry::list(std::string_view prefix) const {
    std::vector<const Cvar*> out;
    for (const auto& [key, cvar] : by_name_) {
        if (istarts_with(key, prefix)) out.push_back(cvar);
    }
    return out;
}

}  // namespace nq
