#include "console/console_drawer.h"

#include "draw2d/rgba_texture.h"

namespace nq {
namespace {

constexpr Colour kBackgroundImageTint{255, 255, 255, 255};

}  // namespace

Result<ConsoleDrawer> ConsoleDrawer::create(ConsoleStyle style) {
    Result<QuadRenderer> renderer = QuadRenderer::create();
    if (!renderer) return renderer.error();
    ConsoleDrawer drawer(std::move(*renderer), style);
    drawer.use_fallback_font();
    return drawer;
}

ConsoleDrawer::ConsoleDrawer(QuadRenderer renderer, ConsoleStyle style)
    : renderer_(std::move(renderer)), scene_(style) {}

void ConsoleDrawer::set_font(const RgbaImage& font) {
    if (font.width != kFontImageSize || font.height != kFontImageSize) return;
    if (!font_) font_ = npr::gl::Texture::create(nullptr);
    upload_rgba_texture(font_.id(), font.width, font.height, font.rgba.data());
}

void ConsoleDrawer::set_background(const RgbaImage& image) {
    if (image.empty()) {
        background_.reset();
        return;
    }
    if (!background_) background_ = npr::gl::Texture::create(nullptr);
    upload_rgba_texture(background_.id(), image.width, image.height, image.rgba.data());
}

void ConsoleDrawer::draw(const Console& console) {
    drawn_ = false;
    const ConsoleLayout& layout = console.layout();
    if (layout.screen_width <= 0 || layout.screen_height <= 0) return;
    if (!scene_.has_content(console)) return;

    drawn_ = true;
    QuadRenderer::Pass pass(renderer_, layout.screen_width, layout.screen_height);
    bool image_background = background_ && console.height_pixels() > 0;
    if (image_background) {
        auto [x, y, width, height] = scene_.background_rect(console);
        pass.use_texture(background_.id());
        pass.batch().image(x, y, width, height, kBackgroundImageTint);
    }
    pass.use_texture(font_.id());
    scene_.build(console, pass.batch(), !image_background);
}

}  // namespace nq
