// Shared by the render_*_test.cpp files: the LibreQuake data through the VFS, raw little-endian
// reads for independent checks, and small vector helpers.
#pragma once

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "formats/bsp.h"
#include "fs/vfs.h"
#include "render/brush_model.h"
#include "render/model_cache.h"
#include "render/vfs_file_reader.h"
#include "support/test_data.h"

namespace nq::render_test {

// The lq1 game directory mounted as the only game (LibreQuake runs as "-game lq1").
inline const Vfs& lq1_vfs() {
    static const Vfs vfs = [] {
        VfsConfig config;
        config.basedir = test::data_root();
        config.games = {"lq1"};
        test::lq1_dir();  // fails loudly when the data is missing
        auto r = Vfs::mount(config);
        if (!r) throw std::runtime_error(r.error().to_string());
        return std::move(*r);
    }();
    return vfs;
}

inline ModelCache::FileReader lq1_reader() {
    return vfs_file_reader(lq1_vfs());
}

inline std::vector<uint8_t> lq1_bytes(const std::string& path) {
    auto r = lq1_vfs().read(path);
    if (!r) throw std::runtime_error(r.error().to_string());
    return std::move(*r);
}

inline std::shared_ptr<const BrushModelData> load_map(const std::string& path) {
    auto bsp = parse_bsp(lq1_bytes(path), path);
    if (!bsp) throw std::runtime_error(bsp.error().to_string());
    return BrushModelData::build(std::move(*bsp));
}

// Map paths "maps/x.bsp" of every LibreQuake map.
inline std::vector<std::string> all_map_paths() {
    return lq1_vfs().list("maps", "bsp");
}

inline int32_t raw_i32(const std::vector<uint8_t>& b, size_t at) {
    int32_t v;
    std::memcpy(&v, b.data() + at, 4);  // the test host is little-endian, like the formats
    return v;
}
inline float raw_f32(const std::vector<uint8_t>& b, size_t at) {
    float v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
}
inline int16_t raw_i16(const std::vector<uint8_t>& b, size_t at) {
    int16_t v;
    std::memcpy(&v, b.data() + at, 2);
    return v;
}

// Lightstyles all at normal brightness.
inline std::vector<float> normal_lightstyles() {
    return std::vector<float>(64, 1.0f);
}

}  // namespace nq::render_test
