// The virtual filesystem: override order, case-insensitive lookup, errors, listing, rescans,
// pak archives on disk, and mounting the real LibreQuake data.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "common/file_io.h"
#include "fs/pak_archive.h"
#include "fs/vfs.h"
#include "fs/vfs_path.h"
#include "support/raw_bytes.h"
#include "support/synth_pak.h"
#include "support/test_data.h"

namespace nq {
namespace {

using test::TempGameTree;

std::string text_of(const std::vector<uint8_t>& b) {
    return std::string(b.begin(), b.end());
}

std::string read_text(const Vfs& vfs, std::string_view path) {
    auto r = vfs.read(path);
    return r.ok() ? text_of(*r) : "<error: " + r.error().to_string() + ">";
}

Vfs mount_or_die(const VfsConfig& config) {
    auto r = Vfs::mount(config);
    if (!r.ok()) throw std::runtime_error(r.error().to_string());
    return std::move(r.value());
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

// base/id1: pak0 and pak1 plus loose files; base/mod: a pak and loose files of its own.
class VfsOverrides : public ::testing::Test {
  protected:
    void SetUp() override {
        tree.write_pak("base/id1/pak0.pak", {{"a.txt", "id1 pak0"},
                                             {"b.txt", "id1 pak0"},
                                             {"c.txt", "id1 pak0"},
                                             {"only0.txt", "id1 pak0"},
                                             {"maps/e1m1.bsp", "id1 pak0"}});
        tree.write_pak("base/id1/pak1.pak", {{"a.txt", "id1 pak1"}, {"b.txt", "id1 pak1"}});
        tree.write("base/id1/b.txt", "id1 loose");
        tree.write("base/id1/maps/e1m2.bsp", "id1 loose");
        tree.write_pak("base/mod/pak0.pak", {{"c.txt", "mod pak0"}, {"maps/e1m3.bsp", "mod"}});
        tree.write("base/mod/b.txt", "mod loose");
    }
    VfsConfig id1_only() const { return VfsConfig::for_game(tree.path("base")); }
    VfsConfig with_mod() const { return VfsConfig::for_game(tree.path("base"), "mod"); }

    TempGameTree tree;
};

TEST_F(VfsOverrides, LaterPakOverridesEarlierPak) {
    Vfs vfs = mount_or_die(id1_only());
    EXPECT_EQ(read_text(vfs, "a.txt"), "id1 pak1");
    EXPECT_EQ(read_text(vfs, "only0.txt"), "id1 pak0");
}

TEST_F(VfsOverrides, LooseFileOverridesThePaksOfItsGameDir) {
    Vfs vfs = mount_or_die(id1_only());
    EXPECT_EQ(read_text(vfs, "b.txt"), "id1 loose");
}

TEST_F(VfsOverrides, ModOverridesBaseGameEntirelyEvenFromItsPak) {
    Vfs vfs = mount_or_die(with_mod());
    EXPECT_EQ(read_text(vfs, "b.txt"), "mod loose");
    EXPECT_EQ(read_text(vfs, "c.txt"), "mod pak0");  // mod's pak beats id1's files
    EXPECT_EQ(read_text(vfs, "a.txt"), "id1 pak1");  // not in the mod: falls through
}

TEST_F(VfsOverrides, LocateNamesTheProvider) {
    Vfs vfs = mount_or_die(with_mod());
    auto c = vfs.locate("C.TXT");
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->path, "c.txt");
    EXPECT_EQ(c->kind, SourceKind::Pak);
    EXPECT_EQ(c->game, "mod");
    EXPECT_EQ(c->container, tree.path("base/mod") + "/pak0.pak");
    EXPECT_EQ(c->size, 8u);
    EXPECT_EQ(c->offset, 12u);  // first entry's data follows the header
    EXPECT_EQ(c->describe(), tree.path("base/mod") + "/pak0.pak:c.txt");

    auto e2 = vfs.locate("maps/e1m2.bsp");
    ASSERT_TRUE(e2.has_value());
    EXPECT_EQ(e2->kind, SourceKind::Directory);
    EXPECT_EQ(e2->game, "id1");
    EXPECT_EQ(e2->host_path(), tree.path("base/id1") + "/maps/e1m2.bsp");
    EXPECT_EQ(e2->size, 9u);

    EXPECT_FALSE(vfs.locate("nothing.here").has_value());
}

TEST_F(VfsOverrides, SearchPathsAreListedHighestPriorityFirst) {
    Vfs vfs = mount_or_die(with_mod());
    auto paths = vfs.search_paths();
    ASSERT_EQ(paths.size(), 5u);
    std::string id1 = tree.path("base/id1"), mod = tree.path("base/mod");
    EXPECT_EQ(paths[0].host_path, mod);
    EXPECT_EQ(paths[0].kind, SourceKind::Directory);
    EXPECT_EQ(paths[1].host_path, mod + "/pak0.pak");
    EXPECT_EQ(paths[1].file_count, 2u);
    EXPECT_EQ(paths[2].host_path, id1);
    EXPECT_EQ(paths[3].host_path, id1 + "/pak1.pak");
    EXPECT_EQ(paths[4].host_path, id1 + "/pak0.pak");
    EXPECT_EQ(paths[4].game, "id1");
    EXPECT_EQ(paths[4].describe(), id1 + "/pak0.pak (5 files)");
}

TEST_F(VfsOverrides, ListFiltersByDirectoryAndExtensionAcrossAllSources) {
    Vfs vfs = mount_or_die(with_mod());
    std::vector<std::string> maps = {"maps/e1m1.bsp", "maps/e1m2.bsp", "maps/e1m3.bsp"};
    EXPECT_EQ(vfs.list("maps", "bsp"), maps);
    EXPECT_EQ(vfs.list("MAPS/", ".BSP"), maps);
    EXPECT_EQ(vfs.list("", "*.bsp"), maps);
    EXPECT_TRUE(vfs.list("map", "bsp").empty());  // a directory, not a string prefix
    // Every name once, though a.txt/b.txt/c.txt exist in several sources; paks are files too.
    EXPECT_EQ(vfs.list("", "txt"),
              (std::vector<std::string>{"a.txt", "b.txt", "c.txt", "only0.txt"}));
    EXPECT_EQ(vfs.list("", "pak"), (std::vector<std::string>{"pak0.pak", "pak1.pak"}));
    EXPECT_EQ(vfs.file_count(), 4u + 3u + 2u);
}

TEST_F(VfsOverrides, NotFoundErrorListsWhereItLooked) {
    Vfs vfs = mount_or_die(with_mod());
    auto r = vfs.read("maps/e9m9.bsp");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, "maps/e9m9.bsp");
    const std::string& m = r.error().message;
    EXPECT_TRUE(contains(m, "not found: maps/e9m9.bsp")) << m;
    EXPECT_TRUE(contains(m, tree.path("base/mod") + "/pak0.pak")) << m;
    EXPECT_TRUE(contains(m, tree.path("base/id1") + "/, ")) << m;
    EXPECT_FALSE(vfs.exists("maps/e9m9.bsp"));
    EXPECT_FALSE(vfs.exists("../id1/b.txt"));
}

TEST_F(VfsOverrides, SeveralInstancesAreIndependent) {
    Vfs plain = mount_or_die(id1_only());
    Vfs modded = mount_or_die(with_mod());
    EXPECT_EQ(read_text(plain, "c.txt"), "id1 pak0");
    EXPECT_EQ(read_text(modded, "c.txt"), "mod pak0");
    Vfs moved = std::move(plain);  // pak handles move along
    EXPECT_EQ(read_text(moved, "a.txt"), "id1 pak1");
}

TEST_F(VfsOverrides, RescanPicksUpNewAndRemovedLooseFiles) {
    Vfs vfs = mount_or_die(with_mod());
    tree.write("base/mod/maps/new.bsp", "new");
    EXPECT_FALSE(vfs.exists("maps/new.bsp"));
    std::filesystem::remove(tree.path("base/mod/b.txt"));
    auto count = vfs.rescan();
    ASSERT_TRUE(count.ok()) << count.error().to_string();
    EXPECT_EQ(*count, vfs.file_count());
    EXPECT_EQ(read_text(vfs, "maps/new.bsp"), "new");
    EXPECT_EQ(read_text(vfs, "b.txt"), "id1 loose");  // the mod's copy is gone
}

// ---------------------------------------------------------------------------------------------
// Case and separators

TEST(VfsNames, LookupsIgnoreCaseAndSeparatorStyle) {
    TempGameTree tree;
    tree.write("base/id1/MAPS/START.BSP", "loose upper");
    tree.write_pak("base/id1/PAK0.PAK", {{"PROGS/Player.mdl", "from pak"}});
    Vfs vfs = mount_or_die(VfsConfig::for_game(tree.path("base")));
    EXPECT_EQ(read_text(vfs, "maps/start.bsp"), "loose upper");
    EXPECT_EQ(read_text(vfs, "Maps\\Start.Bsp"), "loose upper");
    EXPECT_EQ(read_text(vfs, "./maps//start.bsp"), "loose upper");
    EXPECT_EQ(read_text(vfs, "progs/player.mdl"), "from pak");  // uppercase pak name found too
    auto info = vfs.locate("progs/PLAYER.MDL");
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->name, "PROGS/Player.mdl");  // stored case is kept for display
    EXPECT_EQ(vfs.list("maps", "bsp"), std::vector<std::string>{"maps/start.bsp"});
}

TEST(VfsNames, NormalizeVfsPath) {
    EXPECT_EQ(normalize_vfs_path("Maps\\E1M1.BSP"), "maps/e1m1.bsp");
    EXPECT_EQ(normalize_vfs_path("/./a//b/"), "a/b");
    EXPECT_EQ(normalize_vfs_path("../x"), "../x");  // kept, so it can never match
    EXPECT_EQ(normalize_extension("BSP"), ".bsp");
    EXPECT_EQ(normalize_extension("*.Dem"), ".dem");
    EXPECT_EQ(normalize_extension(""), "");
}

TEST(VfsNames, CaseTwinLooseFilesKeepOneWithAWarning) {
    TempGameTree tree;
    tree.write("base/id1/Autoexec.cfg", "upper");
    tree.write("base/id1/autoexec.cfg", "lower");
    Vfs vfs = mount_or_die(VfsConfig::for_game(tree.path("base")));
    EXPECT_EQ(read_text(vfs, "AUTOEXEC.CFG"), "upper");  // "Autoexec" sorts before "autoexec"
    auto warnings = vfs.warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(contains(warnings[0], "ignoring 'autoexec.cfg'")) << warnings[0];
}

// A game directory whose progs/ is a symbolic link to data kept elsewhere is read through it;
// a link back up the tree (a loop) is walked once, with a warning, not forever.
TEST(VfsNames, SymlinkedDirectoriesAreReadAndLoopsAreNotFollowed) {
    TempGameTree tree;
    tree.write("elsewhere/progs/player.mdl", "a model");
    tree.write("base/id1/maps/e1m1.bsp", "a map");
    std::filesystem::create_directory_symlink(tree.path("elsewhere/progs"),
                                              tree.path("base/id1/progs"));
    std::filesystem::create_directory_symlink(tree.path("base/id1"), tree.path("base/id1/maps/up"));
    Vfs vfs = mount_or_die(VfsConfig::for_game(tree.path("base")));
    EXPECT_EQ(read_text(vfs, "progs/player.mdl"), "a model");
    EXPECT_EQ(read_text(vfs, "maps/e1m1.bsp"), "a map");
    EXPECT_FALSE(vfs.read("maps/up/maps/e1m1.bsp").ok()) << "the loop was walked";
    bool warned = false;
    for (const std::string& w : vfs.warnings()) warned |= contains(w, "not following 'maps/up'");
    EXPECT_TRUE(warned);
}

TEST(VfsPaks, NumberedPaksStackInNumericNotLexicalOrder) {
    TempGameTree tree;
    tree.write_pak("base/id1/pak2.pak", {{"x.txt", "pak2"}});
    tree.write_pak("base/id1/pak10.pak", {{"x.txt", "pak10"}});
    tree.write_pak("base/id1/other.pak", {{"x.txt", "not a numbered pak"}});
    Vfs vfs = mount_or_die(VfsConfig::for_game(tree.path("base")));
    EXPECT_EQ(read_text(vfs, "x.txt"), "pak10");
    EXPECT_EQ(vfs.search_paths().size(), 3u);  // dir, pak10, pak2
}

TEST(VfsPaks, PakWarningsAreReportedAtMount) {
    TempGameTree tree;
    tree.write_pak("base/id1/pak0.pak", {{"../escape", "x"}, {"ok", "y"}});
    Vfs vfs = mount_or_die(VfsConfig::for_game(tree.path("base")));
    EXPECT_FALSE(vfs.exists("../escape"));
    EXPECT_FALSE(vfs.exists("escape"));
    EXPECT_TRUE(vfs.exists("ok"));
    auto warnings = vfs.warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(contains(warnings[0], "pak0.pak: entry 0 '../escape' at offset 14")) << warnings[0];
}

TEST(VfsPaks, CorruptPakFailsTheMountNamingPakAndOffset) {
    TempGameTree tree;
    auto pak = test::build_pak({{"a", "aaaa"}});
    test::poke_le32(pak, 12 + 4 + 60, 400);  // entry 0 length now runs past the end
    tree.write_bytes("base/id1/pak0.pak", pak);
    auto r = Vfs::mount(VfsConfig::for_game(tree.path("base")));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().file, tree.path("base/id1") + "/pak0.pak");
    EXPECT_EQ(r.error().offset, 16u + 56);
    EXPECT_TRUE(contains(r.error().message, "extends past end of file")) << r.error().message;
}

TEST(VfsPaks, ArchiveReadsEntriesOnDemandAndNoticesATruncatedFile) {
    TempGameTree tree;
    tree.write_pak("p.pak", {{"one", "11111"}, {"two", "22"}});
    auto pak = PakArchive::open(tree.path("p.pak"));
    ASSERT_TRUE(pak.ok()) << pak.error().to_string();
    EXPECT_EQ(pak->file_size(), 12u + 7 + 128);
    auto two = pak->read(pak->entries().at(1));
    ASSERT_TRUE(two.ok());
    EXPECT_EQ(text_of(*two), "22");
    std::filesystem::resize_file(tree.path("p.pak"), 14);  // cut inside entry "one"
    auto one = pak->read(pak->entries().at(0));
    ASSERT_FALSE(one.ok());
    EXPECT_EQ(one.error().offset, 12u);
    EXPECT_TRUE(contains(one.error().message, "file ends early")) << one.error().message;
}

TEST(VfsPaks, OpeningAMissingOrTinyPakFails) {
    TempGameTree tree;
    auto missing = PakArchive::open(tree.path("none.pak"));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(contains(missing.error().message, "cannot open")) << missing.error().message;
    tree.write("tiny.pak", "PACK");
    auto tiny = PakArchive::open(tree.path("tiny.pak"));
    ASSERT_FALSE(tiny.ok());
    EXPECT_TRUE(contains(tiny.error().message, "too small")) << tiny.error().message;
}

// ---------------------------------------------------------------------------------------------
// Mount errors

TEST(VfsMount, MissingBasedirIsAnErrorNamingIt) {
    TempGameTree tree;
    auto r = Vfs::mount(VfsConfig::for_game(tree.path("no-such-base")));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(
        contains(r.error().message, "base directory not found: " + tree.path("no-such-base")))
        << r.error().message;
}

TEST(VfsMount, MissingModDirIsAnErrorNamingThePath) {
    TempGameTree tree;
    tree.write("base/id1/a.txt", "a");
    auto r = Vfs::mount(VfsConfig::for_game(tree.path("base"), "nomod"));
    ASSERT_FALSE(r.ok());
    std::string expected = (std::filesystem::path(tree.path("base")) / "nomod").string();
    EXPECT_EQ(r.error().file, expected);
    EXPECT_TRUE(contains(r.error().message, "game directory not found: " + expected));
}

TEST(VfsMount, MissingId1AloneIsAnError) {
    TempGameTree tree;
    tree.make_dir("base");
    auto r = Vfs::mount(VfsConfig::for_game(tree.path("base")));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error().message, "game directory not found")) << r.error().message;
}

TEST(VfsMount, MissingId1UnderAModIsOnlyAWarning) {
    TempGameTree tree;
    tree.write("base/mod/a.txt", "a");
    auto r = Vfs::mount(VfsConfig::for_game(tree.path("base"), "mod"));
    ASSERT_TRUE(r.ok()) << r.error().to_string();
    EXPECT_EQ(read_text(*r, "a.txt"), "a");
    auto warnings = r->warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_TRUE(contains(warnings[0], "base game directory")) << warnings[0];
    EXPECT_EQ(r->search_paths().size(), 1u);
}

TEST(VfsMount, UnsafeOrDuplicateGameNamesAreRejected) {
    TempGameTree tree;
    tree.write("base/id1/a.txt", "a");
    VfsConfig escape{tree.path("base"), {"id1", "../elsewhere"}};
    auto r = Vfs::mount(escape);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(contains(r.error().message, "bad game dir name")) << r.error().message;
    VfsConfig twice{tree.path("base"), {"id1", "id1"}};
    EXPECT_FALSE(Vfs::mount(twice).ok());
    VfsConfig none{tree.path("base"), {}};
    EXPECT_FALSE(Vfs::mount(none).ok());
}

TEST(VfsMount, ForGameBuildsTheUsualStack) {
    EXPECT_EQ(VfsConfig::for_game("/q").games, (std::vector<std::string>{"id1"}));
    EXPECT_EQ(VfsConfig::for_game("/q", "lq1").games, (std::vector<std::string>{"id1", "lq1"}));
    EXPECT_EQ(VfsConfig::for_game("/q", "ID1").games, (std::vector<std::string>{"id1"}));
}

// ---------------------------------------------------------------------------------------------
// The real data: -basedir ../shared/data -game lq1 (LibreQuake, loose files, no id1 there)

TEST(VfsRealData, MountsLibreQuakeAsAModAndReadsItsFiles) {
    std::string lq1 = test::lq1_dir();
    Vfs vfs = mount_or_die(VfsConfig::for_game(test::data_root(), "lq1"));

    auto palette = vfs.read("gfx/palette.lmp");
    ASSERT_TRUE(palette.ok()) << palette.error().to_string();
    EXPECT_EQ(palette->size(), 768u);  // 256 RGB triplets
    EXPECT_EQ(*palette, read_file(lq1 + "/gfx/palette.lmp").value());

    auto start = vfs.read("MAPS/START.BSP");
    ASSERT_TRUE(start.ok()) << start.error().to_string();
    EXPECT_EQ(*start, read_file(lq1 + "/maps/start.bsp").value());
    auto info = vfs.locate("maps/start.bsp");
    ASSERT_TRUE(info.has_value());
    EXPECT_EQ(info->game, "lq1");
    EXPECT_EQ(info->size, start->size());

    // Every map on disk is listed, and nothing else.
    auto on_disk = test::lq1_files("maps", ".bsp");
    auto listed = vfs.list("maps", "bsp");
    ASSERT_EQ(listed.size(), on_disk.size());
    for (size_t i = 0; i < listed.size(); ++i) {
        std::string leaf = std::filesystem::path(on_disk[i]).filename().string();
        EXPECT_EQ(listed[i], normalize_vfs_path("maps/" + leaf));
    }

    // Whether or not an id1 exists beside lq1, mounting succeeded; without one we were told.
    bool has_id1 = std::filesystem::is_directory(test::data_root() + "/id1");
    bool warned = false;
    for (const std::string& w : vfs.warnings()) warned |= contains(w, "base game directory");
    EXPECT_EQ(warned, !has_id1);
}

}  // namespace
}  // namespace nq
