// Quake's attract loop as a list (app/demo_loop.h): the order it plays, and when it gives up —
// only once every demo of it has failed one after another.
#include <gtest/gtest.h>

#include "app/sessions/demo_loop.h"

namespace nq {
namespace {

TEST(DemoLoop, PlaysItsDemosInTurnAndWraps) {
    DemoLoop loop;
    EXPECT_EQ(loop.next(), "");
    loop.set({"demo1", "demo2"});
    EXPECT_EQ(loop.next(), "demo1");
    EXPECT_EQ(loop.next(), "demo2");
    EXPECT_EQ(loop.next(), "demo1");
    loop.set({"a", "b", "c", "d", "e", "f", "g", "h", "i"});
    EXPECT_EQ(loop.names().size(), kMaxLoopDemos);
}

TEST(DemoLoop, StopsOnlyWhenEveryDemoFailedInARow) {
    DemoLoop loop;
    loop.set({"demo1", "demo2", "demo3"});
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_FALSE(loop.demo_ended(true)) << "three of three failed";
    // Stopped: a later `demos` gives every demo another try.
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_TRUE(loop.demo_ended(false)) << "one that played resets the count";
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_FALSE(loop.demo_ended(true));
}

TEST(DemoLoop, ANewListStartsTheCountAfresh) {
    DemoLoop loop;
    loop.set({"demo1", "demo2"});
    EXPECT_TRUE(loop.demo_ended(true));
    loop.set({"demo1", "demo2"});
    EXPECT_TRUE(loop.demo_ended(true));
    EXPECT_FALSE(loop.demo_ended(true));
    DemoLoop one;
    one.set({"demo"});
    EXPECT_FALSE(one.demo_ended(true)) << "a loop of one broken demo stops at once";
    EXPECT_TRUE(one.demo_ended(false));
}

}  // namespace
}  // namespace nq
