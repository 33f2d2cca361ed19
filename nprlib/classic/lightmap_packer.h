// Packs surface lightmaps into square atlas pages the way GLQuake filled its lightmap blocks:
// each page keeps, per column, the height already used (a skyline); a w x h block goes where the
// tallest column under it is lowest. A block that fits no open page opens a new one.
#pragma once

#include <vector>

namespace nq::npr::classic {

struct LightmapPlacement {
    int page = -1;  // -1: did not fit (larger than a page)
    int x = 0, y = 0;
};

class LightmapPacker {
  public:
    explicit LightmapPacker(int page_size) : page_size_(page_size) {}

    LightmapPlacement place(int width, int height);

    int page_size() const { return page_size_; }
    int page_count() const { return static_cast<int>(skylines_.size()); }

  private:
    bool place_in_page(std::vector<int>& skyline, int width, int height, int& x, int& y) const;

    int page_size_;
    std::vector<std::vector<int>> skylines_;  // per page, used height of each column
};

}  // namespace nq::npr::classic
