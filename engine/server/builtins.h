// The builtin functions QuakeC calls by number (Quake's #1..#78); their host pointer is the
// ServerLevel they act on.
#pragma once

#include <span>

#include "vm/vm.h"

namespace nq::server {

std::span<const vm::Builtin> game_builtins();

}  // namespace nq::server
