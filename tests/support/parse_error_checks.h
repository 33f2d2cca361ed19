// How the parser tests check an error: the offset it names and a phrase of its message.
#pragma once

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "common/error.h"

namespace nq::test {

inline void expect_error(const Error& e, uint64_t offset, const std::string& text) {
    EXPECT_EQ(e.offset, offset) << e.to_string();
    EXPECT_NE(e.message.find(text), std::string::npos) << e.to_string();
}

}  // namespace nq::test
