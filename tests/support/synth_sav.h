// A writer for synthetic save files in Quake's text format (version 5): fuzz seeds and test
// fixtures. It writes exactly what it is given, in Quake's layout, without knowing any progs,
// so tests can build both valid saves and every malformed variation.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "support/seed_file.h"

namespace nq::test {

struct SynthSav {
    using Pairs = std::vector<std::pair<std::string, std::string>>;

    std::string version = "5";
    std::string comment = "LibreQuake_Start_______kills:__0/__9____";
    std::vector<std::string> parms;  // 16 by default ("%f" text)
    std::string skill = "1";
    std::string map = "start";
    std::string time = "3.250000";
    std::vector<std::string> lightstyles;  // 64 by default
    Pairs globals;
    std::vector<Pairs> edicts;  // no pairs: a free edict
    std::string newline = "\n";
    std::string trailing;  // appended after the last edict
};

std::string write_sav(const SynthSav& sav);

// A small save of 'start': the world, the player and one free edict.
SynthSav minimal_sav();

// Valid and malformed saves for fuzzing.
std::vector<SeedFile> synthetic_sav_seeds();

}  // namespace nq::test
