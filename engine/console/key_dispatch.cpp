#include "console/key_dispatch.h"

#include <algorithm>

namespace nq {

KeyDispatch::KeyDispatch(CommandSystem& commands, const KeyBindings& bindings)
    : commands_(commands), bindings_(bindings) {}

void KeyDispatch::key_down(std::string_view key, bool repeat) {
    if (repeat) return;
    const std::string* command = bindings_.binding(key);
    if (!command || command->empty()) return;
    if (command->front() != '+') {
        commands_.add_text(*command + "\n");
        return;
    }
    // A second press without a release (lost event): release the first one before.
    key_up(key);
    commands_.add_text(*command + " " + std::string(key) + "\n");
    held_.push_back({std::string(key), "-" + command->substr(1) + " " + std::string(key) + "\n"});
}

void KeyDispatch::key_up(std::string_view key) {
    auto held = std::find_if(held_.begin(), held_.end(),
                             [&](const HeldAction& action) { return action.key == key; });
    if (held == held_.end()) return;
    commands_.add_text(held->release_command);
    held_.erase(held);
}

void KeyDispatch::release_all() {
    for (const HeldAction& action : held_) commands_.add_text(action.release_command);
    held_.clear();
}

}  // namespace nq
