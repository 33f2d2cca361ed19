// A test scene with every kind of model and drawing at once, for the renderers' lifecycle tests
// (ClassicRenderer, TechnicalRenderer: the same hooks).
#pragma once

#include <glm/gtc/matrix_transform.hpp>

#include "support/nprlib_test_support.h"

namespace nq::npr::test {

// Every kind of model and drawing at once: world (lit, fullbright, sky, liquid, animated),
// a brush entity, a translated player, a sprite, particles and a moving dynamic light.
struct Scene {
    BrushBuilder brush;
    AliasBuilder player;
    SpriteBuilder sprite;
    nqr_entity door{}, guy{}, weapon{}, flare{};
    TestFrame frame;

    void build_models() {
        const auto grey =
            make_image(16, 16, [](int x, int) { return x < 4 ? colour::kFullbrightGreen : 150; });
        const int floor = brush.add_texture("floor", 16, 16, grey);
        const int anim0 = brush.add_texture(
            "+0anim", 16, 16, make_image(16, 16, [](int, int) { return colour::kRed; }));
        const int anim1 = brush.add_texture(
            "+1anim", 16, 16, make_image(16, 16, [](int, int) { return colour::kBlue; }));
        brush.set_animation(anim0, {anim0, anim1});
        brush.set_animation(anim1, {anim0, anim1});
        const int sky = brush.add_texture(
            "sky1", 256, 128,
            make_image(
                256, 128,
                [](int x, int) { return x >= 128 ? colour::kBlue : (x % 16 < 8 ? 0 : 150); }),
            NQR_TEXTURE_SKY);
        const int water = brush.add_texture(
            "*water", 64, 64,
            make_image(64, 64,
                       [](int x, int) { return x % 16 < 8 ? colour::kTeal : colour::kRed; }),
            NQR_TEXTURE_LIQUID);
        brush.add_floor({0, 0, 64, 64, 0, floor});
        brush.add_floor({64, 0, 128, 64, 0, anim0});
        BrushBuilder::Quad sky_quad{0, 64, 64, 128, 0, sky};
        sky_quad.flags = NQR_SURFACE_SKY;
        brush.add_floor(sky_quad);
        BrushBuilder::Quad water_quad{64, 64, 128, 128, 0, water};
        water_quad.flags = NQR_SURFACE_LIQUID;
        brush.add_floor(water_quad);
        brush.add_floor({0, 0, 16, 16, 0, floor});  // surface 4: submodel *1
        brush.build();

        player.add_box_pose({0, 0, 0}, {16, 16, 16});
        player.add_box_pose({0, 8, 0}, {16, 24, 16});
        player.origin = glm::vec3(-8.0f);
        player.skin.assign(64, colour::kShirtBase + 3);
        player.build();

        sprite.images.push_back({8, 8, -4, 4, make_image(8, 8, [](int x, int) {
                                     return x < 4 ? colour::kOrange : colour::kTransparent;
                                 })});
    }

    template <class Renderer>
    void register_all(Renderer& renderer) {
        nqr_model world = brush.model(1, 0, 4);
        nqr_model submodel = brush.model(2, 4, 1, "*1");
        nqr_model guy_model = player.model(3);
        nqr_model flare_model = sprite.model(4);
        for (const nqr_model* m : {&world, &submodel, &guy_model, &flare_model}) {
            renderer.register_model(m);
        }
    }

    void build_frame() {
        door = make_entity(2, glm::translate(glm::mat4(1.0f), {40.0f, 40.0f, 4.0f}));
        guy = make_entity(3, glm::translate(glm::mat4(1.0f), {64.0f, 64.0f, 16.0f}));
        guy.has_translation = 1;
        guy.top_color = 4;
        guy.bottom_color = 12;
        guy.pose1 = 1;
        guy.lerp = 0.3f;
        weapon = make_entity(3, glm::translate(glm::mat4(1.0f), {80.0f, 64.0f, 40.0f}));
        weapon.flags = NQR_ENTITY_VIEWMODEL;
        flare = make_entity(4, glm::translate(glm::mat4(1.0f), {30.0f, 90.0f, 10.0f}));
        frame.brush = {&door};
        frame.alias = {&guy, &weapon};
        frame.sprite = {&flare};
        frame.visible = {0, 1, 2, 3};
        frame.use_visible_list = true;
        for (int i = 0; i < 100; ++i) {
            frame.particles.push_back(
                make_particle({20.0f + i % 10, 20.0f + i / 10, 8.0f}, colour::kRed + i % 3));
        }
        frame.dlights.push_back(make_dlight({32, 32, 16}, 120));
    }

    // One whole frame; the light moves and a style flickers so lightmaps rebuild every time.
    template <class Renderer>
    void draw(Renderer& renderer, const GlTestContext& gl, int n) {
        frame.dlights[0].origin[0] = 20.0f + static_cast<float>(n % 7) * 10.0f;
        frame.lightstyles[0] = (n % 2) ? 1.0f : 0.6f;
        const nqr_camera camera = make_camera({64.0f, 64.0f, 80.0f}, {90.0f, 0.0f, 0.0f});
        gl.clear();
        const nqr_frame* f = frame.build(camera, 1, 0.1 * n);
        renderer.draw_world(f);
        renderer.draw_brush_entities(f);
        renderer.draw_alias_entities(f);
        renderer.draw_sprite_entities(f);
        renderer.draw_particles(f);
    }
};

}  // namespace nq::npr::test
