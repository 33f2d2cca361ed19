#include "console/text_wrap.h"

#include <algorithm>

namespace nq {
namespace {

bool is_space(char c) {
    return (static_cast<unsigned char>(c) & 0x7f) == ' ';
}

}  // namespace

WrappedRow wrap_row(std::string_view line, size_t begin, size_t columns) {
    columns = std::max<size_t>(columns, 1);
    if (line.size() - begin <= columns) return {begin, line.size(), line.size()};
    // Break at the last space that still lets the row fit: the byte right after a full row
    // counts, since a break there needs no room on this row.
    for (size_t i = begin + columns; i > begin; --i) {
        if (is_space(line[i])) return {begin, i, i + 1};
    }
    return {begin, begin + columns, begin + columns};
}

size_t wrapped_row_count(std::string_view line, size_t columns) {
    size_t rows = 1;
    for (WrappedRow row = wrap_row(line, 0, columns); row.next < line.size(); ++rows) {
        row = wrap_row(line, row.next, columns);
    }
    return rows;
}

}  // namespace nq
