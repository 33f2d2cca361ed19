#include "fs/vfs.h"

#include <algorithm>
#include <filesystem>

#include "common/file_io.h"
#include "formats/pak.h"
#include "fs/vfs_path.h"

namespace nq {

namespace fs = std::filesystem;

VfsConfig VfsConfig::for_game(std::string basedir, std::string_view mod) {
    VfsConfig config;
    config.basedir = std::move(basedir);
    if (!mod.empty() && normalize_vfs_path(mod) != "id1") config.games.emplace_back(mod);
    return config;
}

std::string SearchPath::describe() const {
    std::string where = kind == SourceKind::Pak ? host_path : host_path + "/";
    return where + " (" + std::to_string(file_count) + " files)";
}

std::string FileInfo::host_path() const {
    return kind == SourceKind::Pak ? container : container + "/" + name;
}

std::string FileInfo::describe() const {
    return kind == SourceKind::Pak ? container + ":" + name : host_path();
}

namespace {

// Mount-time checks of one game dir. Returns its host path, or an Error; an empty path means
// "skip it" (a missing base game under a mod), with a warning added.
Result<std::string> game_dir_path(const VfsConfig& config, size_t index,
                                  std::vector<std::string>& warnings) {
    const std::string& game = config.games[index];
    if (std::string problem = pak_name_problem(game); !problem.empty()) {
        return Error{game, 0, "bad game dir name '" + game + "': " + problem};
    }
    std::string path = (fs::path(config.basedir) / game).string();
    std::error_code ec;
    if (fs::is_directory(path, ec)) return path;
    bool is_base_under_mod = index == 0 && config.games.size() > 1;
    if (!is_base_under_mod) return Error{path, 0, "game directory not found: " + path};
    warnings.push_back("base game directory " + path + " not found; continuing without it");
    return std::string();
}

std::string check_config(const VfsConfig& config) {
    std::error_code ec;
    if (!fs::is_directory(config.basedir, ec)) {
        return "base directory not found: " + config.basedir;
    }
    if (config.games.empty()) return "no game directory given";
    for (size_t i = 0; i < config.games.size(); ++i) {
        for (size_t j = 0; j < i; ++j) {
            if (config.games[i] == config.games[j]) {
                return "game directory '" + config.games[i] + "' given twice";
            }
        }
    }
    return {};
}

}  // namespace

Result<Vfs> Vfs::mount(const VfsConfig& config) {
    if (std::string problem = check_config(config); !problem.empty()) {
        return Error{config.basedir, 0, problem};
    }
    Vfs vfs;
    vfs.basedir_ = config.basedir;
    for (size_t i = 0; i < config.games.size(); ++i) {
        auto path = game_dir_path(config, i, vfs.mount_warnings_);
        if (!path) return path.error();
        if (path->empty()) continue;
        auto scan = scan_loose_files(*path);
        if (!scan) return scan.error();
        MountedGame game{config.games[i], *path, {}, std::move(scan.value())};
        for (const LooseFile* pak_file : numbered_paks(game.loose)) {
            auto pak = PakArchive::open(*path + "/" + pak_file->relative);
            if (!pak) return pak.error();
            for (const std::string& w : pak->warnings()) {
                vfs.mount_warnings_.push_back(pak->path() + ": " + w);
            }
            game.paks.push_back(std::move(pak.value()));
        }
        vfs.games_.push_back(std::move(game));
    }
    vfs.build_index();
    return vfs;
}

// Later insertions overwrite earlier ones, so inserting from the lowest priority source to the
// highest leaves each key pointing at the file that wins.
void Vfs::build_index() {
    index_.clear();
    for (size_t g = 0; g < games_.size(); ++g) {
        const MountedGame& game = games_[g];
        for (size_t p = 0; p < game.paks.size(); ++p) {
            const auto& entries = game.paks[p].entries();
            for (size_t e = 0; e < entries.size(); ++e) {
                index_[normalize_vfs_path(entries[e].name)] = Location{
                    static_cast<uint32_t>(g), static_cast<int32_t>(p), static_cast<uint32_t>(e)};
            }
        }
        for (size_t e = 0; e < game.loose.files.size(); ++e) {
            index_[game.loose.files[e].key] =
                Location{static_cast<uint32_t>(g), kLoose, static_cast<uint32_t>(e)};
        }
    }
}

const Vfs::Location* Vfs::find(std::string_view path) const {
    auto it = index_.find(normalize_vfs_path(path));
    return it == index_.end() ? nullptr : &it->second;
}

FileInfo Vfs::describe(const std::string& key, const Location& at) const {
    const MountedGame& game = games_[at.game];
    FileInfo info;
    info.path = key;
    info.game = game.name;
    if (at.pak == kLoose) {
        const LooseFile& file = game.loose.files[at.entry];
        info.name = file.relative;
        info.kind = SourceKind::Directory;
        info.container = game.host_path;
        info.size = file.size;
    } else {
        const PakArchive& pak = game.paks[static_cast<size_t>(at.pak)];
        const PakEntry& entry = pak.entries()[at.entry];
        info.name = entry.name;
        info.kind = SourceKind::Pak;
        info.container = pak.path();
        info.size = entry.size;
        info.offset = entry.offset;
    }
    return info;
}

std::string Vfs::searched_places() const {
    std::string out;
    for (const SearchPath& sp : search_paths()) {
        if (!out.empty()) out += ", ";
        out += sp.kind == SourceKind::Pak ? sp.host_path : sp.host_path + "/";
    }
    return out.empty() ? "no search paths" : out;
}

Result<std::vector<uint8_t>> Vfs::read(std::string_view path) const {
    const Location* at = find(path);
    if (!at) {
        return Error{std::string(path), 0,
                     "not found: " + std::string(path) + " (searched " + searched_places() + ")"};
    }
    const MountedGame& game = games_[at->game];
    if (at->pak == kLoose) {
        return read_file(game.host_path + "/" + game.loose.files[at->entry].relative);
    }
    const PakArchive& pak = game.paks[static_cast<size_t>(at->pak)];
    return pak.read(pak.entries()[at->entry]);
}

bool Vfs::exists(std::string_view path) const {
    return find(path) != nullptr;
}

std::optional<FileInfo> Vfs::locate(std::string_view path) const {
    std::string key = normalize_vfs_path(path);
    auto it = index_.find(key);
    if (it == index_.end()) return std::nullopt;
    return describe(key, it->second);
}

std::vector<std::string> Vfs::list(std::string_view dir, std::string_view extension) const {
    std::string dir_key = normalize_vfs_path(dir);
    std::string ext_key = normalize_extension(extension);
    std::vector<std::string> out;
    for (const auto& [key, at] : index_) {
        if (vfs_key_matches(key, dir_key, ext_key)) out.push_back(key);
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<SearchPath> Vfs::search_paths() const {
    std::vector<SearchPath> out;
    for (auto game = games_.rbegin(); game != games_.rend(); ++game) {
        out.push_back(SearchPath{SourceKind::Directory, game->name, game->host_path,
                                 game->loose.files.size()});
        for (auto pak = game->paks.rbegin(); pak != game->paks.rend(); ++pak) {
            out.push_back(
                SearchPath{SourceKind::Pak, game->name, pak->path(), pak->entries().size()});
        }
    }
    return out;
}

Result<size_t> Vfs::rescan() {
    std::vector<LooseScan> scans;
    for (const MountedGame& game : games_) {
        auto scan = scan_loose_files(game.host_path);
        if (!scan) return scan.error();
        scans.push_back(std::move(scan.value()));
    }
    for (size_t g = 0; g < games_.size(); ++g) games_[g].loose = std::move(scans[g]);
    build_index();
    return index_.size();
}

std::vector<std::string> Vfs::warnings() const {
    std::vector<std::string> out = mount_warnings_;
    for (const MountedGame& game : games_) {
        out.insert(out.end(), game.loose.warnings.begin(), game.loose.warnings.end());
    }
    return out;
}

}  // namespace nq
