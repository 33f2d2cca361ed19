#include "illustrative/kuwahara_filter.h"

#include <algorithm>

namespace nq::npr::illustrative {
namespace {

// One summed-area table entry: sums of R, G, B and R^2 + G^2 + B^2 (modulo 2^32).
struct Sums {
    uint32_t r, g, b, sq;
};

int wrap(int i, int size) {
    return ((i % size) + size) % size;
}

// Table over the image padded by `pad` wrapped pixels on every side: entry (x, y) holds the
// sums over padded pixels [0, x) x [0, y), so it is (w + 1) x (h + 1) for padded size w x h.
class SummedAreaTable {
  public:
    SummedAreaTable(std::span<const uint8_t> rgb, int width, int height, int pad)
        : stride_(width + 2 * pad + 1), table_(size_t(stride_) * size_t(height + 2 * pad + 1)) {
        const int padded_w = width + 2 * pad, padded_h = height + 2 * pad;
        // Source byte offset of each padded column, wrapped once here instead of per texel.
        std::vector<uint32_t> column(static_cast<size_t>(padded_w));
        for (int x = 0; x < padded_w; ++x) column[size_t(x)] = uint32_t(wrap(x - pad, width) * 3);
        for (int y = 0; y < padded_h; ++y) {
            const uint8_t* row = rgb.data() + size_t(wrap(y - pad, height)) * size_t(width) * 3;
            Sums running{0, 0, 0, 0};
            const Sums* above = &table_[size_t(y) * size_t(stride_)];
            Sums* here = &table_[size_t(y + 1) * size_t(stride_)];
            for (int x = 0; x < padded_w; ++x) {
                const uint8_t* p = row + column[size_t(x)];
                const uint32_t r = p[0], g = p[1], b = p[2];
                running.r += r;
                running.g += g;
                running.b += b;
                running.sq += r * r + g * g + b * b;
                here[x + 1] = {above[x + 1].r + running.r, above[x + 1].g + running.g,
                               above[x + 1].b + running.b, above[x + 1].sq + running.sq};
            }
        }
    }

    // Sums over padded pixels [x0, x1) x [y0, y1).
    Sums box(int x0, int y0, int x1, int y1) const {
        const Sums& a = at(x1, y1);
        const Sums& b = at(x0, y1);
        const Sums& c = at(x1, y0);
        const Sums& d = at(x0, y0);
        return {a.r - b.r - c.r + d.r, a.g - b.g - c.g + d.g, a.b - b.b - c.b + d.b,
                a.sq - b.sq - c.sq + d.sq};
    }

  private:
    const Sums& at(int x, int y) const { return table_[size_t(y) * size_t(stride_) + size_t(x)]; }
    int stride_;
    std::vector<Sums> table_;
};

// One (radius + 1)^2 box: its mean colour and its spread n^2 * (sum of channel variances)
// = n * sum(sq) - |sum|^2, which orders boxes by variance without a division.
struct Box {
    float spread;
    uint8_t mean[3];
};

// Every box whose top-left is at padded (bx, by), bx < width + radius, by < height + radius:
// each pixel's four quadrants are four of these, so each box is summed once, not four times.
std::vector<Box> quadrant_boxes(const SummedAreaTable& sat, int width, int height, int radius) {
    const int boxes_w = width + radius, boxes_h = height + radius;
    const uint32_t n = uint32_t(radius + 1) * uint32_t(radius + 1);
    const float inv_n = 1.0f / float(n);
    std::vector<Box> boxes(size_t(boxes_w) * size_t(boxes_h));
    Box* out = boxes.data();
    for (int by = 0; by < boxes_h; ++by) {
        for (int bx = 0; bx < boxes_w; ++bx, ++out) {
            const Sums s = sat.box(bx, by, bx + radius + 1, by + radius + 1);
            const uint64_t spread =
                uint64_t(n) * s.sq -
                (uint64_t(s.r) * s.r + uint64_t(s.g) * s.g + uint64_t(s.b) * s.b);
            out->spread = float(spread);
            out->mean[0] = uint8_t(float(s.r) * inv_n + 0.5f);
            out->mean[1] = uint8_t(float(s.g) * inv_n + 0.5f);
            out->mean[2] = uint8_t(float(s.b) * inv_n + 0.5f);
        }
    }
    return boxes;
}

}  // namespace

void kuwahara_filter(std::span<const uint8_t> rgb, int width, int height, int radius,
                     std::vector<uint8_t>& out) {
    if (width <= 0 || height <= 0 || rgb.size() != size_t(width) * size_t(height) * 3) {
        out.clear();
        return;
    }
    out.assign(rgb.begin(), rgb.end());
    radius = std::min(radius, kMaxKuwaharaRadius);
    if (radius <= 0) return;
    const std::vector<Box> boxes =
        quadrant_boxes(SummedAreaTable(rgb, width, height, radius), width, height, radius);
    const size_t stride = size_t(width + radius);
    uint8_t* o = out.data();
    for (int y = 0; y < height; ++y) {
        // Pixel (x, y) is padded (x + r, y + r); its quadrants start at padded x or x + r,
        // y or y + r. Ties go to the first of top-left, top-right, bottom-left, bottom-right.
        const Box* top = &boxes[size_t(y) * stride];
        const Box* bottom = top + size_t(radius) * stride;
        for (int x = 0; x < width; ++x, o += 3) {
            const Box* q[4] = {top + x, top + x + radius, bottom + x, bottom + x + radius};
            const Box* best = q[0];
            for (int k = 1; k < 4; ++k) {
                if (q[k]->spread < best->spread) best = q[k];
            }
            o[0] = best->mean[0];
            o[1] = best->mean[1];
            o[2] = best->mean[2];
        }
    }
}

}  // namespace nq::npr::illustrative
