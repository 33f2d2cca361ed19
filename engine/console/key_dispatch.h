// Keys in game (console closed): each press runs the key's binding through the command buffer.
// A binding that starts with '+' is a held action: the press runs "+action <key>" and the
// release runs "-action <key>", as Quake does (the key name tells the action which key let go
// when two keys hold it). The release always runs for a press that ran "+", even when the
// console opened or the binding changed in between, so no action stays stuck.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "host/command_system.h"
#include "host/key_bindings.h"

namespace nq {

class KeyDispatch {
  public:
    KeyDispatch(CommandSystem& commands, const KeyBindings& bindings);

    // A key went down in game. Auto-repeats are ignored (a held key is one press).
    void key_down(std::string_view key, bool repeat);
    // A key went up (whoever got its press): runs the '-' command its press started, if any.
    void key_up(std::string_view key);
    // Runs every pending '-' command (focus lost: releases would never arrive).
    void release_all();

    size_t held_actions() const { return held_.size(); }

  private:
    struct HeldAction {
        std::string key;
        std::string release_command;  // "-action key\n"
    };

    CommandSystem& commands_;
    const KeyBindings& bindings_;
    std::vector<HeldAction> held_;
};

}  // namespace nq
