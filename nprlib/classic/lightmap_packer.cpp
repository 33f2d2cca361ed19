#include "classic/lightmap_packer.h"

#include <algorithm>

namespace nq::npr::classic {

bool LightmapPacker::place_in_page(std::vector<int>& skyline, int width, int height, int& x,
                                   int& y) const {
    int best_y = page_size_;
    int best_x = -1;
    for (int column = 0; column + width <= page_size_; ++column) {
        // Tallest column under the block; give up early once it cannot beat the best so far.
        int top = 0;
        int j = 0;
        for (; j < width; ++j) {
            const int used = skyline[static_cast<size_t>(column + j)];
            if (used >= best_y) break;
            top = std::max(top, used);
        }
        if (j == width) {
            best_y = top;
            best_x = column;
        }
    }
    if (best_x < 0 || best_y + height > page_size_) return false;
    std::fill(skyline.begin() + best_x, skyline.begin() + best_x + width, best_y + height);
    x = best_x;
    y = best_y;
    return true;
}

LightmapPlacement LightmapPacker::place(int width, int height) {
    LightmapPlacement placement;
    if (width <= 0 || height <= 0 || width > page_size_ || height > page_size_) return placement;
    for (size_t page = 0; page < skylines_.size(); ++page) {
        if (place_in_page(skylines_[page], width, height, placement.x, placement.y)) {
            placement.page = static_cast<int>(page);
            return placement;
        }
    }
    skylines_.emplace_back(static_cast<size_t>(page_size_), 0);
    place_in_page(skylines_.back(), width, height, placement.x, placement.y);
    placement.page = static_cast<int>(skylines_.size() - 1);
    return placement;
}

}  // namespace nq::npr::classic
