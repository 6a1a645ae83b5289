// Where a test finds the source tree and the programs it runs: read at run time from iga_test_paths.txt beside
// the test's executable (tests/CMakeLists.txt writes it), not compiled in as -D strings. So a test's object
// file is the same in every clone of the repository and ccache reuses it when CI builds a fresh clone
// (README, "Build times").
#pragma once

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace iga::test {

/// The value of KEY in iga_test_paths.txt (lines KEY=VALUE); a test without it aborts with one line.
inline const char* build_path(const char* key) {
  static const std::map<std::string, std::string> table = [] {
    std::map<std::string, std::string> t;
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    std::ifstream in(exe.parent_path() / "iga_test_paths.txt");
    for (std::string line; std::getline(in, line);) {
      const auto eq = line.find('=');
      if (eq != std::string::npos) t[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return t;
  }();
  const auto it = table.find(key);
  if (it == table.end()) {
    std::fprintf(stderr, "test set-up: no %s in iga_test_paths.txt beside the test executable (re-run cmake)\n", key);
    std::abort();
  }
  return it->second.c_str();
}

}  // namespace iga::test

#define IGA_SOURCE_DIR (::iga::test::build_path("IGA_SOURCE_DIR"))
#define IGA_POISSON_EXE (::iga::test::build_path("IGA_POISSON_EXE"))
#define IGA_BEM_EXE (::iga::test::build_path("IGA_BEM_EXE"))
#define IGA_QUADRATURE_EXE (::iga::test::build_path("IGA_QUADRATURE_EXE"))
#define IGA_GEOMETRY_EXE (::iga::test::build_path("IGA_GEOMETRY_EXE"))
#define IGA_KNOTS_EXE (::iga::test::build_path("IGA_KNOTS_EXE"))
#define BENCH_BEM_EXE (::iga::test::build_path("BENCH_BEM_EXE"))
#define BENCH_HALFBOX_EXE (::iga::test::build_path("BENCH_HALFBOX_EXE"))
#define BENCH_THB_REFINE_EXE (::iga::test::build_path("BENCH_THB_REFINE_EXE"))
