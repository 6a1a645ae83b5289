#include "io/report.hpp"

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

void write_json(const std::string& path, const nlohmann::json& report) {
  // Serialize first, so that a serialization problem never leaves a half-written file behind.
  write_text(path, report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

}  // namespace iga::io
