// The fixture the classic drawers' tests share: a GL context (GlSuiteTest), a test engine and a
// ClassicRenderer initialised before each test and shut down after it with no GL object left.
#pragma once

#include <string>

#include "classic/classic_renderer.h"
#include "support/nprlib_test_support.h"

namespace nq::npr::test {

template <class Suite>
class ClassicRendererSuite : public GlSuiteTest<Suite> {
  protected:
    void SetUp() override {
        GlSuiteTest<Suite>::SetUp();
        if (this->HasFatalFailure()) return;
        std::string error;
        ASSERT_TRUE(renderer_.init(&engine_.engine, &error)) << error;
    }
    void TearDown() override {
        renderer_.shutdown();
        EXPECT_EQ(renderer_.live_gl_objects(), 0);
    }

    Rgb colour(int index) const { return palette_colour(engine_.palette, index); }

    TestEngine engine_;
    classic::ClassicRenderer renderer_;
};

}  // namespace nq::npr::test
