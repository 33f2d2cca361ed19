// pak: list, extract and create Quake PAK archives.
//   pak list [--json] FILE.pak
//   pak extract FILE.pak [DIR] [NAME...]
//   pak create OUT.pak DIR
// Exit status: 0 success, 1 error (bad pak, I/O, refused entry), 2 bad command line.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "common/file_io.h"
#include "common/json_writer.h"
#include "formats/pak.h"
#include "fs/pak_archive.h"
#include "fs/pak_tree.h"
#include "fs/vfs_path.h"

namespace {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

constexpr const char* kUsage =
    "usage: pak <command> ...\n"
    "  pak list [--json] FILE.pak            list entries (offset, size, name) and the total\n"
    "  pak extract FILE.pak [DIR] [NAME...]  extract all entries, or the named ones, under DIR\n"
    "                                        (default: the current directory)\n"
    "  pak create OUT.pak DIR                pack every file under DIR, sorted by name\n"
    "  pak --help                            show this message\n"
    "exit status: 0 ok, 1 error, 2 usage\n";

using Args = std::vector<std::string>;

int usage_error(const std::string& message) {
    std::fprintf(stderr, "pak: %s\n%s", message.c_str(), kUsage);
    return kExitUsage;
}

int error(const std::string& message) {
    std::fprintf(stderr, "pak: error: %s\n", message.c_str());
    return kExitError;
}

void print_warnings(const std::vector<std::string>& warnings, const std::string& file) {
    for (const std::string& w : warnings) {
        std::fprintf(stderr, "pak: warning: %s: %s\n", file.c_str(), w.c_str());
    }
}

bool is_option(const std::string& arg) {
    return arg.size() > 1 && arg[0] == '-';
}

uint64_t total_size(const std::vector<nq::PakEntry>& entries) {
    uint64_t total = 0;
    for (const nq::PakEntry& e : entries) total += e.size;
    return total;
}

void print_list_json(const nq::PakArchive& pak) {
    nq::JsonWriter json;
    json.begin_object().field("file", pak.path()).key("entries").begin_array();
    for (const nq::PakEntry& e : pak.entries()) {
        json.begin_object()
            .field("name", e.name)
            .field("offset", e.offset)
            .field("size", e.size)
            .end_object();
    }
    json.end_array();
    json.field("count", static_cast<uint64_t>(pak.entries().size()));
    json.field("total_size", total_size(pak.entries()));
    json.key("warnings").begin_array();
    for (const std::string& w : pak.warnings()) json.value(w);
    json.end_array().end_object();
    std::fputs(json.str().c_str(), stdout);
}

void print_list_text(const nq::PakArchive& pak) {
    std::printf("%10s %10s  %s\n", "offset", "size", "name");
    for (const nq::PakEntry& e : pak.entries()) {
        std::printf("%10u %10u  %s\n", e.offset, e.size, e.name.c_str());
    }
    std::printf("%zu files, %llu bytes\n", pak.entries().size(),
                static_cast<unsigned long long>(total_size(pak.entries())));
}

int list_command(const Args& args) {
    bool json = false;
    Args files;
    for (const std::string& a : args) {
        if (a == "--json") {
            json = true;
        } else if (is_option(a)) {
            return usage_error("list: unknown option " + a);
        } else {
            files.push_back(a);
        }
    }
    if (files.size() != 1) return usage_error("list: expected one FILE.pak");
    auto pak = nq::PakArchive::open(files[0]);
    if (!pak) return error(pak.error().to_string());
    print_warnings(pak->warnings(), pak->path());
    json ? print_list_json(*pak) : print_list_text(*pak);
    return kExitOk;
}

// The entries named on the command line (exact name first, then ignoring case and separator
// style), or every entry when none is named. Names not in the pak go to `missing`.
std::vector<const nq::PakEntry*> select_entries(const nq::PakArchive& pak, const Args& names,
                                                Args& missing) {
    std::vector<const nq::PakEntry*> out;
    if (names.empty()) {
        for (const nq::PakEntry& e : pak.entries()) out.push_back(&e);
        return out;
    }
    for (const std::string& wanted : names) {
        const nq::PakEntry* match = nullptr;
        for (const nq::PakEntry& e : pak.entries()) {
            if (e.name == wanted) match = &e;
        }
        for (const nq::PakEntry& e : pak.entries()) {
            if (!match && nq::normalize_vfs_path(e.name) == nq::normalize_vfs_path(wanted)) {
                match = &e;
            }
        }
        if (match) {
            out.push_back(match);
        } else {
            missing.push_back(wanted);
        }
    }
    return out;
}

int extract_command(const Args& args) {
    for (const std::string& a : args) {
        if (is_option(a)) return usage_error("extract: unknown option " + a);
    }
    if (args.empty()) return usage_error("extract: expected FILE.pak [DIR] [NAME...]");
    std::string out_dir = args.size() >= 2 ? args[1] : ".";
    Args names(args.begin() + std::min<size_t>(2, args.size()), args.end());

    auto pak = nq::PakArchive::open(args[0]);
    if (!pak) return error(pak.error().to_string());
    print_warnings(pak->warnings(), pak->path());
    Args missing;
    auto selected = select_entries(*pak, names, missing);
    if (!missing.empty()) {
        std::string list;
        for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
        return error("not in " + pak->path() + ": " + list + " (nothing extracted)");
    }
    int status = kExitOk;
    uint64_t bytes = 0;
    size_t written = 0;
    for (const nq::PakEntry* e : selected) {
        if (std::string problem = nq::extract_pak_entry(*pak, *e, out_dir); !problem.empty()) {
            status = error(problem);
            continue;
        }
        ++written;
        bytes += e->size;
    }
    if (names.empty() && pak->directory().unsafe_entries > 0) {
        status = error("refused " + std::to_string(pak->directory().unsafe_entries) +
                       " entries with unsafe names (see the warnings above)");
    }
    std::printf("extracted %zu files (%llu bytes) to %s\n", written,
                static_cast<unsigned long long>(bytes), out_dir.c_str());
    return status;
}

int create_command(const Args& args) {
    for (const std::string& a : args) {
        if (is_option(a)) return usage_error("create: unknown option " + a);
    }
    if (args.size() != 2) return usage_error("create: expected OUT.pak DIR");
    const std::string& out = args[0];
    auto files = nq::collect_pak_files(args[1], out);
    if (!files) return error(files.error().message + " (" + files.error().file + ")");
    auto bytes = nq::write_pak(*files, out);
    if (!bytes) return error(bytes.error().to_string());
    if (std::string problem = nq::write_file(out, *bytes); !problem.empty()) return error(problem);
    std::printf("wrote %s: %zu files, %zu bytes\n", out.c_str(), files->size(), bytes->size());
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    Args args(argv + 1, argv + argc);
    if (args.empty()) return usage_error("no command given");
    std::string command = args[0];
    args.erase(args.begin());
    if (command == "-h" || command == "--help" || command == "help") {
        std::fputs(kUsage, stdout);
        return kExitOk;
    }
    if (command == "list") return list_command(args);
    if (command == "extract") return extract_command(args);
    if (command == "create") return create_command(args);
    return usage_error("unknown command '" + command + "'");
}
