// Result<T>: a value or an Error. What every parser returns (C++20 has no std::expected).
#pragma once

#include <cassert>
#include <exception>
#include <new>
#include <utility>
#include <variant>

#include "common/error.h"

namespace nq {

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : v_(std::move(value)) {}
    Result(Error error) : v_(std::move(error)) {}

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }

    T& value() & { assert(ok()); return std::get<0>(v_); }
    const T& value() const& { assert(ok()); return std::get<0>(v_); }
    T&& value() && { assert(ok()); return std::get<0>(std::move(v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }

    const Error& error() const { assert(!ok()); return std::get<1>(v_); }

private:
    std::variant<T, Error> v_;
};

// Runs a parser body that may throw FormatError (from ByteReader) and turns the throw into a
// returned Error. Allocation failure from a lying size is reported the same way, never aborts.
template <class F>
auto capture_errors(const std::string& file, F&& body) -> Result<decltype(body())> {
    try {
        return body();
    } catch (const FormatError& e) {
        return e.error();
    } catch (const std::bad_alloc&) {
        return Error{file, 0, "out of memory while parsing (sizes in the file are implausible)"};
    } catch (const std::length_error&) {
        return Error{file, 0, "implausible size in file"};
    }
}

}  // namespace nq
