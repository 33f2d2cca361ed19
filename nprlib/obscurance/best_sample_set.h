// The best set a generator has seen so far: every candidate's Voronoi regions are measured, and
// the set whose measures are most even (sample_quality.h) is kept, its measures as its weights.
#pragma once

#include <span>
#include <vector>

#include "obscurance/discrete_voronoi.h"
#include "obscurance/sample_quality.h"
#include "obscurance/sample_sets.h"

namespace nq::npr::obscurance {

template <int Dimension>
class BestSampleSet {
  public:
    // Offers positions whose regions are already computed; true when they become the best.
    bool offer(std::span<const Vec<Dimension>> positions,
               const VoronoiRegions<Dimension>& regions) {
        const SampleQuality quality = measure_quality(regions.measures);
        if (found_ && !is_better(quality, quality_)) return false;
        found_ = true;
        quality_ = quality;
        set_.positions.assign(positions.begin(), positions.end());
        set_.weights = regions.measures;
        return true;
    }

    bool found() const { return found_; }
    const SampleSet<Dimension>& set() const { return set_; }
    const SampleQuality& quality() const { return quality_; }

  private:
    bool found_ = false;
    SampleQuality quality_;
    SampleSet<Dimension> set_;
};

}  // namespace nq::npr::obscurance
