#include "adjacency_progress.h"

#include <unistd.h>

#include <cstdio>

namespace nq::mdltool {

namespace {

constexpr size_t kBarWidth = 30;
constexpr size_t kNameWidth = 40;

}  // namespace

ProgressBar::ProgressBar(size_t total)
    : total_(total), enabled_(total > 1 && isatty(STDERR_FILENO) == 1) {}

void ProgressBar::show(size_t done, const std::string& current) {
    if (!enabled_) return;
    const size_t filled = total_ ? done * kBarWidth / total_ : kBarWidth;
    std::string bar(filled, '#');
    bar.resize(kBarWidth, '.');
    const std::string name = current.size() > kNameWidth
                                 ? "..." + current.substr(current.size() - kNameWidth + 3)
                                 : current;
    std::fprintf(stderr, "\r\033[K[%s] %zu/%zu %s", bar.c_str(), done, total_, name.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressBar::clear() {
    if (!drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    drawn_ = false;
}

}  // namespace nq::mdltool
