#pragma once
// Shared by the libFuzzer targets (tests/fuzz/): an iga::Error is the expected way to refuse input, but its
// message must be one line (a program prints it as its single error line).
#include <cstdlib>
#include <cstdio>
#include <string>

#include "core/error.hpp"

namespace iga::fuzz {

inline void check_one_line(const iga::Error& e) {
  const std::string message = e.what();
  if (message.empty() || message.find_first_of("\n\r") != std::string::npos) {
    std::fprintf(stderr, "finding: error message is not one line: [%s]\n", message.c_str());
    std::abort();
  }
}

}  // namespace iga::fuzz
