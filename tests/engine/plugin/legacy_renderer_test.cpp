// The 1.x adapter: the 1.x layouts the engine converts to match the header the 1.5 plugin was
// built from, and a 2.0 frame comes out in the 1.x layout field for field — the camera and
// each entity's light by value, the light list copied from its pointer, the rest passed on.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <array>
#include <cstring>

#include "plugin/legacy_renderer.h"
#include "support/build_paths.h"
#include "support/null_engine_services.h"

namespace nq {
namespace {

using NoServices = test::NullEngineServices;

TEST(LegacyRenderer, TheEnginesOneXLayoutsAreThe15HeadersLayouts) {
    const std::string path = test::test_plugin_dir() + "/nqr_legacy15.so";
    void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(h, nullptr) << dlerror();
    auto layout = reinterpret_cast<void (*)(size_t*)>(dlsym(h, "nqr_legacy_layout"));
    ASSERT_NE(layout, nullptr);
    std::array<size_t, 8> built{};
    layout(built.data());
    dlclose(h);
    const std::array<size_t, 8> ours = {
        sizeof(nqr1_frame),  offsetof(nqr1_frame, camera), offsetof(nqr1_frame, view_planes),
        sizeof(nqr1_entity), offsetof(nqr1_entity, light), sizeof(nqr1_entity_light),
        sizeof(nqr1_engine), sizeof(nqr1_renderer)};
    EXPECT_EQ(built, ours);
}

// A 1.x table with every hook, all doing nothing: what the adapter wraps.
int ok_init(const nqr1_engine*) {
    return 0;
}
void no_shutdown() {}
void no_frame(const nqr1_frame*) {}

nqr1_renderer legacy_table() {
    nqr1_renderer t{};
    t.size = sizeof t;
    t.abi_version = NQR1_ABI_VERSION;
    t.name = "old";
    t.init = ok_init;
    t.shutdown = no_shutdown;
    t.draw_world = no_frame;
    return t;
}

TEST(LegacyRenderer, ConvertsA20FrameToThe1xLayout) {
    NoServices services;
    ServiceTable table(services, 7);
    const nqr1_engine engine = legacy_services(table);
    LegacyRenderer adapter(legacy_table(), engine, table);

    nqr_camera camera{};
    camera.size = sizeof camera;
    for (int i = 0; i < 16; ++i) camera.view_projection[i] = float(i) * 0.5f + 1.0f;
    camera.origin[0] = 12.5f;
    camera.viewport[2] = 320;
    camera.fov_y = 73.0f;

    std::array<nqr_light_source, 3> sources{};
    for (size_t i = 0; i < sources.size(); ++i) {
        sources[i].size = sizeof(nqr_light_source);
        sources[i].position[0] = 100.0f + float(i);
        sources[i].color[2] = 0.25f * float(i + 1);
    }
    nqr_entity_light light{};
    light.size = sizeof light;
    light.ambient = 0.75f;
    light.direction[1] = -1.0f;
    light.ambient_cube[5][2] = 0.125f;
    light.num_lights = 3;
    light.lights = sources.data();

    std::array<nqr_entity, 3> entities{};
    for (size_t i = 0; i < entities.size(); ++i) {
        entities[i].size = sizeof(nqr_entity);
        entities[i].number = uint32_t(40 + i);
        entities[i].origin[2] = 8.0f * float(i);
        entities[i].effects = 0x55;
        entities[i].alpha = 0.5f;
        entities[i].light = &light;
    }
    const nqr_entity* brush[] = {&entities[0]};
    const nqr_entity* alias[] = {&entities[1], &entities[2]};
    const uint32_t visible[] = {3, 1, 4};

    nqr_frame frame{};
    frame.size = sizeof frame;
    frame.number = 9;
    frame.time = 2.5;
    frame.flags = NQR_FRAME_UNDERWATER;
    frame.camera = &camera;
    frame.world = 1;
    frame.visible_surfaces = visible;
    frame.num_visible_surfaces = 3;
    frame.brush_entities = brush;
    frame.num_brush_entities = 1;
    frame.alias_entities = alias;
    frame.num_alias_entities = 2;
    frame.view_planes[2][3] = -6.0f;

    const nqr1_frame& out = adapter.convert(frame);
    EXPECT_EQ(out.size, sizeof(nqr1_frame));
    EXPECT_EQ(out.number, 9u);
    EXPECT_EQ(out.time, 2.5);
    EXPECT_EQ(out.flags, uint32_t(NQR_FRAME_UNDERWATER));
    EXPECT_EQ(out.camera.size, sizeof(nqr1_camera));
    EXPECT_EQ(0, std::memcmp(out.camera.view_projection, camera.view_projection,
                             sizeof camera.view_projection));
    EXPECT_EQ(out.camera.origin[0], 12.5f);
    EXPECT_EQ(out.camera.viewport[2], 320);
    EXPECT_EQ(out.camera.fov_y, 73.0f);
    EXPECT_EQ(out.visible_surfaces, visible);
    EXPECT_EQ(out.num_visible_surfaces, 3u);
    EXPECT_EQ(out.view_planes[2][3], -6.0f);
    EXPECT_EQ(out.blend[0], 0.0f) << "1.x's blend was never filled";
    ASSERT_EQ(out.num_brush_entities, 1u);
    ASSERT_EQ(out.num_alias_entities, 2u);
    EXPECT_EQ(out.num_sprite_entities, 0u);
    const nqr1_entity* listed[] = {out.brush_entities[0], out.alias_entities[0],
                                   out.alias_entities[1]};
    for (size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(i);
        const nqr1_entity& e = *listed[i];
        EXPECT_EQ(e.size, sizeof(nqr1_entity));
        EXPECT_EQ(e.number, 40 + i);
        EXPECT_EQ(e.origin[2], 8.0f * float(i));
        EXPECT_EQ(e.effects, 0x55u);
        EXPECT_EQ(e.alpha, 0.5f);
        EXPECT_EQ(e.light.size, sizeof(nqr1_entity_light));
        EXPECT_EQ(e.light.ambient, 0.75f);
        EXPECT_EQ(e.light.direction[1], -1.0f);
        EXPECT_EQ(e.light.ambient_cube[5][2], 0.125f);
        ASSERT_EQ(e.light.num_lights, 3u);
        for (size_t k = 0; k < 3; ++k) {
            EXPECT_EQ(e.light.lights[k].size, sizeof(nqr1_light_source));
            EXPECT_EQ(e.light.lights[k].position[0], 100.0f + float(k));
            EXPECT_EQ(e.light.lights[k].color[2], 0.25f * float(k + 1));
        }
        EXPECT_EQ(e.light.lights[3].size, sizeof(nqr1_light_source)) << "unused, still sized";
    }

    // The same frame number is converted once; a new frame is converted again.
    entities[1].number = 99;
    EXPECT_EQ(adapter.convert(frame).alias_entities[0]->number, 41u);
    frame.number = 10;
    EXPECT_EQ(adapter.convert(frame).alias_entities[0]->number, 99u);
}

TEST(LegacyRenderer, OnlyThePluginsOwnHooksArePresent) {
    NoServices services;
    ServiceTable table(services, 7);
    const nqr1_engine engine = legacy_services(table);
    LegacyRenderer adapter(legacy_table(), engine, table);
    EXPECT_STREQ(adapter.table().name, "old");
    EXPECT_EQ(NQR_ABI_MAJOR(adapter.table().abi_version), 1u);
    EXPECT_NE(adapter.table().draw_world, nullptr);
    EXPECT_NE(adapter.table().shutdown, nullptr);
    for (const void* hook :
         {(const void*)adapter.table().begin_frame,
          (const void*)adapter.table().draw_alias_entities,
          (const void*)adapter.table().post_process, (const void*)adapter.table().register_model}) {
        EXPECT_EQ(hook, nullptr);
    }
}

TEST(LegacyRenderer, RefusesBrokenOneXTables) {
    nqr1_renderer t = legacy_table();
    EXPECT_EQ(validate_legacy_table(&t), "");
    EXPECT_NE(validate_legacy_table(nullptr).find("refused"), std::string::npos);
    t.size = 16;
    EXPECT_NE(validate_legacy_table(&t).find("too small"), std::string::npos);
    t = legacy_table();
    t.init = nullptr;
    EXPECT_NE(validate_legacy_table(&t).find("no init"), std::string::npos);
}

}  // namespace
}  // namespace nq
