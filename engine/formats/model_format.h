// Which kind of model a file holds, told by its first four bytes as Quake's Mod_ForName does,
// never by its name: a ".mdl" that is really a sprite loads as one, and a misnamed or foreign
// file fails with what its bytes are.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace nq {

enum class ModelFormat {
    alias,   // "IDPO" (mdl.h)
    sprite,  // "IDSP" (spr.h)
    brush,   // BSP version 29, "BSP2" or "2PSB" (bsp.h)
    unknown,
};

ModelFormat identify_model(std::span<const uint8_t> bytes);

// "alias model (IDPO)", "sprite (IDSP)", "brush model (BSP)", "unknown".
const char* model_format_name(ModelFormat format);

// The format a model's file name suggests (".mdl", ".spr", ".bsp", any case); unknown for others.
ModelFormat model_format_by_extension(const std::string& name);

// For an unknown file: its first bytes, printable ones as text ("first bytes \"RIFF\"", or in
// hex when not printable), so the message says what the file is instead.
std::string describe_model_magic(std::span<const uint8_t> bytes);

}  // namespace nq
