// Parse errors: every failure names the file, the byte offset and the problem.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace nq {

struct Error {
    std::string file;     // name of the file (or pak entry) being read
    uint64_t offset = 0;  // byte offset in that file where the problem was found
    std::string message;  // what is wrong, e.g. "frame 3 extends past end of file"

    // "progs/ogre.mdl: offset 1234: frame 3 extends past end of file"
    std::string to_string() const;
};

// Thrown only *inside* parsers (by ByteReader and format checks) and always caught at the
// parser's public entry point, which returns it as Result<T>. It never escapes a library call.
class FormatError : public std::runtime_error {
public:
    explicit FormatError(Error e) : std::runtime_error(e.to_string()), error_(std::move(e)) {}
    const Error& error() const { return error_; }

private:
    Error error_;
};

}  // namespace nq
