#pragma once
// Typed exceptions. Every error a user can cause carries what is wrong and where (file and line, element,
// or option), so a program can print one clear line and exit non-zero.
#include <stdexcept>
#include <string>

namespace iga {

/// Base of every exception the library throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad input data: a malformed file, an invalid knot vector, an inconsistent argument.
/// With a file, the message reads "file:line: reason" (line 0 = the file as a whole).
class InputError : public Error {
 public:
  explicit InputError(const std::string& reason) : Error(reason), reason_(reason) {}
  InputError(const std::string& file, long line, const std::string& reason)
      : Error(file + ":" + std::to_string(line) + ": " + reason), file_(file), line_(line), reason_(reason) {}
  const std::string& file() const { return file_; }
  long line() const { return line_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string file_;
  long line_ = 0;
  std::string reason_;
};

/// A configuration the library knows it does not handle (named, never silently skipped).
class UnsupportedError : public Error {
 public:
  using Error::Error;
};

/// A numerical failure: a singular system, a solver that did not converge, a degenerate Jacobian.
class NumericalError : public Error {
 public:
  using Error::Error;
};

}  // namespace iga
