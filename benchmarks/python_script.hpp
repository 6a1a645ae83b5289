#pragma once
// Python scripts installed with the project (share/iga/), found relative to the running executable, and run with
// the system's python3: how iga-poisson --study draws its plots with matplotlib.
#include <string>
#include <vector>

namespace iga::bench {

/// The path of the data file `name` installed with the project, the first that exists of
///  1. $IGA_SHARE_DIR/name (an override),
///  2. <folder of /proc/self/exe>/IGA_SHARE_FROM_BIN/name (installed: bin/../share/iga; build tree:
///     build/benchmarks/../share/iga, where CMake copies the scripts).
/// No path of the build or source tree is compiled in (the installed program is relocatable).
/// "" when none exists; `looked` lists the paths tried, in order.
std::string find_share_file(const std::string& name, std::vector<std::string>& looked);

/// The interpreter: $IGA_PYTHON, else /usr/bin/python3 (Debian's, where numpy and matplotlib are installed).
std::string python_interpreter();

struct ScriptRun {
  bool started = false;  ///< false: the interpreter could not be started (reason in `output`)
  int exit_code = -1;
  std::string output;    ///< the script's stderr (and stdout), or why it did not start
};

/// Runs `interpreter args...` and waits for it; its stdout and stderr are captured, not shown.
ScriptRun run_script(const std::string& interpreter, const std::vector<std::string>& args);

}  // namespace iga::bench
