#include "io/report.hpp"

#include <cmath>
#include <fstream>
#include <iostream>

#include "core/error.hpp"

namespace iga::io {

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
