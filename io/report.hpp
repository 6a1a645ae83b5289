#pragma once
// Machine-readable run reports (JSON).
#include <nlohmann/json.hpp>
#include <string>

namespace iga::io {

/// Whether an output option names a file to write: "none" (and "") means "do not write", in every program.
inline bool writes(const std::string& path) { return !path.empty() && path != "none"; }

/// Checks before the work that an output option's file can be written, so that a run is not wasted on a path it will
/// refuse at the end: a folder that does not exist, a path that is a folder, a file or folder without write permission,
/// and a device that takes no byte (/dev/full) give InputError(path, 0, "cannot write file"), the line the write itself
/// would give. Nothing is left behind: an existing file keeps its content (opened to append, nothing written), a new
/// one is created and removed again. "-", "none" and "" are not checked.
void check_writable(const std::string& path);

/// Writes text to a file, or to standard output when path is "-"; every write is checked (a full disk, /dev/full):
/// InputError(path, 0, "cannot write file"), "stdout" for "-".
void write_text(const std::string& path, const std::string& text);

/// Writes a JSON report (pretty, 2-space indent, trailing newline) with write_text ("-": standard output). Strings that are not valid UTF-8 are
/// written with U+FFFD replacement characters. Throws InputError(path, 0, "cannot write file"), and
/// NumericalError naming the key when a number in the report is NaN or infinite (null means "not requested").
void write_json(const std::string& path, const nlohmann::json& report);

}  // namespace iga::io
