// A one-line progress bar on stderr for long batches, drawn only when stderr is a terminal (so
// logs, pipes and tests never see it) and erased before anything else is printed.
#pragma once

#include <cstddef>
#include <string>

namespace nq::mdltool {

class ProgressBar {
  public:
    explicit ProgressBar(size_t total);  // shown only if total > 1 and stderr is a tty
    ~ProgressBar() { clear(); }
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void show(size_t done, const std::string& current);
    void clear();  // erase the line (call before writing other text to stderr)

  private:
    size_t total_;
    bool enabled_;
    bool drawn_ = false;
};

}  // namespace nq::mdltool
