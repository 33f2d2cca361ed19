// Splitting one console line into screen rows of a fixed width, breaking between words where it
// can (a word longer than a whole row is cut). Works on raw console bytes: a space with the
// colour bit set (0xA0) is still a space.
#pragma once

#include <cstddef>
#include <string_view>

namespace nq {

struct WrappedRow {
    size_t begin = 0;  // byte range of the row in the line
    size_t end = 0;
    size_t next = 0;  // where the following row starts (past the space the row broke at)
};

// The row that starts at `begin` (0 for the first row); `columns` is at least 1.
WrappedRow wrap_row(std::string_view line, size_t begin, size_t columns);

// How many rows the line takes: at least 1, an empty line is one empty row.
size_t wrapped_row_count(std::string_view line, size_t columns);

}  // namespace nq
