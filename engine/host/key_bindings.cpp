#include "host/key_bindings.h"

#include "host/key_names.h"

namespace nq {

bool KeyBindings::bind(std::string_view key, std::string command) {
    std::optional<std::string> name = canonical_key_name(key);
    if (!name) return false;
    if (command.empty()) {
        bindings_.erase(*name);
    } else {
        bindings_[*name] = std::move(command);
    }
    return true;
}

bool KeyBindings::unbind(std::string_view key) {
    return bind(key, "");
}

const std::string* KeyBindings::binding(std::string_view key) const {
    std::optional<std::string> name = canonical_key_name(key);
    if (!name) return nullptr;
    auto it = bindings_.find(*name);
    return it == bindings_.end() ? nullptr : &it->second;
}

}  // namespace nq
