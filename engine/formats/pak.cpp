#include "formats/pak.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <unordered_map>

#include "common/byte_reader.h"

namespace nq {

namespace {

constexpr char kMagic[4] = {'P', 'A', 'C', 'K'};
constexpr size_t kDirOffsetField = 4;
constexpr size_t kDirLengthField = 8;
constexpr size_t kEntryOffsetField = kPakNameField;
constexpr size_t kEntryLengthField = kPakNameField + 4;

std::string ascii_lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    }
    return out;
}

// Bytes from a file, made safe to print inside quotes in a message.
std::string printable(std::span<const uint8_t> bytes) {
    static const char kHex[] = "0123456789abcdef";
    std::string out;
    for (uint8_t b : bytes) {
        if (b >= 0x20 && b < 0x7f && b != '\\') {
            out += static_cast<char>(b);
        } else {
            out += "\\x";
            out += kHex[b >> 4];
            out += kHex[b & 15];
        }
    }
    return out;
}

std::string printable(std::string_view s) {
    return printable({reinterpret_cast<const uint8_t*>(s.data()), s.size()});
}

std::string range_text(uint64_t offset, uint64_t length) {
    return "[" + std::to_string(offset) + ", +" + std::to_string(length) + ")";
}

std::string entry_label(size_t index, std::string_view name) {
    return "entry " + std::to_string(index) + " '" + printable(name) + "'";
}

void check_header_fields(const ByteReader& r, int32_t dir_offset, int32_t dir_length,
                         uint64_t file_size) {
    if (dir_offset < 0) {
        r.fail_at(kDirOffsetField, "negative directory offset " + std::to_string(dir_offset));
    }
    if (dir_length < 0) {
        r.fail_at(kDirLengthField, "negative directory length " + std::to_string(dir_length));
    }
    if (dir_length % kPakEntrySize != 0) {
        r.fail_at(kDirLengthField, "directory length " + std::to_string(dir_length) +
                                       " is not a multiple of the 64-byte entry size");
    }
    uint64_t count = static_cast<uint64_t>(dir_length) / kPakEntrySize;
    if (count > kPakMaxEntries) {
        r.fail_at(kDirLengthField, "directory claims " + std::to_string(count) +
                                       " entries, over the limit of " +
                                       std::to_string(kPakMaxEntries));
    }
    uint64_t end = static_cast<uint64_t>(dir_offset) + static_cast<uint64_t>(dir_length);
    if (end > file_size) {
        r.fail_at(kDirOffsetField, "directory " + range_text(dir_offset, dir_length) +
                                       " extends past end of file (size " +
                                       std::to_string(file_size) + ")");
    }
    if (dir_length > 0 && static_cast<uint64_t>(dir_offset) < kPakHeaderSize) {
        r.fail_at(kDirOffsetField, "directory at offset " + std::to_string(dir_offset) +
                                       " overlaps the 12-byte header");
    }
}

// One directory record, validated for structure (name field, data range). Whether the name
// is safe to use is decided by the caller, which can skip the entry instead of failing.
PakEntry read_entry(ByteReader& r, size_t index, uint64_t file_size) {
    size_t at = r.tell();
    auto field = r.bytes(kPakNameField);
    auto nul = std::find(field.begin(), field.end(), uint8_t{0});
    if (nul == field.end()) {
        r.fail_at(at, "entry " + std::to_string(index) + ": name '" + printable(field) +
                          "' is not NUL-terminated within its 56 bytes");
    }
    if (nul == field.begin()) r.fail_at(at, "entry " + std::to_string(index) + ": empty name");
    std::string name(field.begin(), nul);
    int32_t offset = r.i32();
    int32_t length = r.i32();
    if (offset < 0) {
        r.fail_at(at + kEntryOffsetField,
                  entry_label(index, name) + ": negative data offset " + std::to_string(offset));
    }
    if (length < 0) {
        r.fail_at(at + kEntryLengthField,
                  entry_label(index, name) + ": negative data length " + std::to_string(length));
    }
    if (static_cast<uint64_t>(offset) + static_cast<uint64_t>(length) > file_size) {
        r.fail_at(at + kEntryOffsetField,
                  entry_label(index, name) + ": data " + range_text(offset, length) +
                      " extends past end of file (size " + std::to_string(file_size) + ")");
    }
    return PakEntry{std::move(name), static_cast<uint32_t>(offset), static_cast<uint32_t>(length)};
}

// Adds `entry` to `dir`, applying the "unsafe names are skipped, later duplicates win" rules.
void add_entry(PakDirectory& dir, std::unordered_map<std::string, size_t>& slot_by_key,
               PakEntry entry, size_t index, uint64_t entry_offset) {
    std::string where =
        entry_label(index, entry.name) + " at offset " + std::to_string(entry_offset);
    // Some DOS-era tools wrote backslashes; the engine only speaks '/'.
    if (entry.name.find('\\') != std::string::npos) {
        std::replace(entry.name.begin(), entry.name.end(), '\\', '/');
        dir.warnings.push_back(where + ": backslashes in name replaced by '/'");
    }
    if (std::string problem = pak_name_problem(entry.name); !problem.empty()) {
        dir.warnings.push_back(where + ": unsafe name (" + problem + "); entry ignored");
        ++dir.unsafe_entries;
        return;
    }
    auto [it, inserted] = slot_by_key.try_emplace(ascii_lower(entry.name), dir.entries.size());
    if (inserted) {
        dir.entries.push_back(std::move(entry));
        return;
    }
    dir.warnings.push_back(where + ": duplicate of an earlier entry named '" +
                           printable(dir.entries[it->second].name) +
                           "' (names ignore case); the later entry is used");
    dir.entries[it->second] = std::move(entry);
}

}  // namespace

Result<PakHeader> parse_pak_header(std::span<const uint8_t> start, uint64_t file_size,
                                   const std::string& name) {
    return capture_errors(name, [&] {
        ByteReader r(start, name);
        if (file_size < kPakHeaderSize || start.size() < kPakHeaderSize) {
            r.fail_at(0, "file is " + std::to_string(file_size) +
                             " bytes, too small for the 12-byte pak header");
        }
        auto magic = r.bytes(sizeof kMagic);
        if (std::memcmp(magic.data(), kMagic, sizeof kMagic) != 0) {
            r.fail_at(0, "bad magic '" + printable(magic) + "' (expected 'PACK')");
        }
        int32_t dir_offset = r.i32();
        int32_t dir_length = r.i32();
        check_header_fields(r, dir_offset, dir_length, file_size);
        return PakHeader{static_cast<uint32_t>(dir_offset), static_cast<uint32_t>(dir_length)};
    });
}

Result<PakDirectory> parse_pak_directory(std::span<const uint8_t> dir_bytes,
                                         const PakHeader& header, uint64_t file_size,
                                         const std::string& name) {
    return capture_errors(name, [&] {
        ByteReader r(dir_bytes, name, header.dir_offset);
        if (dir_bytes.size() != header.dir_length) {
            r.fail_at(0, "directory is " + std::to_string(dir_bytes.size()) +
                             " bytes, the header says " + std::to_string(header.dir_length));
        }
        size_t count = header.entry_count();
        r.require_records(static_cast<int64_t>(count), kPakEntrySize, "pak directory");
        PakDirectory dir;
        dir.header = header;
        dir.entries.reserve(count);
        std::unordered_map<std::string, size_t> slot_by_key;
        for (size_t i = 0; i < count; ++i) {
            uint64_t entry_offset = r.absolute(r.tell());
            add_entry(dir, slot_by_key, read_entry(r, i, file_size), i, entry_offset);
        }
        if (count == 0) dir.warnings.push_back("pak has no entries");
        return dir;
    });
}

Result<PakDirectory> parse_pak(std::span<const uint8_t> data, const std::string& name) {
    auto header = parse_pak_header(data, data.size(), name);
    if (!header) return header.error();
    // The header check guarantees the directory lies inside `data`.
    auto dir_bytes = data.subspan(header->dir_offset, header->dir_length);
    return parse_pak_directory(dir_bytes, *header, data.size(), name);
}

std::span<const uint8_t> pak_entry_bytes(std::span<const uint8_t> pak, const PakEntry& entry) {
    if (entry.offset > pak.size() || entry.size > pak.size() - entry.offset) return {};
    return pak.subspan(entry.offset, entry.size);
}

std::string pak_name_problem(std::string_view name) {
    if (name.empty()) return "empty name";
    if (name.front() == '/') return "absolute path";
    if (name.size() >= 2 && name[1] == ':' &&
        ((name[0] >= 'a' && name[0] <= 'z') || (name[0] >= 'A' && name[0] <= 'Z'))) {
        return "drive-letter path";
    }
    for (unsigned char c : name) {
        if (c == '\\') return "contains a backslash";
        if (c < 0x20 || c == 0x7f) return "contains a control character";
    }
    size_t start = 0;
    while (start <= name.size()) {
        size_t end = std::min(name.find('/', start), name.size());
        std::string_view part = name.substr(start, end - start);
        if (part.empty()) return "empty path component";
        if (part == ".") return "'.' path component";
        if (part == "..") return "'..' path component";
        start = end + 1;
    }
    return {};
}

namespace {

std::string check_files_for_writing(std::span<const PakFile> files) {
    if (files.size() > kPakMaxEntries) {
        return std::to_string(files.size()) + " files, over the limit of " +
               std::to_string(kPakMaxEntries);
    }
    std::unordered_map<std::string, size_t> index_by_key;
    for (size_t i = 0; i < files.size(); ++i) {
        const std::string& n = files[i].name;
        if (std::string problem = pak_name_problem(n); !problem.empty()) {
            return entry_label(i, n) + ": unusable name (" + problem + ")";
        }
        if (n.size() > kPakMaxNameLength) {
            return entry_label(i, n) + ": name is " + std::to_string(n.size()) +
                   " bytes, over the pak limit of " + std::to_string(kPakMaxNameLength);
        }
        auto [it, inserted] = index_by_key.try_emplace(ascii_lower(n), i);
        if (!inserted) {
            return entry_label(i, n) + ": same name (ignoring case) as " +
                   entry_label(it->second, files[it->second].name);
        }
    }
    return {};
}

void put_i32(std::vector<uint8_t>& out, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) out[at + i] = static_cast<uint8_t>(v >> (8 * i));
}

void append_i32(std::vector<uint8_t>& out, uint32_t v) {
    out.resize(out.size() + 4);
    put_i32(out, out.size() - 4, v);
}

}  // namespace

Result<std::vector<uint8_t>> write_pak(std::span<const PakFile> files, const std::string& name) {
    if (std::string problem = check_files_for_writing(files); !problem.empty()) {
        return Error{name, 0, "cannot write pak: " + problem};
    }
    uint64_t total = kPakHeaderSize + kPakEntrySize * files.size();
    for (const PakFile& f : files) total += f.data.size();
    if (total > static_cast<uint64_t>(std::numeric_limits<int32_t>::max())) {
        return Error{name, 0,
                     "cannot write pak: " + std::to_string(total) +
                         " bytes in all, over the format's 2 GiB limit"};
    }
    std::vector<uint8_t> out(kPakHeaderSize);
    std::memcpy(out.data(), kMagic, sizeof kMagic);
    out.reserve(total);
    std::vector<uint32_t> offsets;
    offsets.reserve(files.size());
    for (const PakFile& f : files) {
        offsets.push_back(static_cast<uint32_t>(out.size()));
        out.insert(out.end(), f.data.begin(), f.data.end());
    }
    put_i32(out, kDirOffsetField, static_cast<uint32_t>(out.size()));
    put_i32(out, kDirLengthField, static_cast<uint32_t>(kPakEntrySize * files.size()));
    for (size_t i = 0; i < files.size(); ++i) {
        size_t field = out.size();
        out.resize(field + kPakNameField, 0);
        std::memcpy(out.data() + field, files[i].name.data(), files[i].name.size());
        append_i32(out, offsets[i]);
        append_i32(out, static_cast<uint32_t>(files[i].data.size()));
    }
    return out;
}

}  // namespace nq
