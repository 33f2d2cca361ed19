#include "menu/menu_drawing.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace nq {
namespace {

constexpr float kPlaqueX = 16, kTitleY = 4;
constexpr float kPictureItemsX = 72, kDotX = 54;
constexpr float kSlotX = 16, kSlotCursorX = 8;
constexpr float kLabelEndX = 192, kSettingCursorX = 200, kValueX = 220;
constexpr float kNoticeY = 188;
constexpr int kSliderCells = 10;
constexpr size_t kMaxLabelChars = 22;  // (kLabelEndX - kPlaqueX) / 8
constexpr uint8_t kHighlight = 128;    // conchars' second half: Quake's brown menu text

bool is_picture_menu(MenuScreen screen) {
    return screen == MenuScreen::Main || screen == MenuScreen::SinglePlayer;
}

bool is_setting_menu(MenuScreen screen) {
    return screen == MenuScreen::Options || screen == MenuScreen::Style;
}

float row_height(MenuScreen screen) {
    return is_picture_menu(screen) ? kPictureMenuRowHeight : kTextMenuRowHeight;
}

float row_top(MenuScreen screen, int row) {
    return kMenuRowsTop + row_height(screen) * float(row);
}

void highlighted_text(const HudCanvas& canvas, float x, float y, std::string_view text) {
    for (char c : text) {
        if (c != ' ') canvas.character(x, y, uint8_t(uint8_t(c) | kHighlight));
        x += kCharacterSize;
    }
}

float centred_x(size_t characters) {
    return std::floor((kVirtualWidth - float(characters) * kCharacterSize) / 2);
}

// The screen's title picture, or its name in the console font where the data lacks it.
void draw_title(const HudCanvas& canvas, const MenuPictureIds& ids, const Menu& menu) {
    PictureId title = kNoPicture;
    std::string words;
    switch (menu.screen()) {
        case MenuScreen::Main:
            title = ids.main_title, words = "MAIN MENU";
            break;
        case MenuScreen::SinglePlayer:
            title = ids.single_player_title, words = "SINGLE PLAYER";
            break;
        case MenuScreen::Load:
            title = ids.load_title, words = "LOAD GAME";
            break;
        case MenuScreen::Save:
            title = ids.save_title, words = "SAVE GAME";
            break;
        case MenuScreen::Options:
            title = ids.options_title, words = "OPTIONS";
            break;
        case MenuScreen::Style:
            words = "STYLE SETTINGS";
            break;
        default:
            return;
    }
    canvas.picture(ids.plaque, kPlaqueX, kTitleY);
    if (const int width = canvas.picture_width(title); width > 0) {
        canvas.picture(title, std::floor((kVirtualWidth - float(width)) / 2), kTitleY);
    } else {
        highlighted_text(canvas, centred_x(words.size()), kTitleY + 8, words);
    }
}

void draw_picture_menu(const HudCanvas& canvas, const MenuPictureIds& ids, const Menu& menu,
                       double real_time) {
    const PictureId items =
        menu.screen() == MenuScreen::Main ? ids.main_items : ids.single_player_items;
    const bool have_items = canvas.picture_width(items) > 0;
    if (have_items) {
        canvas.picture(items, kPictureItemsX, kMenuRowsTop);
    } else {
        for (size_t row = 0; row < menu.rows().size(); ++row) {
            highlighted_text(canvas, kPictureItemsX, row_top(menu.screen(), int(row)) + 6,
                             menu.rows()[row].label);
        }
    }
    const int frame = int(real_time * 10) % kMenuDotFrames;
    const float dot_y = row_top(menu.screen(), menu.cursor());
    if (canvas.picture_width(ids.dots[size_t(frame)]) > 0) {
        canvas.picture(ids.dots[size_t(frame)], kDotX, dot_y);
    } else {
        canvas.character(kDotX + 8, dot_y + 6, uint8_t(12 + (int(real_time * 4) & 1)));
    }
}

void draw_slider(const HudCanvas& canvas, float y, float position) {
    canvas.character(kValueX - 8, y, 128);
    for (int cell = 0; cell < kSliderCells; ++cell) canvas.character(kValueX + 8 * cell, y, 129);
    canvas.character(kValueX + 8 * kSliderCells, y, 130);
    canvas.character(kValueX + std::round((kSliderCells - 1) * 8 * position), y, 131);
}

void draw_text_menu(const HudCanvas& canvas, const Menu& menu, double real_time) {
    const bool settings = is_setting_menu(menu.screen());
    for (size_t i = 0; i < menu.rows().size(); ++i) {
        const MenuRow& row = menu.rows()[i];
        const float y = row_top(menu.screen(), int(i));
        std::string label = row.label.substr(0, settings ? kMaxLabelChars : 38);
        const float x = settings ? kLabelEndX - float(label.size()) * kCharacterSize : kSlotX;
        if (row.enabled) {
            highlighted_text(canvas, x, y, label);
        } else {
            canvas.text(x, y, label);
        }
        if (row.slider) draw_slider(canvas, y, *row.slider);
        if (!row.value.empty()) canvas.text(kValueX, y, row.value.substr(0, 12));
    }
    const float cursor_x = settings ? kSettingCursorX : kSlotCursorX;
    canvas.character(cursor_x, row_top(menu.screen(), menu.cursor()),
                     uint8_t(12 + (int(real_time * 4) & 1)));
}

// Quake's help pictures, or the keys in words where the data has none.
void draw_help(const HudCanvas& canvas, const MenuPictureIds& ids, const Menu& menu) {
    if (menu.help_pages() > 0) {
        canvas.picture(ids.help[size_t(menu.help_page())], 0, 0);
        return;
    }
    const char* const lines[] = {"HELP",
                                 "",
                                 "ESC        menu",
                                 "~          console",
                                 "arrows     move, turn",
                                 "mouse      look, fire",
                                 "ENTER      choose",
                                 "",
                                 "exec default.cfg binds",
                                 "WASD, mouse and weapons"};
    float y = 40;
    for (const char* line : lines) {
        highlighted_text(canvas, 40, y, line);
        y += 10;
    }
}

void draw_quit(const HudCanvas& canvas) {
    constexpr float kBoxX = 56, kBoxY = 76, kBoxWidth = 208, kBoxHeight = 48;
    canvas.fill(kBoxX, kBoxY, kBoxWidth, kBoxHeight, 0);
    const std::string question = "Really quit?";
    const std::string answer = "Press Y or N";
    highlighted_text(canvas, centred_x(question.size()), kBoxY + 12, question);
    canvas.text(centred_x(answer.size()), kBoxY + 28, answer);
}

}  // namespace

void build_menu(const Menu& menu, const HudPictures& pictures, const HudScreen& screen,
                double real_time, QuadBatch& batch) {
    if (!menu.active()) return;
    batch.solid(0, 0, float(screen.width), float(screen.height),
                Colour{0, 0, 0, uint8_t(kMenuFadeAlpha * 255)});
    const HudCanvas canvas = HudCanvas::menu(batch, pictures, screen);
    const MenuPictureIds& ids = pictures.ids().menu;
    switch (menu.screen()) {
        case MenuScreen::Help:
            draw_help(canvas, ids, menu);
            return;
        case MenuScreen::Quit:
            draw_quit(canvas);
            return;
        default:
            break;
    }
    draw_title(canvas, ids, menu);
    if (is_picture_menu(menu.screen())) {
        draw_picture_menu(canvas, ids, menu, real_time);
    } else {
        draw_text_menu(canvas, menu, real_time);
    }
    if (!menu.notice().empty())
        canvas.text(centred_x(menu.notice().size()), kNoticeY, menu.notice());
}

int menu_row_at(const Menu& menu, const HudScreen& screen, float x, float y) {
    if (!menu.active() || menu.rows().empty()) return -1;
    const HudCanvas::Placement at = HudCanvas::menu_placement(screen);
    const float virtual_x = (x - at.left) / at.scale;
    const float virtual_y = (y - at.top) / at.scale;
    if (virtual_x < 0 || virtual_x >= kVirtualWidth) return -1;
    const float row = std::floor((virtual_y - kMenuRowsTop) / row_height(menu.screen()));
    if (!(row >= 0) || row >= float(menu.rows().size())) return -1;
    return int(row);
}

}  // namespace nq
