// Which command each key runs: what `bind` stores and config.cfg saves. Keys are stored under
// their canonical names (key_names.h), so "ESCAPE", "escape" and "Escape" are one binding.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace nq {

class KeyBindings {
  public:
    // False when `key` is no key name. An empty command unbinds.
    bool bind(std::string_view key, std::string command);
    // False when `key` is no key name (unbinding an unbound key is fine).
    bool unbind(std::string_view key);
    void unbind_all() { bindings_.clear(); }
    // The bound command, or nullptr when the key is unbound or no key.
    const std::string* binding(std::string_view key) const;
    // Canonical key name -> command, sorted by key name (byte order).
    const std::map<std::string, std::string>& all() const { return bindings_; }

  private:
    std::map<std::string, std::string> bindings_;
};

}  // namespace nq
