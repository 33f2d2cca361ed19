// A light structural check of JSON a tool printed: one top-level object, brackets balanced and
// nested outside strings, no raw control character inside a string (JSON forbids them).
#pragma once

#include <string>

namespace nq::test {

bool looks_like_json_object(const std::string& text);

}  // namespace nq::test
