// libFuzzer target: fem::Expression from arbitrary text (the first byte chooses whether the normal nx, ny, nz
// may be used). If it constructs, it is evaluated at a few points, with and without a normal. Refusing the text
// with an iga::Error of one line is fine; a crash, a sanitizer report, any other exception (muparser's own
// included) or a hang is a finding.
// Each input runs in a short-lived thread: Expression keeps one parser per thread and expression in a
// thread_local cache that is never trimmed, so one long-lived thread would grow by a parser per input.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <thread>

#include "fem/expression.hpp"
#include "tests/fuzz/fuzz_support.hpp"

namespace {

void run(const std::string& text, bool allow_normal) {
  try {
    const iga::fem::Expression f(text, "--fuzz", allow_normal);
    Eigen::Matrix3Xd x(3, 4), n(3, 4);
    x << 0, 0.5, -3, 1e300, 0, -1, 2, -1e-300, 0, 2, 0.25, NAN;
    n << 1, 0, 0, 0.6, 0, 1, 0, 0.8, 0, 0, 1, 0;
    Eigen::VectorXd out;
    f.values(x, out);
    if (out.size() != 4) std::abort();
    if (allow_normal) f.values(x, n, out);
  } catch (const iga::Error& e) {
    iga::fuzz::check_one_line(e);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool allow_normal = (data[0] & 1U) != 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  std::thread worker(run, std::cref(text), allow_normal);
  worker.join();
  return 0;
}
