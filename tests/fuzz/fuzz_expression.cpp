// libFuzzer target: fem::Expression from arbitrary text (the first byte chooses whether the normal nx, ny, nz
// may be used). If it constructs, it is evaluated at a few points, with and without a normal. Refusing the text
// with an iga::Error of one line is fine; a crash, a sanitizer report, any other exception (muparser's own
// included) or a hang is a finding.
// Inputs run on a worker thread that is replaced every kInputsPerThread inputs: Expression keeps one parser
// per thread and expression in a thread_local cache that is never trimmed, so one long-lived thread would grow
// by a parser per input, and a thread per input costs three times the run time.
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
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

constexpr int kInputsPerThread = 500;

// One thread that runs the inputs handed to it, one at a time; the caller waits for each.
class Worker {
 public:
  Worker() : thread_([this] { loop(); }) {}
  ~Worker() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    ready_.notify_all();
    thread_.join();
  }
  void submit(const std::string& text, bool allow_normal) {
    std::unique_lock<std::mutex> lock(mutex_);
    job_ = &text;
    allow_normal_ = allow_normal;
    ready_.notify_all();
    ready_.wait(lock, [this] { return job_ == nullptr; });
  }

 private:
  void loop() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      ready_.wait(lock, [this] { return job_ != nullptr || stop_; });
      if (job_ == nullptr) return;
      lock.unlock();
      run(*job_, allow_normal_);
      lock.lock();
      job_ = nullptr;
      ready_.notify_all();
    }
  }
  std::mutex mutex_;
  std::condition_variable ready_;
  const std::string* job_ = nullptr;
  bool allow_normal_ = false;
  bool stop_ = false;
  std::thread thread_;  // last: started once the members above exist
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool allow_normal = (data[0] & 1U) != 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  static std::unique_ptr<Worker> worker;
  static int inputs = 0;
  if (inputs++ % kInputsPerThread == 0) {
    worker.reset();  // its thread, and its parsers, end here
    worker = std::make_unique<Worker>();
  }
  worker->submit(text, allow_normal);
  return 0;
}
