#include "fs/vfs_path.h"

namespace nq {

namespace {

char lower_ascii(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

void append_component(std::string& out, std::string_view part) {
    if (part.empty() || part == ".") return;
    if (!out.empty()) out += '/';
    for (char c : part) out += lower_ascii(c);
}

}  // namespace

std::string normalize_vfs_path(std::string_view path) {
    std::string out;
    out.reserve(path.size());
    size_t start = 0;
    for (size_t i = 0; i <= path.size(); ++i) {
        if (i == path.size() || path[i] == '/' || path[i] == '\\') {
            append_component(out, path.substr(start, i - start));
            start = i + 1;
        }
    }
    return out;
}

std::string normalize_extension(std::string_view extension) {
    if (extension.starts_with('*')) extension.remove_prefix(1);
    if (extension.empty()) return {};
    std::string out = extension.starts_with('.') ? "" : ".";
    for (char c : extension) out += lower_ascii(c);
    return out;
}

bool vfs_key_matches(std::string_view key, std::string_view dir, std::string_view extension) {
    if (!key.ends_with(extension) || key.size() == extension.size()) return false;
    if (dir.empty()) return true;
    return key.size() > dir.size() + extension.size() && key.starts_with(dir) &&
           key[dir.size()] == '/';
}

}  // namespace nq
