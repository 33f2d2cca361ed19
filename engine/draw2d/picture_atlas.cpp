#include "draw2d/picture_atlas.h"

#include <algorithm>
#include <cstring>

namespace nq {
namespace {

constexpr int kBorder = 1;  // repeated edge pixels on each side of a picture

struct Spot {
    int x = 0, y = 0;  // the picture's top-left pixel (its border lies outside)
};

uint8_t* pixel_at(RgbaImage& image, int x, int y) {
    return &image.rgba[(static_cast<size_t>(y) * image.width + x) * 4];
}

// The picture at `at`, and its edge pixels once more all around it.
void copy_with_border(RgbaImage& atlas, const RgbaImage& picture, Spot at) {
    for (int y = -kBorder; y < picture.height + kBorder; ++y) {
        int from_y = std::clamp(y, 0, picture.height - 1);
        for (int x = -kBorder; x < picture.width + kBorder; ++x) {
            int from_x = std::clamp(x, 0, picture.width - 1);
            const uint8_t* from =
                &picture.rgba[(static_cast<size_t>(from_y) * picture.width + from_x) * 4];
            std::memcpy(pixel_at(atlas, at.x + x, at.y + y), from, 4);
        }
    }
}

// Gives each fully transparent pixel the average colour of its opaque neighbours (alpha stays
// 0), so that linear filtering across an outline blends toward the outline's colour.
void colour_transparent_pixels(RgbaImage& image) {
    const RgbaImage source = image;
    auto opaque = [&](int x, int y) {
        return source.rgba[(static_cast<size_t>(y) * source.width + x) * 4 + 3] != 0;
    };
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (opaque(x, y)) continue;
            int sum[3] = {0, 0, 0}, count = 0;
            for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, image.height - 1); ++ny) {
                for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, image.width - 1); ++nx) {
                    if (!opaque(nx, ny)) continue;
                    const uint8_t* n =
                        &source.rgba[(static_cast<size_t>(ny) * source.width + nx) * 4];
                    for (int c = 0; c < 3; ++c) sum[c] += n[c];
                    ++count;
                }
            }
            if (count == 0) continue;
            uint8_t* out = pixel_at(image, x, y);
            for (int c = 0; c < 3; ++c) out[c] = static_cast<uint8_t>(sum[c] / count);
        }
    }
}

bool usable(const RgbaImage& picture) {
    return !picture.empty() &&
           picture.rgba.size() == static_cast<size_t>(picture.width) * picture.height * 4;
}

}  // namespace

PictureAtlas pack_pictures(std::span<const RgbaImage> pictures) {
    PictureAtlas atlas;
    atlas.pictures.resize(pictures.size());

    std::vector<size_t> order;
    int width = kAtlasWidth;
    for (size_t i = 0; i < pictures.size(); ++i) {
        if (!usable(pictures[i])) continue;
        order.push_back(i);
        width = std::max(width, pictures[i].width + 2 * kBorder);
    }
    if (order.empty()) return atlas;
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return pictures[a].height > pictures[b].height; });

    // Rows ("shelves"): a picture goes to the right of the previous one while it fits, else
    // it starts a new row below the tallest picture of the current one.
    std::vector<Spot> spots(pictures.size());
    int x = 0, row_top = 0, row_height = 0;  // in cells: picture plus border
    for (size_t i : order) {
        int cell_width = pictures[i].width + 2 * kBorder;
        if (x > 0 && x + cell_width > width) {
            row_top += row_height;
            x = 0;
            row_height = 0;
        }
        spots[i] = Spot{x + kBorder, row_top + kBorder};
        x += cell_width;
        row_height = std::max(row_height, pictures[i].height + 2 * kBorder);
    }
    int height = row_top + row_height;

    atlas.image.width = width;
    atlas.image.height = height;
    atlas.image.rgba.assign(static_cast<size_t>(width) * height * 4, 0);
    float w = static_cast<float>(width), h = static_cast<float>(height);
    for (size_t i : order) {
        const RgbaImage& p = pictures[i];
        RgbaImage coloured = p;
        colour_transparent_pixels(coloured);
        copy_with_border(atlas.image, coloured, spots[i]);
        Spot s = spots[i];
        atlas.pictures[i] =
            AtlasPicture{p.width, p.height,
                         TextureRegion{static_cast<float>(s.x) / w, static_cast<float>(s.y) / h,
                                       static_cast<float>(s.x + p.width) / w,
                                       static_cast<float>(s.y + p.height) / h}};
    }
    return atlas;
}

}  // namespace nq
