// The live instances of a C++ renderer plugin. Hooks carry no instance pointer, so a plugin
// keeps its state in globals, and `r_plugin NAME` with NAME already active loads the same
// library image again: the engine calls init() for the new instance *before* shutdown() for the
// old one (a swap is transactional). With one global the new instance would be destroyed by the
// old one's shutdown. So: init appends, shutdown retires the oldest, hooks use the newest.
#pragma once

#include <deque>
#include <memory>
#include <utility>

namespace nq::npr {

template <class Instance>
class PluginInstances {
  public:
    void add(std::unique_ptr<Instance> instance) { instances_.push_back(std::move(instance)); }
    void retire_oldest() {
        if (!instances_.empty()) instances_.pop_front();
    }
    Instance& current() { return *instances_.back(); }
    bool empty() const { return instances_.empty(); }

  private:
    std::deque<std::unique_ptr<Instance>> instances_;
};

}  // namespace nq::npr
