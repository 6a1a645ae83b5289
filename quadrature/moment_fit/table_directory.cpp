#include "quadrature/moment_fit/table_directory.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "quadrature/moment_fit/table.hpp"

namespace iga::quadrature::moment_fit {

namespace fs = std::filesystem;

namespace {
// The file this code was loaded from (libiga_quadrature.so, or the program for a static build); empty if unknown.
fs::path own_file() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&own_file), &info) == 0 || info.dli_fname == nullptr) return {};
  std::error_code ec;
  const fs::path p = fs::absolute(info.dli_fname, ec);
  return ec ? fs::path() : p.lexically_normal();
}

bool has_tables(const fs::path& dir, Space space) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return false;
  for (int n = 3; n <= 16; ++n) {
    for (const bool symmetric : {false, true}) {
      if (fs::exists(dir / table_file_name(n, space, symmetric), ec)) return true;
    }
  }
  return false;
}
}  // namespace

std::string default_table_directory(Space space) {
  if (const char* env = std::getenv("IGA_QUADRATURE_DIR")) return env;
  const std::string tables = "cc_" + to_string(space) + "_n*.txt";
  const fs::path lib = own_file();
  if (lib.empty()) {
    throw InputError("fitted quadrature: $IGA_QUADRATURE_DIR is not set and the library's own location is unknown "
                     "(dladdr failed): give the tables' directory as fitted:DIR");
  }
  std::string looked = "$IGA_QUADRATURE_DIR (not set)";
  const fs::path installed = (lib.parent_path() / IGA_QUADRATURE_INSTALL_REL).lexically_normal();
  if (has_tables(installed, space)) return installed.string();
  looked += ", " + installed.string() + " (next to " + lib.string() + ")";
  const fs::path marker = lib.parent_path() / "iga-build-tree-quadrature-dir.txt";
  std::ifstream in(marker);
  std::string line;
  if (in && std::getline(in, line) && !line.empty()) {
    if (has_tables(line, space)) return line;
    looked += ", " + line + " (the build tree's, from " + marker.string() + ")";
  }
  throw InputError("fitted quadrature: no " + tables + " tables in " + looked +
                   ": set $IGA_QUADRATURE_DIR or give fitted:DIR");
}

}  // namespace iga::quadrature::moment_fit
