#include "fem/expression.hpp"

#include <muParser.h>

#include <atomic>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <numbers>
#include <unordered_map>

#include "core/error.hpp"

namespace iga::fem {

struct Expression::Evaluator {
  mu::Parser parser;
  double x = 0, y = 0, z = 0, nx = 0, ny = 0, nz = 0;

  Evaluator(const std::string& text, bool allow_normal) {
    parser.DefineConst("pi", std::numbers::pi);
    parser.DefineConst("e", std::numbers::e);
    parser.DefineFun("atan2", static_cast<double (*)(double, double)>(std::atan2));
    parser.DefineFun("pow", static_cast<double (*)(double, double)>(std::pow));
    parser.DefineVar("x", &x);
    parser.DefineVar("y", &y);
    parser.DefineVar("z", &z);
    if (allow_normal) {
      parser.DefineVar("nx", &nx);
      parser.DefineVar("ny", &ny);
      parser.DefineVar("nz", &nz);
    }
    parser.SetExpr(text);
  }
};

namespace {
std::atomic<std::uint64_t> next_id{1};

std::string point_text(const Eigen::Matrix3Xd& x, Eigen::Index k) {
  std::ostringstream s;
  s << std::setprecision(6) << "(" << x(0, k) << ", " << x(1, k) << ", " << x(2, k) << ")";
  return s.str();
}
}  // namespace

void Expression::check_finite(const Eigen::Matrix3Xd& x, const Eigen::VectorXd& out) const {
  for (Eigen::Index k = 0; k < out.size(); ++k) {
    if (std::isfinite(out(k))) continue;
    throw InputError(what_ + ": " + quoted_ + " is " + (std::isnan(out(k)) ? "NaN" : "infinite") + " at " +
                     point_text(x, k) + "; data must be finite wherever they are used");
  }
}

Expression::Expression(std::string text, std::string what, bool allow_normal)
    : text_(std::move(text)), what_(std::move(what)), allow_normal_(allow_normal), id_(next_id++) {
  if (text_.find_first_not_of(" \t") == std::string::npos) throw InputError(what_ + ": empty expression");
  // A control character (a pasted line break, binary data) would split the quoted text below, and so the one
  // error line, over several lines: refused first, by position (1-based byte).
  for (std::size_t k = 0; k < text_.size(); ++k) {
    const auto byte = static_cast<unsigned char>(text_[k]);
    if ((byte < 0x20U && byte != '\t') || byte == 0x7FU) {
      const char* const hex = "0123456789ABCDEF";
      throw InputError(what_ + ": control character (byte 0x" + hex[byte >> 4U] + hex[byte & 15U] + ") at position " +
                       std::to_string(k + 1) + " of the expression");
    }
  }
  // Quoted in messages up to 60 characters, so that a long expression still gives one short line.
  std::string& quoted = quoted_;
  quoted.assign(1, '\'');
  if (text_.size() > 60) {
    quoted.append(text_, 0, 57);
    quoted.append("...");
  } else {
    quoted.append(text_);
  }
  quoted.push_back('\'');
  // muparser would read "x=3" as an assignment to x (value 3) and "1,2" as two results (the last one used):
  // neither is a formula in x, y, z. Comparisons (==, <=, >=, !=) stay.
  for (std::size_t k = 0; k < text_.size(); ++k) {
    if (text_[k] != '=') continue;
    const bool comparison = (k > 0 && std::string("=<>!").find(text_[k - 1]) != std::string::npos) ||
                            (k + 1 < text_.size() && text_[k + 1] == '=');
    if (!comparison) throw InputError(what_ + ": " + quoted + ": '=' assigns; use '==' to compare");
  }
  try {
    Evaluator check(text_, allow_normal_);
    check.parser.Eval();  // compiles; reports syntax errors and undefined variables
    if (check.parser.GetNumResults() != 1) {
      throw InputError(what_ + ": " + quoted + ": ',' separates several expressions; give one");
    }
  } catch (const mu::Parser::exception_type& e) {
    throw InputError(what_ + ": " + quoted + ": " + e.GetMsg());
  }
}

Expression::~Expression() = default;

Expression::Evaluator& Expression::evaluator() const {
  thread_local std::unordered_map<std::uint64_t, std::unique_ptr<Evaluator>> cache;
  auto& slot = cache[id_];
  if (!slot) slot = std::make_unique<Evaluator>(text_, allow_normal_);
  return *slot;
}

void Expression::values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const {
  Evaluator& ev = evaluator();
  out.resize(x.cols());
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    ev.x = x(0, k);
    ev.y = x(1, k);
    ev.z = x(2, k);
    out(k) = ev.parser.Eval();
  }
  check_finite(x, out);
}

void Expression::values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const {
  Evaluator& ev = evaluator();
  out.resize(x.cols());
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    ev.x = x(0, k);
    ev.y = x(1, k);
    ev.z = x(2, k);
    ev.nx = n(0, k);
    ev.ny = n(1, k);
    ev.nz = n(2, k);
    out(k) = ev.parser.Eval();
  }
  check_finite(x, out);
}

}  // namespace iga::fem
