// Quake's attract loop: `startdemos demo1 demo2 demo3` (quake.rc's last line) plays the listed
// demos one after another, again and again, while nothing else runs. Playing a map, loading a
// game or starting a demo by hand ends it; `demos` takes it up again, `stopdemo` ends it.
// A demo that cannot play (a broken level, a damaged file) is passed over; when every demo of
// the loop has failed in a row the loop stops, so a broken game directory never spins.
#pragma once

#include <string>
#include <vector>

namespace nq {

inline constexpr size_t kMaxLoopDemos = 8;  // Quake's MAX_DEMOS

class DemoLoop {
  public:
    // The demos of the loop, in order (at most kMaxLoopDemos kept); the loop starts over.
    void set(std::vector<std::string> names);
    const std::vector<std::string>& names() const { return names_; }

    // The demo to play now, advancing (wrapping) the loop; "" when the loop is empty.
    std::string next();

    // Whether the demo now playing came from the loop (its end plays the next one).
    bool playing() const { return playing_; }
    void set_playing(bool playing) { playing_ = playing; }

    // A demo of the loop ended, `failed` when it could not play. Returns whether the loop
    // goes on: false once every demo of the loop has failed one after another.
    bool demo_ended(bool failed);

  private:
    std::vector<std::string> names_;
    size_t next_ = 0;
    size_t failed_in_a_row_ = 0;
    bool playing_ = false;
};

}  // namespace nq
