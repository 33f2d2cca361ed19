// Shared by the host_*_test.cpp files: a HostCore whose console output is captured and whose
// scripts come from an in-memory file map.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "host/host_core.h"

namespace nq::test {

class HostFixture : public ::testing::Test {
  protected:
    explicit HostFixture(size_t buffer_bytes = kDefaultCommandBufferBytes) : host(buffer_bytes) {
        host.set_print([this](std::string_view text) { output += text; });
        host.set_file_reader([this](const std::string& path) -> std::optional<std::string> {
            auto it = files.find(path);
            if (it == files.end()) return std::nullopt;
            return it->second;
        });
    }

    // Adds `text` to the buffer, runs one frame, returns what it printed.
    std::string run(const std::string& text) {
        host.commands().add_text(text);
        return frame();
    }
    // Runs one frame of whatever is buffered, returns what it printed.
    std::string frame() {
        output.clear();
        host.commands().execute();
        return output;
    }

    HostCore host;
    std::string output;
    std::map<std::string, std::string> files;
};

}  // namespace nq::test
