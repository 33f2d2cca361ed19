#include "app/sessions/demo_loop.h"

namespace nq {

void DemoLoop::set(std::vector<std::string> names) {
    if (names.size() > kMaxLoopDemos) names.resize(kMaxLoopDemos);
    names_ = std::move(names);
    next_ = 0;
    failed_in_a_row_ = 0;
}

std::string DemoLoop::next() {
    if (names_.empty()) return {};
    if (next_ >= names_.size()) next_ = 0;
    return names_[next_++];
}

bool DemoLoop::demo_ended(bool failed) {
    failed_in_a_row_ = failed ? failed_in_a_row_ + 1 : 0;
    if (failed_in_a_row_ < names_.size()) return true;
    failed_in_a_row_ = 0;  // stopped: a later `demos` gives every demo another try
    return false;
}

}  // namespace nq
