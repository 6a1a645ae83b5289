#include "benchmarks/python_script.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#ifndef IGA_SHARE_FROM_BIN
#define IGA_SHARE_FROM_BIN "../share/iga"
#endif

extern char** environ;

namespace iga::bench {

namespace fs = std::filesystem;

std::string find_share_file(const std::string& name, std::vector<std::string>& looked) {
  std::vector<fs::path> candidates;
  if (const char* dir = std::getenv("IGA_SHARE_DIR"); dir && *dir) candidates.push_back(fs::path(dir) / name);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path() / IGA_SHARE_FROM_BIN / name);
  for (const fs::path& p : candidates) {
    const fs::path normal = p.lexically_normal();
    looked.push_back(normal.string());
    if (fs::is_regular_file(normal, ec)) return normal.string();
  }
  return std::string();
}

std::string python_interpreter() {
  const char* python = std::getenv("IGA_PYTHON");
  return python && *python ? python : "/usr/bin/python3";
}

ScriptRun run_script(const std::string& interpreter, const std::vector<std::string>& args) {
  ScriptRun run;
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) {
    run.output = std::string("cannot create a pipe: ") + std::strerror(errno);
    return run;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);
  std::vector<std::string> argv_text{interpreter};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, interpreter.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  if (spawned != 0) {
    ::close(pipe_fds[0]);
    run.output = interpreter + ": " + std::strerror(spawned);
    return run;
  }
  char buffer[4096];
  for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    run.output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  run.started = true;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return run;
}

}  // namespace iga::bench
