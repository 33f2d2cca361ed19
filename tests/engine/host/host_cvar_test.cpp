#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "host/cvar_registry.h"
#include "host/number_text.h"

namespace nq {
namespace {

CvarSpec spec(std::string name, std::string value, uint32_t flags = 0, std::string help = {}) {
    CvarSpec s;
    s.name = std::move(name);
    s.default_value = std::move(value);
    s.flags = flags;
    s.description = std::move(help);
    return s;
}

CvarSpec ranged(std::string name, std::string value, float lo, float hi) {
    CvarSpec s = spec(std::move(name), std::move(value));
    s.min_value = lo;
    s.max_value = hi;
    return s;
}

constexpr OwnerId kPlugin = 7;

TEST(HostCvar, RegisterStartsAtDefaultWithNumberForms) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("r_Outline", "2.75", kCvarArchive, "outline width"));
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->name(), "r_Outline");
    EXPECT_EQ(c->string(), "2.75");
    EXPECT_FLOAT_EQ(c->value(), 2.75f);
    EXPECT_EQ(c->integer(), 2);
    EXPECT_EQ(c->default_value(), "2.75");
    EXPECT_EQ(c->description(), "outline width");
    EXPECT_EQ(c->flags(), uint32_t{kCvarArchive});
    EXPECT_EQ(c->owner(), kEngineOwner);
    EXPECT_EQ(c->modified_count(), 0u);  // starting at the default is not a change
    const CvarValue* v = c->value_ptr();
    EXPECT_STREQ(v->string, "2.75");
    EXPECT_FLOAT_EQ(v->value, 2.75f);
    EXPECT_EQ(v->integer, 2);
}

TEST(HostCvar, LookupIgnoresCase) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("Sensitivity", "3"));
    EXPECT_EQ(reg.find("sensitivity"), c);
    EXPECT_EQ(reg.find("SENSITIVITY"), c);
    EXPECT_EQ(reg.find("sensitivit"), nullptr);
    EXPECT_EQ(reg.size(), 1u);
}

TEST(HostCvar, SetUpdatesTextNumbersAndCount) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("volume", "0.7"));
    EXPECT_EQ(reg.set("VOLUME", "-3.9"), CvarSetResult::kChanged);
    EXPECT_EQ(c->string(), "-3.9");
    EXPECT_FLOAT_EQ(c->value(), -3.9f);
    EXPECT_EQ(c->integer(), -3);  // truncated toward zero, like a C cast
    EXPECT_EQ(c->modified_count(), 1u);
    EXPECT_EQ(reg.set("volume", "-3.9"), CvarSetResult::kUnchanged);
    EXPECT_EQ(c->modified_count(), 1u);
    EXPECT_EQ(reg.set("nosuch", "1"), CvarSetResult::kNotFound);
}

TEST(HostCvar, NonNumericTextFollowsAtof) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("name", "player"));
    EXPECT_EQ(c->value(), 0.0f);
    reg.set(*c, "1.5abc");
    EXPECT_FLOAT_EQ(c->value(), 1.5f);
    reg.set(*c, "  +4");
    EXPECT_FLOAT_EQ(c->value(), 4.0f);
    reg.set(*c, "nan");
    EXPECT_EQ(c->value(), 0.0f);  // no cvar ever holds NaN
    reg.set(*c, "1e10");
    EXPECT_EQ(c->integer(), std::numeric_limits<int32_t>::max());  // saturated, no UB
    reg.set(*c, "-1e10");
    EXPECT_EQ(c->integer(), std::numeric_limits<int32_t>::min());
    reg.set(*c, "1e400");
    EXPECT_TRUE(std::isinf(c->value()));
    reg.set(*c, "1e-400");
    EXPECT_EQ(c->value(), 0.0f);
    EXPECT_EQ(c->string(), "1e-400");  // the text is kept as typed
}

TEST(HostCvar, NumericCvarsAreClampedAndRefuseText) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(ranged("r_edge", "1", 0.0f, 10.0f));
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(reg.set(*c, "15"), CvarSetResult::kClamped);
    EXPECT_EQ(c->string(), "10");
    EXPECT_EQ(reg.set(*c, "-0.25"), CvarSetResult::kClamped);
    EXPECT_EQ(c->string(), "0");
    EXPECT_EQ(reg.set(*c, "0.50"), CvarSetResult::kChanged);
    EXPECT_EQ(c->string(), "0.50");  // in range: the user's spelling is kept
    EXPECT_EQ(reg.set(*c, "lots"), CvarSetResult::kNotNumeric);
    EXPECT_EQ(reg.set(*c, "3x"), CvarSetResult::kNotNumeric);
    EXPECT_EQ(reg.set(*c, "nan"), CvarSetResult::kNotNumeric);
    EXPECT_EQ(c->string(), "0.50");
    EXPECT_EQ(reg.set(*c, " 7 "), CvarSetResult::kChanged);
    EXPECT_EQ(c->integer(), 7);
    EXPECT_EQ(describe_range(*c), "between 0 and 10");
}

TEST(HostCvar, OneSidedRangeAndClampedDefault) {
    CvarRegistry reg;
    CvarSpec s = spec("gamma", "-2");
    s.min_value = 0.5f;
    Cvar* c = reg.register_cvar(s);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(c->default_value(), "0.5");  // a default outside the range is clamped too
    EXPECT_EQ(c->string(), "0.5");
    EXPECT_EQ(describe_range(*c), "of at least 0.5");
    EXPECT_EQ(reg.set(*c, "1000"), CvarSetResult::kChanged);
}

TEST(HostCvar, InvalidSpecsAreRefused) {
    CvarRegistry reg;
    EXPECT_EQ(reg.register_cvar(spec("", "1")), nullptr);
    EXPECT_EQ(reg.register_cvar(spec("has space", "1")), nullptr);
    EXPECT_EQ(reg.register_cvar(spec("semi;colon", "1")), nullptr);
    EXPECT_EQ(reg.register_cvar(spec("quo\"te", "1")), nullptr);
    EXPECT_EQ(reg.register_cvar(spec("//comment", "1")), nullptr);
    EXPECT_EQ(reg.register_cvar(spec(std::string(65, 'a'), "1")), nullptr);
    EXPECT_EQ(reg.register_cvar(ranged("backwards", "1", 5.0f, 1.0f)), nullptr);
    EXPECT_EQ(reg.register_cvar(ranged("nanrange", "1", std::nanf(""), 1.0f)), nullptr);
    EXPECT_EQ(reg.register_cvar(ranged("textdefault", "fast", 0.0f, 1.0f)), nullptr);
    EXPECT_EQ(reg.size(), 0u);
    EXPECT_NE(reg.register_cvar(spec(std::string(64, 'a'), "1")), nullptr);
}

TEST(HostCvar, ReadOnlyRefusesTheUserNotTheEngine) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("version", "0.1", kCvarReadOnly));
    EXPECT_EQ(reg.set(*c, "9", CvarSource::kUser), CvarSetResult::kReadOnly);
    EXPECT_EQ(reg.set_or_create("version", "9", kCvarArchive), CvarSetResult::kReadOnly);
    EXPECT_EQ(c->string(), "0.1");
    EXPECT_FALSE(c->has_flag(kCvarArchive));  // a refused seta archives nothing
    EXPECT_EQ(reg.set(*c, "0.2", CvarSource::kEngine), CvarSetResult::kChanged);
    EXPECT_EQ(c->string(), "0.2");
}

TEST(HostCvar, CallbacksRunOncePerChange) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("fov", "90"));
    std::vector<std::string> seen;
    reg.add_callback(*c, [&](const Cvar& cv) { seen.push_back(cv.string()); });
    reg.set(*c, "100");
    reg.set(*c, "100");  // unchanged: no call
    reg.set(*c, "110");
    reg.reset(*c);
    EXPECT_EQ(seen, (std::vector<std::string>{"100", "110", "90"}));
}

TEST(HostCvar, CallbacksAreRemovedByIdAndByOwner) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("r_ink", "1", kCvarPlugin), kPlugin);
    int engine_calls = 0, plugin_calls = 0;
    CvarCallbackId engine_id = reg.add_callback(*c, [&](const Cvar&) { ++engine_calls; });
    reg.add_callback(
        *c, [&](const Cvar&) { ++plugin_calls; }, kPlugin);
    reg.add_callback(
        *c, [&](const Cvar&) { ++plugin_calls; }, kPlugin);
    EXPECT_NE(engine_id, 0u);
    reg.set(*c, "2");
    EXPECT_EQ(engine_calls, 1);
    EXPECT_EQ(plugin_calls, 2);

    reg.release_owner(kPlugin);  // the plugin unloads: its code must never be called again
    EXPECT_EQ(c->owner(), kNoOwner);
    reg.set(*c, "3");
    EXPECT_EQ(engine_calls, 2);
    EXPECT_EQ(plugin_calls, 2);
    EXPECT_EQ(c->string(), "3");  // the cvar itself lives on

    EXPECT_TRUE(reg.remove_callback(engine_id));
    EXPECT_FALSE(reg.remove_callback(engine_id));
    reg.set(*c, "4");
    EXPECT_EQ(engine_calls, 2);
}

TEST(HostCvar, CallbackMayRemoveOthersAndSetItsOwnCvar) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("r_mode", "0"));
    int second_calls = 0;
    int first_calls = 0;
    CvarCallbackId second = 0;
    reg.add_callback(*c, [&](const Cvar& cv) {
        ++first_calls;
        reg.remove_callback(second);     // removed while notifications are running
        reg.set(*c, cv.string() + "!");  // re-entrant change: applied, not re-notified
    });
    second = reg.add_callback(*c, [&](const Cvar&) { ++second_calls; });
    reg.set(*c, "1");
    EXPECT_EQ(first_calls, 1);
    EXPECT_EQ(second_calls, 0);
    EXPECT_EQ(c->string(), "1!");
    EXPECT_EQ(c->modified_count(), 2u);
}

TEST(HostCvar, ReRegistrationKeepsTheUsersValue) {
    CvarRegistry reg;
    CvarSpec v1 = ranged("r_hatch", "1", 0.0f, 8.0f);
    v1.flags = kCvarPlugin | kCvarArchive;
    v1.description = "hatching layers";
    Cvar* c = reg.register_cvar(v1, kPlugin);
    const CvarValue* view = c->value_ptr();
    reg.set(*c, "6", CvarSource::kUser);
    reg.release_owner(kPlugin);

    CvarSpec v2 = ranged("R_HATCH", "2", 0.0f, 4.0f);  // the next build: new default and range
    v2.flags = kCvarPlugin;
    v2.description = "hatching layers (max 4)";
    EXPECT_EQ(reg.register_cvar(v2, kPlugin + 1), c);
    EXPECT_EQ(c->value_ptr(), view);
    EXPECT_EQ(c->name(), "R_HATCH");
    EXPECT_EQ(c->string(), "4");  // the user's 6, clamped into the new range
    EXPECT_EQ(c->default_value(), "2");
    EXPECT_EQ(c->description(), "hatching layers (max 4)");
    EXPECT_EQ(c->flags(), uint32_t{kCvarPlugin});
    EXPECT_EQ(c->owner(), kPlugin + 1);
    EXPECT_EQ(reg.size(), 1u);
}

TEST(HostCvar, ReRegistrationAdoptsANewDefaultWhenUntouched) {
    CvarRegistry reg;
    Cvar* c = reg.register_cvar(spec("r_paper", "white"), kPlugin);
    reg.register_cvar(spec("r_paper", "cream"), kPlugin);
    EXPECT_EQ(c->string(), "cream");
    EXPECT_EQ(c->modified_count(), 1u);
}

TEST(HostCvar, ValuesSetBeforeRegistrationAreApplied) {
    CvarRegistry reg;
    // config.cfg ran before the plugin loaded.
    EXPECT_EQ(reg.set_or_create("r_Sketch", "7", kCvarArchive), CvarSetResult::kChanged);
    Cvar* early = reg.find("r_sketch");
    ASSERT_NE(early, nullptr);
    EXPECT_EQ(early->flags(), uint32_t{kCvarUserCreated | kCvarArchive});
    const CvarValue* view = early->value_ptr();

    CvarSpec s = ranged("r_sketch", "1", 0.0f, 5.0f);
    s.flags = kCvarPlugin;
    Cvar* c = reg.register_cvar(s, kPlugin);
    EXPECT_EQ(c, early);
    EXPECT_EQ(c->value_ptr(), view);
    EXPECT_EQ(c->string(), "5");  // kept, clamped to the registered range
    // Registered now; `seta` asked for archiving, which registration keeps.
    EXPECT_EQ(c->flags(), uint32_t{kCvarPlugin | kCvarArchive});

    reg.set_or_create("r_words", "hello", 0);
    Cvar* words = reg.register_cvar(ranged("r_words", "2", 0.0f, 3.0f));
    EXPECT_EQ(words->string(), "2");  // text is no number: the default wins

    reg.set_or_create("sv_locked", "1", 0);
    Cvar* locked = reg.register_cvar(spec("sv_locked", "0", kCvarReadOnly));
    EXPECT_EQ(locked->string(), "0");  // read-only: the user's value is not applied
}

TEST(HostCvar, SetOrCreateValidatesNames) {
    CvarRegistry reg;
    EXPECT_EQ(reg.set_or_create("bad name", "1", 0), CvarSetResult::kInvalidName);
    EXPECT_EQ(reg.size(), 0u);
}

TEST(HostCvar, StablePointerSurvivesManyRegistrations) {
    CvarRegistry reg;
    Cvar* first = reg.register_cvar(spec("r_first", "1"));
    const CvarValue* view = first->value_ptr();
    for (int i = 0; i < 5000; ++i) {
        ASSERT_NE(reg.register_cvar(spec("r_filler" + std::to_string(i), std::to_string(i))),
                  nullptr);
    }
    reg.set("r_first", "a much longer value than any small-string buffer holds, 42");
    reg.register_cvar(spec("r_first", "1"));  // registered again
    EXPECT_EQ(reg.find("r_first")->value_ptr(), view);
    EXPECT_STREQ(view->string, "a much longer value than any small-string buffer holds, 42");
    EXPECT_EQ(view->modified_count, 1u);
    EXPECT_STREQ(reg.find("r_filler4999")->value_ptr()->string, "4999");
    EXPECT_EQ(reg.size(), 5001u);
}

TEST(HostCvar, ListIsSortedAndFiltered) {
    CvarRegistry reg;
    for (const char* name : {"r_zeta", "cl_speed", "R_alpha", "r_Mid"}) {
        reg.register_cvar(spec(name, "0"));
    }
    std::vector<std::string> names;
    for (const Cvar* c : reg.list("r_")) names.push_back(c->name());
    EXPECT_EQ(names, (std::vector<std::string>{"R_alpha", "r_Mid", "r_zeta"}));
    EXPECT_EQ(reg.list().size(), 4u);
    EXPECT_TRUE(reg.list("x").empty());
}

TEST(HostNumberText, ParsesAndFormatsIndependentOfLocale) {
    EXPECT_EQ(parse_number_exact("12.5"), 12.5f);
    EXPECT_EQ(parse_number_exact(" -3 "), -3.0f);
    EXPECT_EQ(parse_number_exact("+2"), 2.0f);
    EXPECT_EQ(parse_number_exact(".5"), 0.5f);
    EXPECT_EQ(parse_number_exact(""), std::nullopt);
    EXPECT_EQ(parse_number_exact("1 2"), std::nullopt);
    EXPECT_EQ(parse_number_exact("0x10"), std::nullopt);
    EXPECT_EQ(parse_number_prefix("0x10"), 0.0f);  // atof without hex: the "0"
    EXPECT_EQ(format_number(1.0f), "1");
    EXPECT_EQ(format_number(0.1f), "0.1");
    EXPECT_EQ(format_number(-0.0f), "0");
    EXPECT_EQ(format_number(1024.5f), "1024.5");
    EXPECT_EQ(saturating_int(-2.9f), -2);
    EXPECT_EQ(saturating_int(std::nanf("")), 0);
    EXPECT_EQ(saturating_int(2147483648.0f), std::numeric_limits<int32_t>::max());
    EXPECT_EQ(saturating_int(2147483520.0f), 2147483520);  // largest float below 2^31
}

}  // namespace
}  // namespace nq
