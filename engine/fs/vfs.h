// The virtual filesystem: every game file the engine reads comes through here.
//
// A Vfs is mounted from a base directory and a list of game dirs (id1, then a mod on top).
// Inside a game dir, the numbered paks pak0.pak, pak1.pak, ... are stacked in numeric order
// (a later pak overrides an earlier one) and the loose files of the dir override all of that
// dir's paks. A higher game dir overrides a lower one entirely, paks included.
//
// Names are case-insensitive and '/' or '\' separated. Everything is indexed at mount time in
// one hash map from lowercase path to provider, so a lookup never touches the disk; reading
// opens the loose file or preads the pak entry. A Vfs owns its pak file handles (no global
// state): several instances may coexist, and const member functions may be called from several
// threads at once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "common/result.h"
#include "fs/loose_index.h"
#include "fs/pak_archive.h"

namespace nq {

struct VfsConfig {
    std::string basedir = ".";
    // Game dirs under basedir, lowest priority first. The first one is the base game: when it
    // is missing but others are given, mounting continues with a warning (LibreQuake can be
    // run as "-game lq1" with no id1 present). Any other missing game dir is an error.
    std::vector<std::string> games = {"id1"};

    // The usual command-line setup: -basedir `basedir` [-game `mod`] -> id1 with mod on top.
    static VfsConfig for_game(std::string basedir, std::string_view mod = {});
};

enum class SourceKind { Directory, Pak };

// One place the Vfs searches, for the console's `path` command.
struct SearchPath {
    SourceKind kind = SourceKind::Directory;
    std::string game;       // the game dir it belongs to, e.g. "id1"
    std::string host_path;  // the pak file or the game dir on the host
    size_t file_count = 0;  // files it holds (including those overridden by others)

    std::string describe() const;  // "/q/id1/pak0.pak (339 files)" or "/q/id1/ (12 files)"
};

// Where a file comes from, for the console's `which` command and for diagnostics.
struct FileInfo {
    std::string path;  // the normalized lookup key, e.g. "maps/start.bsp"
    std::string name;  // the name in its source, case as stored on disk or in the pak
    SourceKind kind = SourceKind::Directory;
    std::string game;       // the game dir providing it
    std::string container;  // host path of the pak, or of the game dir
    uint64_t size = 0;      // bytes (for a loose file, as seen at the last scan)
    uint64_t offset = 0;    // data offset inside the pak; 0 for a loose file

    // The host file holding the data: the loose file itself, or the pak.
    std::string host_path() const;
    // "/q/lq1/maps/start.bsp" or "/q/id1/pak1.pak:maps/start.bsp".
    std::string describe() const;
};

class Vfs {
  public:
    // Fails with a message naming the path if basedir or a (non-base) game dir is missing, if
    // a game name is not a plain relative name, or if a numbered pak is corrupt (naming the pak
    // and the offset of the problem).
    static Result<Vfs> mount(const VfsConfig& config);

    // The bytes of a file; "not found: <path>" lists where it looked.
    Result<std::vector<uint8_t>> read(std::string_view path) const;
    bool exists(std::string_view path) const;
    std::optional<FileInfo> locate(std::string_view path) const;

    // Normalized paths (lowercase, '/'-separated) of all visible files under directory `dir`
    // ("" for everywhere; recursive) whose name ends with `extension` ("bsp", ".bsp" or ""),
    // sorted and without duplicates. E.g. list("maps", "bsp"), list("", "dem").
    std::vector<std::string> list(std::string_view dir = {}, std::string_view extension = {}) const;

    // Highest priority first, as Quake's `path` command prints them.
    std::vector<SearchPath> search_paths() const;

    // Walks the game dirs again to pick up loose files added or removed since mounting (paks
    // are not reopened). On failure the Vfs is left as it was. Returns the number of visible
    // files.
    Result<size_t> rescan();

    size_t file_count() const { return index_.size(); }
    const std::string& basedir() const { return basedir_; }
    // Non-fatal findings: a missing base game, pak oddities, case-twin loose files.
    std::vector<std::string> warnings() const;

  private:
    struct MountedGame {
        std::string name;
        std::string host_path;
        std::vector<PakArchive> paks;  // lowest priority first
        LooseScan loose;
    };
    // Which game dir, which of its paks (kLoose for a loose file), which entry.
    struct Location {
        uint32_t game = 0;
        int32_t pak = 0;
        uint32_t entry = 0;
    };
    static constexpr int32_t kLoose = -1;

    Vfs() = default;
    void build_index();
    const Location* find(std::string_view path) const;
    FileInfo describe(const std::string& key, const Location& at) const;
    std::string searched_places() const;

    std::string basedir_;
    std::vector<MountedGame> games_;  // lowest priority first
    std::unordered_map<std::string, Location> index_;
    std::vector<std::string> mount_warnings_;
};

}  // namespace nq
