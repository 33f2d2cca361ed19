#include "support/synth_sav.h"

namespace nq::test {

namespace {

void write_block(std::string& out, const SynthSav::Pairs& pairs, const std::string& nl) {
    out += "{" + nl;
    for (const auto& [key, value] : pairs) out += "\"" + key + "\" \"" + value + "\"" + nl;
    out += "}" + nl;
}

std::vector<uint8_t> bytes(const std::string& text) {
    return {text.begin(), text.end()};
}

}  // namespace

std::string write_sav(const SynthSav& sav) {
    const std::string& nl = sav.newline;
    std::string out = sav.version + nl + sav.comment + nl;
    for (size_t i = 0; i < 16; ++i) {
        out += (i < sav.parms.size() ? sav.parms[i] : std::string("0.000000")) + nl;
    }
    out += sav.skill + nl + sav.map + nl + sav.time + nl;
    for (size_t i = 0; i < 64; ++i) {
        out += (i < sav.lightstyles.size() ? sav.lightstyles[i] : std::string("m")) + nl;
    }
    write_block(out, sav.globals, nl);
    for (const SynthSav::Pairs& edict : sav.edicts) write_block(out, edict, nl);
    return out + sav.trailing;
}

SynthSav minimal_sav() {
    SynthSav sav;
    sav.parms = {"4096.000000", "100.000000", "0.000000", "25.000000", "0.000000",
                 "0.000000",    "0.000000",   "1.000000", "0.000000",  "0.000000"};
    sav.lightstyles = {"m", "mmnmmommommnonmmonqnmmo",
                       "abcdefghijklmnopqrstuvwxyzyxwvutsrqponmlkjihgfedcba"};
    sav.globals = {{"self", "0"},
                   {"time", "3.250000"},
                   {"mapname", "start"},
                   {"total_monsters", "9.000000"},
                   {"killed_monsters", "0.000000"},
                   {"v_forward_x", "1.000000"}};
    sav.edicts = {
        {{"modelindex", "1.000000"},
         {"absmax", "2048.000000 2048.000000 1024.000000"},
         {"movetype", "7.000000"},
         {"solid", "4.000000"},
         {"classname", "worldspawn"},
         {"model", "maps/start.bsp"},
         {"message", "LibreQuake Start"}},
        {{"movetype", "3.000000"},
         {"solid", "3.000000"},
         {"origin", "480.000000 -352.000000 88.031250"},
         {"angles", "0.000000 90.000000 0.000000"},
         {"classname", "player"},
         {"health", "100.000000"},
         {"items", "4097.000000"},
         {"ammo_shells", "25.000000"},
         {"think", "player_stand1"},
         {"netname", "player"},
         {"mins", "-16.000000 -16.000000 -24.000000"},
         {"maxs", "16.000000 16.000000 32.000000"}},
        {},
    };
    return sav;
}

std::vector<SeedFile> synthetic_sav_seeds() {
    std::vector<SeedFile> seeds;
    const SynthSav base = minimal_sav();
    seeds.push_back({"minimal.sav", bytes(write_sav(base))});
    {  // Windows line ends, a Quake 1.06 float skill, QuakeSpasm-Spiked's commented extension
        SynthSav s = base;
        s.newline = "\r\n";
        s.skill = "2.000000";
        s.trailing =
            "/*\r\n// QuakeSpasm extended savegame\r\nsv.model_precache 1 maps/start.bsp\r\n*/\r\n";
        seeds.push_back({"crlf_extended.sav", bytes(write_sav(s))});
    }
    {  // escapes, an angle key, editor notes and a string with a brace
        SynthSav s = base;
        s.edicts.push_back({{"classname", "trigger_once"},
                            {"message", "Line one\\nline two {}"},
                            {"angle", "90"},
                            {"_note", "ignored"},
                            {"target", "t1"}});
        seeds.push_back({"keys.sav", bytes(write_sav(s))});
    }
    {  // malformed: wrong version, truncated, a bad number
        SynthSav s = base;
        s.version = "6";
        seeds.push_back({"version6.sav", bytes(write_sav(s))});
        const std::string text = write_sav(base);
        seeds.push_back({"truncated.sav", bytes(text.substr(0, text.size() / 2))});
        s = base;
        s.time = "3.25x";
        seeds.push_back({"bad_time.sav", bytes(write_sav(s))});
    }
    return seeds;
}

}  // namespace nq::test
