// Running one of the project's programs from a test: in a folder, its stderr kept and its exit code returned.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace iga::test {

struct Outcome {
  int code;         ///< the exit code
  std::string err;  ///< what it wrote on stderr
};

/// `exe args` run by the shell in `dir` (args as a shell would read them), stdout discarded.
inline Outcome run_program(const std::filesystem::path& dir, const std::string& exe, const std::string& args) {
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string cmd = "cd '" + dir.string() + "' && '" + exe + "' " + args + " 2> '" + err.string() + "' > /dev/null";
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  return {WEXITSTATUS(status), ss.str()};
}

}  // namespace iga::test
