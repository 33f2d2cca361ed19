#include "common/error.h"

namespace nq {

std::string Error::to_string() const {
    return file + ": offset " + std::to_string(offset) + ": " + message;
}

}  // namespace nq
