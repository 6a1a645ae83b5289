#pragma once
// Machine-readable run reports (JSON).
#include <nlohmann/json.hpp>
#include <string>

namespace iga::io {

/// Whether an output option names a file to write: "none" (and "") means "do not write", in every program.
inline bool writes(const std::string& path) { return !path.empty() && path != "none"; }

/// Writes text to a file, or to standard output when path is "-"; every write is checked (a full disk, /dev/full):
/// InputError(path, 0, "cannot write file"), "stdout" for "-".
void write_text(const std::string& path, const std::string& text);

/// Writes a JSON report (pretty, 2-space indent, trailing newline) with write_text ("-": standard output). Strings that are not valid UTF-8 are
/// written with U+FFFD replacement characters. Throws InputError(path, 0, "cannot write file"), and
/// NumericalError naming the key when a number in the report is NaN or infinite (null means "not requested").
void write_json(const std::string& path, const nlohmann::json& report);

}  // namespace iga::io
