// Which edicts are in use. Edict 0 is the world and 1..max_clients the players; the rest are
// handed out by alloc() as Quake does: the lowest free edict that has been free for at least
// 0.5 s (so a client never sees a new entity take over an old one's interpolation), or a new one
// at the end. The VM's num_edicts() is the end of the used range.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "server/progs_layout.h"
#include "vm/vm.h"

namespace nq::server {

class EdictPool {
  public:
    static constexpr float kReuseDelay = 0.5f;

    // A new level: world and clients in use, nothing else.
    void reset(vm::Vm& vm, uint32_t max_clients);
    // A cleared edict, or nothing when every edict is taken.
    std::optional<uint32_t> alloc(vm::Vm& vm, double time);
    // Marks `edict` free at `time` and resets what Quake resets (model, solid, think, position;
    // QuakeC may still read the rest of a removed entity). The caller unlinks it.
    void free(vm::Vm& vm, const ProgsLayout& layout, uint32_t edict, double time);
    bool is_free(uint32_t edict) const { return edict >= free_.size() || free_[edict]; }
    float free_time(uint32_t edict) const {
        return edict < free_time_.size() ? free_time_[edict] : 0;
    }
    // For loading a saved game: edicts below `count` exist, `free` marks the free ones.
    void set_free(uint32_t edict, bool free);
    uint32_t max_clients() const { return max_clients_; }

  private:
    std::vector<uint8_t> free_;
    std::vector<float> free_time_;
    uint32_t max_clients_ = 1;
};

}  // namespace nq::server
