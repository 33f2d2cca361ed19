// Which keys the open console takes for itself. The others (function keys, mouse buttons, ...)
// still run their bindings while it is open, as in Quake, so a bound F-key or a screenshot key
// keeps working.
#pragma once

#include <string_view>

namespace nq {

// The key that opens and closes the console (canonical name, key_names.h).
inline constexpr std::string_view kConsoleToggleKey = "`";

// `key` is a canonical key name (InputEvent::key).
bool is_console_key(std::string_view key);

}  // namespace nq
