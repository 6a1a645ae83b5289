#include "io/report.hpp"

#include <fstream>

#include "core/error.hpp"

namespace iga::io {

void write_json(const std::string& path, const nlohmann::json& report) {
  // Serialize first, so that a serialization problem never leaves a half-written file behind.
  const std::string text = report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  std::ofstream out(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!out) throw InputError(path, 0, "cannot write file");
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  if (!out) throw InputError(path, 0, "cannot write file");
}

}  // namespace iga::io
