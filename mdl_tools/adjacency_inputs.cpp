#include "adjacency_inputs.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>

#include "common/file_io.h"
#include "fs/pak_archive.h"
#include "model_paths.h"

namespace nq::mdltool {

namespace {

bool ends_with_ignoring_case(const std::string& name, std::string_view suffix) {
    if (name.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(), name.end() - suffix.size(), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) ==
               std::tolower(static_cast<unsigned char>(b));
    });
}

void add_pak_models(const std::string& path, ModelInputs& out) {
    Result<PakArchive> opened = PakArchive::open(path);
    if (!opened) {
        out.errors.push_back(opened.error().to_string());
        return;
    }
    auto pak = std::make_shared<PakArchive>(std::move(*opened));
    size_t found = 0;
    for (const PakEntry& entry : pak->entries()) {
        if (!ends_with_ignoring_case(entry.name, ".mdl")) continue;
        ++found;
        out.models.push_back({path + ":" + entry.name, [pak, entry] { return pak->read(entry); }});
    }
    if (found == 0) out.errors.push_back(path + ": no *.mdl entries in this pak");
}

void add_loose_models(const std::string& arg, ModelInputs& out) {
    PathExpansion expansion = expand_model_paths({arg}, ".mdl");
    for (std::string& file : expansion.files) {
        out.models.push_back({file, [file] { return read_file(file); }});
    }
    for (std::string& e : expansion.errors) out.errors.push_back(std::move(e));
}

}  // namespace

ModelInputs expand_model_inputs(const std::vector<std::string>& args) {
    ModelInputs out;
    for (const std::string& arg : args) {
        std::error_code ec;
        if (ends_with_ignoring_case(arg, ".pak") && std::filesystem::is_regular_file(arg, ec)) {
            add_pak_models(arg, out);
        } else {
            add_loose_models(arg, out);
        }
    }
    return out;
}

}  // namespace nq::mdltool
