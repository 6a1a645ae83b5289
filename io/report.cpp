#include "io/report.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <iostream>

#include "core/error.hpp"

namespace iga::io {

void check_writable(const std::string& path) {
  if (!writes(path) || path == "-") return;
  namespace fs = std::filesystem;
  const auto fail = [&] { throw InputError(path, 0, "cannot write file"); };
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) fail();
  if (fs::is_regular_file(status)) {
    std::ofstream out(path, std::ios::out | std::ios::app | std::ios::binary);
    if (!out) fail();
    return;
  }
  if (fs::exists(status)) {
    // A device: /dev/full (character device 1, 7 on Linux) accepts the open and refuses every byte; the others
    // (/dev/null, a terminal) are not written to here.
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode) && st.st_rdev == makedev(1, 7)) fail();
    std::ofstream out(path, std::ios::out | std::ios::app | std::ios::binary);
    if (!out) fail();
    return;
  }
  {
    std::ofstream out(path, std::ios::out | std::ios::binary);
    if (!out) fail();
  }
  fs::remove(path, ec);
}

void write_text(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
    std::cout.flush();
    if (!std::cout) throw InputError("stdout", 0, "cannot write");
    return;
  }
  std::ofstream out(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out) throw InputError(path, 0, "cannot write file");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  if (!out) throw InputError(path, 0, "cannot write file");
}

namespace {
// The JSON pointer of the first number in `j` that is not finite, or "" (JSON has no NaN: nlohmann writes null,
// which in a report means "not requested").
std::string first_non_finite(const nlohmann::json& j, const std::string& at) {
  if (j.is_number_float()) return std::isfinite(j.get<double>()) ? std::string() : (at.empty() ? "/" : at);
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) {
      std::string found = first_non_finite(it.value(), at + "/" + it.key());
      if (!found.empty()) return found;
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) {
      std::string found = first_non_finite(j[i], at + "/" + std::to_string(i));
      if (!found.empty()) return found;
    }
  }
  return std::string();
}
}  // namespace

void write_json(const std::string& path, const nlohmann::json& report) {
  if (const std::string key = first_non_finite(report, ""); !key.empty()) {
    throw NumericalError("the result " + key.substr(1) + " is not finite (" +
                         std::to_string(nlohmann::json(report[nlohmann::json::json_pointer(key)]).get<double>()) +
                         "); no report written to " + path);
  }
  // Serialize first, so that a serialization problem never leaves a half-written file behind.
  write_text(path, report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace iga::io
