// The entity lump of a map (Bsp::entities): Quake's text format, a sequence of
//   { "key" "value" "key" "value" ... }
// blocks. Tokens are "quoted strings" (no escapes) or bare words; // starts a comment to the end
// of the line. Keys keep their file order, duplicates included.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/result.h"

namespace nq {

struct Entity {
    std::vector<std::pair<std::string, std::string>> pairs;  // in file order
    uint64_t offset = 0;                                     // file offset of the entity's '{'
};

struct EntityList {
    std::vector<Entity> entities;  // entity 0 is worldspawn in a well-formed map
    std::vector<std::string> warnings;
};

// `base_offset` is the file offset of text[0] (Bsp::entities_offset), so errors point into the
// .bsp. Parsing stops at the first NUL byte.
Result<EntityList> parse_entities(std::span<const uint8_t> text, const std::string& name,
                                  uint64_t base_offset = 0);
// Convenience for the text of a parsed map.
Result<EntityList> parse_entities(std::string_view text, const std::string& name,
                                  uint64_t base_offset = 0);

// The value of `key`; if the key repeats, the last one (the game assigns fields in order, so
// the last one wins there too). The view points into `entity`.
std::optional<std::string_view> find_value(const Entity& entity, std::string_view key);
// The entity's classname, or "" when it has none.
std::string_view classname(const Entity& entity);
// Entities whose classname is `name`, in file order.
std::vector<const Entity*> find_entities(const EntityList& list, std::string_view name);

// "x y z" (three finite numbers separated by blanks; nothing else but blanks) as a vector.
std::optional<std::array<float, 3>> parse_vec3(std::string_view text);
// find_value + parse_vec3, e.g. for "origin" or "_color".
std::optional<std::array<float, 3>> find_vec3(const Entity& entity, std::string_view key);

}  // namespace nq
