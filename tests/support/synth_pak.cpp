#include "support/synth_pak.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace nq::test {

namespace fs = std::filesystem;

namespace {

constexpr size_t kHeaderBytes = 12;
constexpr size_t kNameBytes = 56;
constexpr size_t kRecordBytes = 64;

void append_le32(std::vector<uint8_t>& out, int32_t value) {
    auto v = static_cast<uint32_t>(value);
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void append_name_field(std::vector<uint8_t>& out, const std::string& name) {
    for (size_t i = 0; i < kNameBytes; ++i) {
        out.push_back(i < name.size() ? static_cast<uint8_t>(name[i]) : 0);
    }
}

std::vector<uint8_t> bytes_of(std::string_view s) {
    return {s.begin(), s.end()};
}

}  // namespace

std::vector<uint8_t> build_raw_pak(const RawPak& pak) {
    std::vector<uint8_t> out;
    for (size_t i = 0; i < 4; ++i) {
        out.push_back(i < pak.magic.size() ? static_cast<uint8_t>(pak.magic[i]) : 0);
    }
    auto natural_offset = static_cast<int32_t>(kHeaderBytes + pak.payload.size());
    auto natural_length = static_cast<int32_t>(kRecordBytes * pak.entries.size());
    append_le32(out, pak.dir_offset.value_or(natural_offset));
    append_le32(out, pak.dir_length.value_or(natural_length));
    out.insert(out.end(), pak.payload.begin(), pak.payload.end());
    for (const RawPakEntry& e : pak.entries) {
        append_name_field(out, e.name);
        append_le32(out, e.offset);
        append_le32(out, e.length);
    }
    return out;
}

std::vector<uint8_t> build_pak(const std::vector<NamedText>& files) {
    RawPak pak;
    for (const auto& [name, content] : files) {
        auto offset = static_cast<int32_t>(kHeaderBytes + pak.payload.size());
        pak.payload.insert(pak.payload.end(), content.begin(), content.end());
        pak.entries.push_back({name, offset, static_cast<int32_t>(content.size())});
    }
    return build_raw_pak(pak);
}

std::vector<SeedFile> synthetic_pak_seeds() {
    std::vector<SeedFile> seeds;
    seeds.push_back({"empty.pak", build_pak({})});
    seeds.push_back({"nested.pak", build_pak({{"gfx/palette.lmp", std::string(768, '\x07')},
                                              {"maps/start.bsp", "BSP data"},
                                              {"progs/player.mdl", "IDPO"}})});
    seeds.push_back({"duplicates.pak", build_pak({{"a.cfg", "first"}, {"A.CFG", "second"}})});
    seeds.push_back({"backslash.pak", build_pak({{"sound\\misc\\h2o.wav", "RIFF"}})});
    RawPak shared;
    shared.payload = bytes_of("shared");
    shared.entries = {{"one", 12, 6}, {"two", 12, 6}, {"empty", 18, 0}};
    seeds.push_back({"shared_data.pak", build_raw_pak(shared)});
    seeds.push_back({"unsafe_names.pak",
                     build_pak({{"../escape.txt", "x"}, {"/abs.txt", "y"}, {"ok.txt", "z"}})});
    RawPak junk;
    junk.payload = bytes_of("data");
    junk.entries = {{std::string("name.txt\0junk after nul", 23), 12, 4}};
    seeds.push_back({"junk_after_nul.pak", build_raw_pak(junk)});
    return seeds;
}

TempGameTree::TempGameTree() : dir_("nq_pak_test") {}

std::string TempGameTree::path(std::string_view relative) const {
    return (fs::path(root()) / relative).string();
}

void TempGameTree::make_dir(std::string_view relative) const {
    std::error_code ec;
    fs::create_directories(path(relative), ec);
    if (ec) throw std::runtime_error("cannot create " + path(relative) + ": " + ec.message());
}

void TempGameTree::write_bytes(std::string_view relative, std::span<const uint8_t> bytes) const {
    fs::path target = path(relative);
    if (target.has_parent_path()) make_dir(fs::path(relative).parent_path().string());
    std::ofstream out(target, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) throw std::runtime_error("cannot write " + target.string());
}

void TempGameTree::write(std::string_view relative, std::string_view content) const {
    write_bytes(relative, bytes_of(content));
}

void TempGameTree::write_pak(std::string_view relative, const std::vector<NamedText>& files) const {
    write_bytes(relative, build_pak(files));
}

}  // namespace nq::test
