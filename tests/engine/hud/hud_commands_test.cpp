// The HUD's console commands: Quake's screen-size keys step viewsize by 10 within 30..120, and
// the commands go with the HUD.
#include <gtest/gtest.h>

#include "host/host_core.h"
#include "hud/hud.h"

namespace nq {
namespace {

float viewsize(HostCore& host) {
    return host.cvars().find("viewsize")->value();
}

void run(HostCore& host, const char* text) {
    host.commands().add_text(text);
    host.commands().execute();
}

TEST(HudCommands, SizeupAndSizedownStepTheViewsizeWithinItsRange) {
    HostCore host;
    {
        Hud hud(host);
        EXPECT_EQ(viewsize(host), 100.0f);
        run(host, "sizeup\n");
        EXPECT_EQ(viewsize(host), 110.0f);
        run(host, "sizeup; sizeup; sizeup\n");
        EXPECT_EQ(viewsize(host), 120.0f) << "120 is the largest";
        run(host, "viewsize 35; sizedown\n");
        EXPECT_EQ(viewsize(host), 30.0f) << "30 is the smallest";
        run(host, "sizedown\n");
        EXPECT_EQ(viewsize(host), 30.0f);
        run(host, "sizeup; sizeup\n");
        EXPECT_EQ(viewsize(host), 50.0f);
        EXPECT_TRUE(host.commands().has_command("sizeup"));
    }
    EXPECT_FALSE(host.commands().has_command("sizeup")) << "removed with the HUD";
    EXPECT_FALSE(host.commands().has_command("+showscores"));
}

}  // namespace
}  // namespace nq
