// PAK format: writer/parser round trip, every malformed-input class, name safety, real data
// packed and read back, and the `pak` command-line tool.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "common/file_io.h"
#include "formats/pak.h"
#include "fs/pak_archive.h"
#include "support/engine_run.h"
#include "support/raw_bytes.h"
#include "support/synth_pak.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::build_pak;
using test::build_raw_pak;
using test::RawPak;
using test::read_le32;

std::vector<uint8_t> bytes_of(std::string_view s) {
    return {s.begin(), s.end()};
}

std::string text_of(std::span<const uint8_t> b) {
    return std::string(b.begin(), b.end());
}

// Parses `bytes`, expecting failure; returns the error.
Error parse_error(const std::vector<uint8_t>& bytes) {
    auto r = parse_pak(bytes, "bad.pak");
    EXPECT_FALSE(r.ok()) << "expected the pak to be rejected";
    return r.ok() ? Error{} : r.error();
}

// A pak whose directory starts right after `payload`: 12 + payload size.
RawPak pak_with(std::string payload, std::vector<test::RawPakEntry> entries) {
    RawPak pak;
    pak.payload = bytes_of(payload);
    pak.entries = std::move(entries);
    return pak;
}

// ---------------------------------------------------------------------------------------------
// Round trips

TEST(PakFormat, WriterOutputHasTheDocumentedLayoutAndParsesBackIdentically) {
    std::vector<uint8_t> all_bytes(256);
    for (int i = 0; i < 256; ++i) all_bytes[i] = static_cast<uint8_t>(i);
    std::vector<PakFile> files = {
        {"gfx/palette.lmp", all_bytes},
        {"empty.txt", {}},
        {"maps/e1m1.bsp", bytes_of("not really a map")},
        {std::string(50, 'n') + ".abcd", bytes_of("55-byte name")},
    };
    auto written = write_pak(files, "out.pak");
    ASSERT_TRUE(written.ok()) << written.error().to_string();
    const std::vector<uint8_t>& pak = *written;

    // Independent reading of the raw layout: header, data in order, directory at the end.
    ASSERT_GE(pak.size(), 12u);
    EXPECT_EQ(text_of({pak.data(), 4}), "PACK");
    size_t data_bytes = 256 + 0 + 16 + 12;
    int32_t dir_offset = read_le32(pak, 4);
    EXPECT_EQ(dir_offset, static_cast<int32_t>(12 + data_bytes));
    EXPECT_EQ(read_le32(pak, 8), 64 * 4);
    EXPECT_EQ(pak.size(), 12 + data_bytes + 64 * 4);
    int32_t expected_offset = 12;
    for (size_t i = 0; i < files.size(); ++i) {
        size_t record = static_cast<size_t>(dir_offset) + 64 * i;
        std::string field(pak.begin() + record, pak.begin() + record + 56);
        EXPECT_EQ(field.substr(0, field.find('\0')), files[i].name);
        EXPECT_EQ(field.back(), '\0');
        EXPECT_EQ(read_le32(pak, record + 56), expected_offset);
        EXPECT_EQ(read_le32(pak, record + 60), static_cast<int32_t>(files[i].data.size()));
        expected_offset += static_cast<int32_t>(files[i].data.size());
    }

    auto parsed = parse_pak(pak, "out.pak");
    ASSERT_TRUE(parsed.ok()) << parsed.error().to_string();
    EXPECT_TRUE(parsed->warnings.empty());
    ASSERT_EQ(parsed->entries.size(), files.size());
    for (size_t i = 0; i < files.size(); ++i) {
        EXPECT_EQ(parsed->entries[i].name, files[i].name);
        EXPECT_EQ(parsed->entries[i].size, files[i].data.size());
        auto data = pak_entry_bytes(pak, parsed->entries[i]);
        EXPECT_TRUE(
            std::equal(data.begin(), data.end(), files[i].data.begin(), files[i].data.end()))
            << files[i].name;
    }
}

TEST(PakFormat, EmptyPakIsJustAHeaderAndParsesWithAWarning) {
    auto written = write_pak({}, "empty.pak");
    ASSERT_TRUE(written.ok());
    EXPECT_EQ(*written, (std::vector<uint8_t>{'P', 'A', 'C', 'K', 12, 0, 0, 0, 0, 0, 0, 0}));
    auto parsed = parse_pak(*written, "empty.pak");
    ASSERT_TRUE(parsed.ok());
    EXPECT_TRUE(parsed->entries.empty());
    ASSERT_EQ(parsed->warnings.size(), 1u);
    EXPECT_NE(parsed->warnings[0].find("no entries"), std::string::npos);
}

TEST(PakFormat, ParsesPakFromTheIndependentWriter) {
    auto pak = build_pak({{"progs/player.mdl", "IDPO...."}, {"sound/a.wav", "RIFF"}});
    auto parsed = parse_pak(pak, "synth.pak");
    ASSERT_TRUE(parsed.ok()) << parsed.error().to_string();
    ASSERT_EQ(parsed->entries.size(), 2u);
    EXPECT_EQ(parsed->header.dir_offset, 12u + 8 + 4);
    EXPECT_EQ(parsed->header.entry_count(), 2u);
    EXPECT_EQ(parsed->entries[0].name, "progs/player.mdl");
    EXPECT_EQ(parsed->entries[0].offset, 12u);
    EXPECT_EQ(parsed->entries[1].offset, 20u);
    EXPECT_EQ(text_of(pak_entry_bytes(pak, parsed->entries[1])), "RIFF");
}

TEST(PakFormat, BytesAfterTheNameTerminatorAreIgnored) {
    auto pak = build_raw_pak(pak_with("data", {{std::string("a.txt\0garbage", 13), 12, 4}}));
    auto parsed = parse_pak(pak, "junk.pak");
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(parsed->entries.at(0).name, "a.txt");
}

TEST(PakFormat, EntriesMaySharePayloadAndBeEmpty) {
    auto pak = build_raw_pak(pak_with("shared", {{"one", 12, 6}, {"two", 12, 6}, {"none", 18, 0}}));
    auto parsed = parse_pak(pak, "shared.pak");
    ASSERT_TRUE(parsed.ok());
    ASSERT_EQ(parsed->entries.size(), 3u);
    EXPECT_EQ(text_of(pak_entry_bytes(pak, parsed->entries[1])), "shared");
    EXPECT_EQ(parsed->entries[2].size, 0u);
}

// ---------------------------------------------------------------------------------------------
// Malformed headers

TEST(PakMalformed, FileTooSmallForHeader) {
    Error e = parse_error({'P', 'A', 'C', 'K', 0, 0, 0, 0});
    EXPECT_EQ(e.file, "bad.pak");
    EXPECT_EQ(e.offset, 0u);
    EXPECT_NE(e.message.find("too small"), std::string::npos) << e.message;
}

TEST(PakMalformed, BadMagic) {
    RawPak pak;
    pak.magic = "PAKK";
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 0u);
    EXPECT_NE(e.message.find("bad magic 'PAKK'"), std::string::npos) << e.message;
}

TEST(PakMalformed, NegativeDirectoryOffset) {
    RawPak pak;
    pak.dir_offset = -12;
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 4u);
    EXPECT_NE(e.message.find("negative directory offset -12"), std::string::npos) << e.message;
}

TEST(PakMalformed, NegativeDirectoryLength) {
    RawPak pak;
    pak.dir_length = -64;
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 8u);
    EXPECT_NE(e.message.find("negative directory length -64"), std::string::npos) << e.message;
}

TEST(PakMalformed, DirectoryBeyondEndOfFile) {
    RawPak pak = pak_with("abcd", {{"a", 12, 4}});  // file is 12 + 4 + 64 = 80 bytes
    pak.dir_offset = 1000;
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 4u);
    EXPECT_NE(e.message.find("directory [1000, +64) extends past end of file (size 80)"),
              std::string::npos)
        << e.message;
}

TEST(PakMalformed, DirectoryLengthRunsPastEndOfFile) {
    RawPak pak = pak_with("abcd", {{"a", 12, 4}});
    pak.dir_length = 128;
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 4u);
    EXPECT_NE(e.message.find("[16, +128) extends past end of file"), std::string::npos)
        << e.message;
}

TEST(PakMalformed, DirectoryLengthNotAMultipleOf64) {
    RawPak pak = pak_with("abcd", {{"a", 12, 4}});
    pak.dir_length = 63;
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 8u);
    EXPECT_NE(e.message.find("63 is not a multiple of the 64-byte entry size"), std::string::npos)
        << e.message;
}

TEST(PakMalformed, DirectoryOverlappingTheHeader) {
    RawPak pak = pak_with(std::string(64, 'x'), {});
    pak.dir_offset = 4;
    pak.dir_length = 64;
    Error e = parse_error(build_raw_pak(pak));
    EXPECT_EQ(e.offset, 4u);
    EXPECT_NE(e.message.find("overlaps the 12-byte header"), std::string::npos) << e.message;
}

TEST(PakMalformed, EntryCountIsCappedBeforeAnythingIsRead) {
    // A header alone, claiming one entry more than the cap inside a (pretend) huge file.
    RawPak pak;
    pak.dir_offset = 12;
    pak.dir_length = static_cast<int32_t>((kPakMaxEntries + 1) * 64);
    auto header = build_raw_pak(pak);
    auto r = parse_pak_header(header, uint64_t{1} << 31, "huge.pak");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().offset, 8u);
    EXPECT_NE(r.error().message.find("over the limit"), std::string::npos) << r.error().message;
}

TEST(PakMalformed, DirectoryBytesNotMatchingTheHeader) {
    PakHeader header{12, 64};
    std::vector<uint8_t> dir(32);
    auto r = parse_pak_directory(dir, header, 1000, "x.pak");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().offset, 12u);
    EXPECT_NE(r.error().message.find("the header says 64"), std::string::npos);
}

TEST(PakMalformed, EveryTruncationOfAValidPakIsRejectedCleanly) {
    auto pak = build_pak({{"a.txt", "hello"}, {"b/c.txt", "world!"}});
    for (size_t len = 0; len < pak.size(); ++len) {
        std::vector<uint8_t> cut(pak.begin(), pak.begin() + static_cast<long>(len));
        auto r = parse_pak(cut, "cut.pak");
        EXPECT_FALSE(r.ok()) << "prefix of " << len << " bytes was accepted";
    }
}

// ---------------------------------------------------------------------------------------------
// Malformed entries. The directory of pak_with(payload, ...) starts at 12 + payload size.

TEST(PakMalformed, EntryDataBeyondEndOfFile) {
    auto pak = build_raw_pak(pak_with("abcd", {{"ok", 12, 4}, {"maps/big.bsp", 12, 1000}}));
    Error e = parse_error(pak);
    size_t second_record = 16 + 64;
    EXPECT_EQ(e.offset, second_record + 56);  // the entry's offset field
    EXPECT_NE(e.message.find("entry 1 'maps/big.bsp': data [12, +1000) extends past end of file "
                             "(size 144)"),
              std::string::npos)
        << e.message;
}

TEST(PakMalformed, EntryRangeThatWouldOverflowInt32) {
    auto max = std::numeric_limits<int32_t>::max();
    Error e = parse_error(build_raw_pak(pak_with("", {{"x", max, max}})));
    EXPECT_EQ(e.offset, 12u + 56);
    EXPECT_NE(e.message.find("extends past end of file"), std::string::npos) << e.message;
}

TEST(PakMalformed, NegativeEntryOffset) {
    Error e = parse_error(build_raw_pak(pak_with("abcd", {{"a", -1, 4}})));
    EXPECT_EQ(e.offset, 16u + 56);
    EXPECT_NE(e.message.find("entry 0 'a': negative data offset -1"), std::string::npos)
        << e.message;
}

TEST(PakMalformed, NegativeEntryLength) {
    Error e = parse_error(build_raw_pak(pak_with("abcd", {{"a", 12, -4}})));
    EXPECT_EQ(e.offset, 16u + 60);
    EXPECT_NE(e.message.find("entry 0 'a': negative data length -4"), std::string::npos)
        << e.message;
}

TEST(PakMalformed, UnterminatedName) {
    std::string name(56, 'q');
    Error e = parse_error(build_raw_pak(pak_with("abcd", {{"a", 12, 4}, {name, 12, 4}})));
    EXPECT_EQ(e.offset, 16u + 64);
    EXPECT_NE(e.message.find("entry 1: name '" + name + "' is not NUL-terminated"),
              std::string::npos)
        << e.message;
}

TEST(PakMalformed, EmptyName) {
    Error e = parse_error(build_raw_pak(pak_with("abcd", {{"", 12, 4}})));
    EXPECT_EQ(e.offset, 16u);
    EXPECT_NE(e.message.find("entry 0: empty name"), std::string::npos) << e.message;
}

TEST(PakMalformed, UnsafeNamesAreLeftOutWithWarningsNamingTheEntryOffset) {
    auto pak = build_raw_pak(pak_with("abcd", {{"../../etc/passwd", 12, 4},
                                               {"ok.txt", 12, 4},
                                               {"/abs/file", 12, 4},
                                               {"maps/../../x", 12, 4},
                                               {"C:evil", 12, 4},
                                               {"a/./b", 12, 4}}));
    auto parsed = parse_pak(pak, "evil.pak");
    ASSERT_TRUE(parsed.ok()) << parsed.error().to_string();
    ASSERT_EQ(parsed->entries.size(), 1u);
    EXPECT_EQ(parsed->entries[0].name, "ok.txt");
    EXPECT_EQ(parsed->unsafe_entries, 5u);
    ASSERT_EQ(parsed->warnings.size(), 5u);
    EXPECT_NE(parsed->warnings[0].find("entry 0 '../../etc/passwd' at offset 16: unsafe name "
                                       "('..' path component)"),
              std::string::npos)
        << parsed->warnings[0];
    EXPECT_NE(parsed->warnings[1].find("at offset 144: unsafe name (absolute path)"),
              std::string::npos)
        << parsed->warnings[1];
    EXPECT_NE(parsed->warnings[2].find("'maps/../../x' at offset 208"), std::string::npos);
    EXPECT_NE(parsed->warnings[3].find("drive-letter"), std::string::npos);
    EXPECT_NE(parsed->warnings[4].find("'.' path component"), std::string::npos);
}

TEST(PakMalformed, BackslashTraversalIsCaughtAfterNormalisation) {
    auto parsed = parse_pak(build_raw_pak(pak_with("abcd", {{"..\\..\\x.txt", 12, 4}})), "b.pak");
    ASSERT_TRUE(parsed.ok());
    EXPECT_TRUE(parsed->entries.empty());
    EXPECT_EQ(parsed->unsafe_entries, 1u);
}

TEST(PakFormat, BackslashesAreNormalisedWithAWarning) {
    auto parsed = parse_pak(build_pak({{"sound\\misc\\h2o.wav", "RIFF"}}), "b.pak");
    ASSERT_TRUE(parsed.ok());
    ASSERT_EQ(parsed->entries.size(), 1u);
    EXPECT_EQ(parsed->entries[0].name, "sound/misc/h2o.wav");
    ASSERT_EQ(parsed->warnings.size(), 1u);
    EXPECT_NE(parsed->warnings[0].find("backslashes"), std::string::npos);
}

TEST(PakFormat, DuplicateNamesIgnoringCaseLaterEntryWinsWithAWarning) {
    auto pak = build_pak({{"a.cfg", "first"}, {"other", "o"}, {"A.CFG", "second"}});
    auto parsed = parse_pak(pak, "dup.pak");
    ASSERT_TRUE(parsed.ok());
    ASSERT_EQ(parsed->entries.size(), 2u);
    EXPECT_EQ(parsed->entries[0].name, "A.CFG");
    EXPECT_EQ(text_of(pak_entry_bytes(pak, parsed->entries[0])), "second");
    ASSERT_EQ(parsed->warnings.size(), 1u);
    // The later record is the third one: 12 + 12 payload bytes + 2 * 64.
    EXPECT_NE(parsed->warnings[0].find("entry 2 'A.CFG' at offset 152: duplicate"),
              std::string::npos)
        << parsed->warnings[0];
}

// ---------------------------------------------------------------------------------------------
// Names and the writer

TEST(PakNames, SafeAndUnsafeNames) {
    EXPECT_EQ(pak_name_problem("maps/start.bsp"), "");
    EXPECT_EQ(pak_name_problem("a..b/c...d"), "");  // dots inside a component are fine
    EXPECT_EQ(pak_name_problem(""), "empty name");
    EXPECT_EQ(pak_name_problem("/etc/passwd"), "absolute path");
    EXPECT_EQ(pak_name_problem("c:/x"), "drive-letter path");
    EXPECT_EQ(pak_name_problem(".."), "'..' path component");
    EXPECT_EQ(pak_name_problem("a/../b"), "'..' path component");
    EXPECT_EQ(pak_name_problem("a/.."), "'..' path component");
    EXPECT_EQ(pak_name_problem("./a"), "'.' path component");
    EXPECT_EQ(pak_name_problem("a//b"), "empty path component");
    EXPECT_EQ(pak_name_problem("dir/"), "empty path component");
    EXPECT_EQ(pak_name_problem("a\\b"), "contains a backslash");
    EXPECT_EQ(pak_name_problem("a\nb"), "contains a control character");
}

TEST(PakWriter, AcceptsA55ByteNameAndRejectsA56ByteOne) {
    std::vector<PakFile> ok = {{std::string(55, 'a'), {}}};
    EXPECT_TRUE(write_pak(ok, "ok.pak").ok());
    std::vector<PakFile> too_long = {{std::string(56, 'a'), {}}};
    auto r = write_pak(too_long, "long.pak");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, "long.pak");
    EXPECT_NE(r.error().message.find("name is 56 bytes, over the pak limit of 55"),
              std::string::npos)
        << r.error().message;
}

TEST(PakWriter, RejectsUnsafeEmptyAndDuplicateNames) {
    auto message = [](std::vector<PakFile> files) {
        auto r = write_pak(files, "w.pak");
        return r.ok() ? std::string("accepted") : r.error().message;
    };
    EXPECT_NE(message({{"../x", {}}}).find("'..' path component"), std::string::npos);
    EXPECT_NE(message({{"", {}}}).find("empty name"), std::string::npos);
    EXPECT_NE(message({{"a\\b", {}}}).find("backslash"), std::string::npos);
    EXPECT_NE(message({{"Maps/A.bsp", {}}, {"maps/a.BSP", {}}})
                  .find("entry 1 'maps/a.BSP': same name (ignoring case) as entry 0"),
              std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Real data: LibreQuake ships loose files, so pack some and read them back from disk.

TEST(PakRealData, PackedGameFilesReadBackIdenticallyFromDisk) {
    std::string lq1 = test::lq1_dir();
    std::vector<PakFile> files;
    for (std::string name : {"gfx/palette.lmp", "maps/start.bsp"}) {
        auto bytes = read_file(lq1 + "/" + name);
        ASSERT_TRUE(bytes.ok()) << bytes.error().to_string();
        files.push_back({name, std::move(bytes.value())});
    }
    ASSERT_EQ(files[0].data.size(), 768u);  // 256 RGB triplets
    auto pak = write_pak(files, "real.pak");
    ASSERT_TRUE(pak.ok());
    test::TempGameTree tree;
    tree.write_bytes("real.pak", *pak);

    auto archive = PakArchive::open(tree.path("real.pak"));
    ASSERT_TRUE(archive.ok()) << archive.error().to_string();
    ASSERT_EQ(archive->entries().size(), 2u);
    for (size_t i = 0; i < files.size(); ++i) {
        EXPECT_EQ(archive->entries()[i].name, files[i].name);
        auto data = archive->read(archive->entries()[i]);
        ASSERT_TRUE(data.ok()) << data.error().to_string();
        EXPECT_EQ(*data, files[i].data) << files[i].name;
    }
    // BSP version 29 or a BSP2 magic opens a real map; the bytes came through unchanged.
    const auto& bsp = files[1].data;
    int32_t version = read_le32(bsp, 0);
    EXPECT_TRUE(version == 29 || text_of({bsp.data(), 4}) == "BSP2") << version;
}

// ---------------------------------------------------------------------------------------------
// The `pak` tool (bin/pak, found through NQ_BIN_DIR which ctest sets)

struct RunResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// The tool's stdout and stderr together.
RunResult run_pak(const std::vector<std::string>& args) {
    const test::ProcessResult run = test::run_tool("pak", args);
    return {run.exit_code, run.out + run.err};
}

std::string file_text(const std::string& path) {
    auto bytes = read_file(path);
    return bytes.ok() ? text_of(*bytes) : "<missing " + path + ">";
}

TEST(PakCli, CreateListAndExtractRoundTrip) {
    test::TempGameTree tree;
    std::vector<std::pair<std::string, std::string>> files = {
        {"readme.txt", "hello"},
        {"maps/E1M1.bsp", std::string("\x1d\0\0\0binary", 10)},
        {"a/b/c/deep.txt", "deep"},
        {"gfx/palette.lmp", std::string(768, '\x42')},
    };
    for (const auto& [name, content] : files) tree.write("src/" + name, content);

    RunResult created = run_pak({"create", tree.path("out.pak"), tree.path("src")});
    ASSERT_EQ(created.exit_code, 0) << created.output;

    // The pak holds the files sorted by name (byte order), '/'-separated, data intact.
    auto pak = read_file(tree.path("out.pak"));
    ASSERT_TRUE(pak.ok());
    auto parsed = parse_pak(*pak, "out.pak");
    ASSERT_TRUE(parsed.ok()) << parsed.error().to_string();
    std::vector<std::string> names;
    for (const PakEntry& e : parsed->entries) names.push_back(e.name);
    EXPECT_EQ(names, (std::vector<std::string>{"a/b/c/deep.txt", "gfx/palette.lmp", "maps/E1M1.bsp",
                                               "readme.txt"}));
    for (const auto& [name, content] : files) {
        auto it = std::find(names.begin(), names.end(), name);
        ASSERT_NE(it, names.end());
        EXPECT_EQ(text_of(pak_entry_bytes(*pak, parsed->entries[it - names.begin()])), content);
    }

    RunResult listed = run_pak({"list", tree.path("out.pak")});
    ASSERT_EQ(listed.exit_code, 0) << listed.output;
    for (const auto& [name, content] : files) {
        EXPECT_NE(listed.output.find(name), std::string::npos) << name;
    }
    EXPECT_NE(listed.output.find("       768  gfx/palette.lmp"), std::string::npos);
    EXPECT_NE(listed.output.find("4 files, 787 bytes"), std::string::npos) << listed.output;

    RunResult json = run_pak({"list", "--json", tree.path("out.pak")});
    ASSERT_EQ(json.exit_code, 0) << json.output;
    EXPECT_NE(json.output.find("\"name\": \"maps/E1M1.bsp\""), std::string::npos) << json.output;
    EXPECT_NE(json.output.find("\"count\": 4"), std::string::npos);
    EXPECT_NE(json.output.find("\"total_size\": 787"), std::string::npos);

    RunResult extracted = run_pak({"extract", tree.path("out.pak"), tree.path("all")});
    ASSERT_EQ(extracted.exit_code, 0) << extracted.output;
    for (const auto& [name, content] : files) {
        EXPECT_EQ(file_text(tree.path("all/" + name)), content) << name;
    }

    RunResult one = run_pak({"extract", tree.path("out.pak"), tree.path("one"), "maps/e1m1.bsp"});
    ASSERT_EQ(one.exit_code, 0) << one.output;
    EXPECT_EQ(file_text(tree.path("one/maps/E1M1.bsp")), files[1].second);
    EXPECT_FALSE(std::filesystem::exists(tree.path("one/readme.txt")));
}

TEST(PakCli, CreateLeavesOutTheOutputPakWhenItLiesInsideTheTree) {
    test::TempGameTree tree;
    tree.write("src/a.txt", "a");
    ASSERT_EQ(run_pak({"create", tree.path("src/self.pak"), tree.path("src")}).exit_code, 0);
    // Run twice: the second run sees self.pak in the tree and must skip it.
    RunResult again = run_pak({"create", tree.path("src/self.pak"), tree.path("src")});
    ASSERT_EQ(again.exit_code, 0) << again.output;
    auto parsed = parse_pak(read_file(tree.path("src/self.pak")).value(), "self.pak");
    ASSERT_TRUE(parsed.ok());
    ASSERT_EQ(parsed->entries.size(), 1u);
    EXPECT_EQ(parsed->entries[0].name, "a.txt");
}

TEST(PakCli, CreateRejectsANameOver55Bytes) {
    test::TempGameTree tree;
    std::string long_name = "maps/" + std::string(47, 'x') + ".bsp";  // 56 bytes
    tree.write("src/" + long_name, "x");
    RunResult r = run_pak({"create", tree.path("out.pak"), tree.path("src")});
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_NE(r.output.find("name is 56 bytes, pak names are at most 55"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(tree.path("out.pak")));
}

TEST(PakCli, ExtractRefusesTraversalNamesAndWritesNothingOutside) {
    test::TempGameTree tree;
    tree.write_pak("evil.pak", {{"../escape.txt", "x"}, {"ok.txt", "fine"}, {"/tmp/abs", "y"}});
    RunResult r = run_pak({"extract", tree.path("evil.pak"), tree.path("out")});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("'../escape.txt' at offset"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("refused 2 entries with unsafe names"), std::string::npos);
    EXPECT_EQ(file_text(tree.path("out/ok.txt")), "fine");
    EXPECT_FALSE(std::filesystem::exists(tree.path("escape.txt")));
}

TEST(PakCli, ExtractDoesNotFollowASymlinkOutOfTheTargetDir) {
    test::TempGameTree tree;
    tree.make_dir("outside");
    tree.make_dir("out");
    std::filesystem::create_directory_symlink(tree.path("outside"), tree.path("out/maps"));
    tree.write_pak("p.pak", {{"maps/x.bsp", "x"}});
    RunResult r = run_pak({"extract", tree.path("p.pak"), tree.path("out")});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("refusing to extract 'maps/x.bsp'"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(tree.path("outside/x.bsp")));
}

TEST(PakCli, ErrorsAndUsage) {
    test::TempGameTree tree;
    RunResult none = run_pak({});
    EXPECT_EQ(none.exit_code, 2);
    EXPECT_NE(none.output.find("usage: pak"), std::string::npos);
    EXPECT_EQ(run_pak({"frobnicate", "x"}).exit_code, 2);
    EXPECT_EQ(run_pak({"list", "a.pak", "b.pak"}).exit_code, 2);
    EXPECT_EQ(run_pak({"list", "--bogus", "a.pak"}).exit_code, 2);
    EXPECT_EQ(run_pak({"create", "only-one-arg"}).exit_code, 2);
    RunResult help = run_pak({"--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("pak create OUT.pak DIR"), std::string::npos);

    RunResult missing = run_pak({"list", tree.path("nope.pak")});
    EXPECT_EQ(missing.exit_code, 1);
    EXPECT_NE(missing.output.find("cannot open"), std::string::npos) << missing.output;

    RawPak bad = pak_with("abcd", {{"a", 12, 400}});
    tree.write_bytes("bad.pak", build_raw_pak(bad));
    RunResult corrupt = run_pak({"list", tree.path("bad.pak")});
    EXPECT_EQ(corrupt.exit_code, 1);
    EXPECT_NE(corrupt.output.find("bad.pak: offset 72: entry 0 'a': data [12, +400)"),
              std::string::npos)
        << corrupt.output;

    tree.write_pak("good.pak", {{"a.txt", "a"}});
    RunResult absent = run_pak({"extract", tree.path("good.pak"), tree.path("o"), "b.txt"});
    EXPECT_EQ(absent.exit_code, 1);
    EXPECT_NE(absent.output.find("b.txt (nothing extracted)"), std::string::npos) << absent.output;
    EXPECT_FALSE(std::filesystem::exists(tree.path("o/a.txt")));
}

}  // namespace
}  // namespace nq
