// What every renderer table must have, whatever its ABI major (1.x through the adapter, 2.x
// directly): a size covering the version's smallest table, init and shutdown, and a name.
#pragma once

#include <cstddef>
#include <string>

namespace nq {

// "" when `table` (non-NULL, of the major version it was checked for) has them, else why not.
template <class Table>
std::string check_table_basics(const Table& table, size_t min_size) {
    if (table.size < min_size) {
        return "function table too small (" + std::to_string(table.size) + " bytes, need " +
               std::to_string(min_size) + ")";
    }
    if (!table.init || !table.shutdown) return "the plugin has no init or shutdown function";
    if (!table.name || !*table.name) return "the plugin has no name";
    return {};
}

}  // namespace nq
