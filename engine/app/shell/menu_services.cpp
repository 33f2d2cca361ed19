#include "app/shell/menu_services.h"

#include "common/file_io.h"
#include "server/savegame.h"

namespace nq {

namespace {

// The second line of a save file: Quake's 39-character comment, '_' standing for spaces.
std::string save_comment_of(const std::vector<uint8_t>& bytes) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const size_t first = text.find('\n');
    if (first == std::string_view::npos) return {};
    const size_t second = text.find('\n', first + 1);
    std::string comment(text.substr(
        first + 1, second == std::string_view::npos ? std::string_view::npos : second - first - 1));
    while (!comment.empty() && (comment.back() == '\r' || comment.back() == ' ')) {
        comment.pop_back();
    }
    for (char& c : comment) {
        if (c == '_') c = ' ';
        if (static_cast<unsigned char>(c) < 32) c = ' ';
    }
    return comment.substr(0, server::kSaveCommentLength);
}

}  // namespace

EngineMenuServices::EngineMenuServices(const PluginHost& plugins, const DemoSession& demo,
                                       std::string save_dir)
    : plugins_(plugins), demo_(demo), save_dir_(std::move(save_dir)) {}

std::vector<std::string> EngineMenuServices::styles() const {
    std::vector<std::string> names;
    // `null` draws nothing (engine tests, CPU timing): not a style a player picks.
    for (const PluginInfo& info : plugins_.available()) {
        if (info.name != "null") names.push_back(info.name);
    }
    return names;
}

std::string EngineMenuServices::active_style() const {
    return plugins_.active_name();
}

std::vector<StyleSetting> EngineMenuServices::style_settings() const {
    const nqr_renderer* table = plugins_.active();
    return table ? read_style_settings(*table).settings : std::vector<StyleSetting>{};
}

std::string EngineMenuServices::save_comment(int slot) const {
    auto bytes = read_file(save_dir_ + "/s" + std::to_string(slot) + ".sav");
    return bytes ? save_comment_of(*bytes) : std::string();
}

bool EngineMenuServices::game_running() const {
    const LiveGame* game = demo_.live();
    return game && game->running();
}

}  // namespace nq
