#pragma once
// Machine-readable run reports (JSON).
#include <nlohmann/json.hpp>
#include <string>

namespace iga::io {

/// Writes a JSON report (pretty, 2-space indent, trailing newline). Strings that are not valid UTF-8 are
/// written with U+FFFD replacement characters. Throws InputError(path, 0, "cannot write file").
void write_json(const std::string& path, const nlohmann::json& report);

}  // namespace iga::io
