#include "app/demo_loop.h"

namespace nq {

void DemoLoop::set(std::vector<std::string> names) {
    if (names.size() > kMaxLoopDemos) names.resize(kMaxLoopDemos);
    names_ = std::move(names);
    next_ = 0;
}

std::string DemoLoop::next() {
    if (names_.empty()) return {};
    if (next_ >= names_.size()) next_ = 0;
    return names_[next_++];
}

}  // namespace nq
