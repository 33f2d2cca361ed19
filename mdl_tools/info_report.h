// Rendering one parsed model (or one failure) for `mdltool info`: a human table or JSON.
#pragma once

#include <ostream>
#include <string>

#include "common/error.h"
#include "common/json_writer.h"
#include "formats/mdl.h"

namespace nq::mdltool {

void print_info_text(std::ostream& out, const std::string& path, const Mdl& mdl);
void write_info_json(JsonWriter& json, const std::string& path, const Mdl& mdl);
void write_error_json(JsonWriter& json, const std::string& path, const Error& error);

}  // namespace nq::mdltool
