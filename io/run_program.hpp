#pragma once
// A program's run with every exception as one line "PROGRAM: error: ..." and exit code 1 (io/program.hpp's
// conventions), without CLI11: library units that run a program's body include this alone.
#include <iostream>
#include <new>
#include <string>

namespace iga::io {

/// Runs body() and turns every exception into one line on stderr and exit code 1.
template <class Body>
int run_program(const std::string& program, Body&& body) {
  try {
    return body();
  } catch (const std::bad_alloc&) {
    std::cerr << program << ": error: out of memory (an allocation failed; a smaller problem, fewer refinements "
                            "or fewer output samples would fit)" << std::endl;
  } catch (const std::exception& e) {
    std::string what = e.what();
    for (char& c : what) {
      if (c == '\n') c = ' ';
    }
    std::cerr << program << ": error: " << what << std::endl;
  } catch (...) {
    std::cerr << program << ": error: unknown failure" << std::endl;
  }
  return 1;
}

}  // namespace iga::io
