#include "fem/expression.hpp"

#include <muParser.h>

#include <atomic>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "core/error.hpp"
#include "fem/symbolic.hpp"

namespace iga::fem {

struct Expression::Evaluator {
  double x = 0, y = 0, z = 0, nx = 0, ny = 0, nz = 0;
  mu::Parser parser;
  std::vector<mu::Parser> derivatives;  // made on first use: ∂x, ∂y, ∂z, xx, xy, yy, xz, yz, zz
  std::vector<mu::Parser> singular;     // made on first use: the singular factors

  Evaluator(const std::string& text, bool allow_normal) { define(parser, text, allow_normal); }

  void define(mu::Parser& p, const std::string& text, bool allow_normal) {
    p.DefineConst("pi", std::numbers::pi);
    p.DefineConst("e", std::numbers::e);
    p.DefineFun("atan2", static_cast<double (*)(double, double)>(std::atan2));
    p.DefineFun("pow", static_cast<double (*)(double, double)>(std::pow));
    p.DefineVar("x", &x);
    p.DefineVar("y", &y);
    p.DefineVar("z", &z);
    if (allow_normal) {
      p.DefineVar("nx", &nx);
      p.DefineVar("ny", &ny);
      p.DefineVar("nz", &nz);
    }
    p.SetExpr(text);
  }
  mu::Parser& derivative(const std::vector<std::string>& texts, std::size_t i) { return made(derivatives, texts, i); }
  mu::Parser& made(std::vector<mu::Parser>& parsers, const std::vector<std::string>& texts, std::size_t i) {
    if (parsers.empty()) {
      parsers.resize(texts.size());
      for (std::size_t k = 0; k < texts.size(); ++k) define(parsers[k], texts[k], false);
    }
    return parsers[i];
  }
  void at(const Eigen::Matrix3Xd& p, Eigen::Index k) {
    x = p(0, k);
    y = p(1, k);
    z = p(2, k);
  }
};

namespace {
std::atomic<std::uint64_t> next_id{1};

// muparser's message in the user's terms: its positions count from 0 ("found at position 4." for the fifth
// character); a user, and the control-character check above, count from 1.
std::string parser_message(std::string msg) {
  // (plain search, not std::regex: GCC 12's <regex> trips -Wmaybe-uninitialized under the sanitizer flags)
  const std::string key = "at position ";
  const std::size_t at = msg.find(key);
  if (at != std::string::npos) {
    const std::size_t begin = at + key.size();
    std::size_t end = begin;
    while (end < msg.size() && msg[end] >= '0' && msg[end] <= '9') ++end;
    if (end > begin && end - begin < 10) {
      msg = msg.substr(0, begin) + std::to_string(std::stoll(msg.substr(begin, end - begin)) + 1) + msg.substr(end);
    }
  }
  while (!msg.empty() && (msg.back() == '.' || msg.back() == ' ')) msg.pop_back();
  return msg;
}

std::string point_text(const Eigen::Matrix3Xd& x, Eigen::Index k) {
  std::ostringstream s;
  s << std::setprecision(6) << "(" << x(0, k) << ", " << x(1, k) << ", " << x(2, k) << ")";
  return s.str();
}
}  // namespace

void Expression::check_finite(const Eigen::Matrix3Xd& x, const Eigen::VectorXd& out, const char* of) const {
  for (Eigen::Index k = 0; k < out.size(); ++k) {
    if (std::isfinite(out(k))) continue;
    throw InputError(what_ + ": " + of + quoted_ + " is " + (std::isnan(out(k)) ? "NaN" : "infinite") + " at " +
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
    throw InputError(what_ + ": " + quoted + ": " + parser_message(e.GetMsg()));
  }
  if (!allow_normal_) differentiate();
}

namespace {
// Where a reading of the text is compared with the text: scattered points of [-3, 3]³ (no zeros, no symmetry),
// each used where both are finite.
constexpr double kCheckPoints[][3] = {{0.3141, 0.5772, 0.1618}, {-0.7071, 0.2718, 0.4142}, {1.7321, -0.3679, 0.6931},
                                      {0.0871, 0.9134, -0.2236}, {-1.2247, -0.8660, 1.1447}, {2.2361, 1.4142, -0.5878},
                                      {0.6180, -2.0794, 0.3010}, {-0.1492, 0.0523, 2.7183}, {0.9511, 0.3090, 0.0175},
                                      {-2.6458, 1.0986, -1.3863}, {0.4472, -0.1054, 0.8944}, {1.0472, 2.0944, 0.5236}};
}  // namespace

void Expression::differentiate() {
  std::string why;
  const std::optional<SymbolicDerivatives> d = fem::differentiate(text_, why);
  if (!d) {
    not_symbolic_ = why;
    return;
  }
  std::vector<std::string> texts(d->gradient.begin(), d->gradient.end());
  texts.insert(texts.end(), d->hessian.begin(), d->hessian.end());
  for (const std::string& t : texts) {
    if (t.size() > static_cast<std::size_t>(mu::MaxLenExpression)) {
      not_symbolic_ = "a derivative is longer than muparser's " + std::to_string(mu::MaxLenExpression) +
                      " characters";
      return;
    }
  }
  // The reading must give the text's own values: a check of the reader against muparser on this very text.
  try {
    Evaluator mine(text_, false), read(d->reading, false);
    int compared = 0;
    for (const auto& p : kCheckPoints) {
      mine.x = read.x = p[0];
      mine.y = read.y = p[1];
      mine.z = read.z = p[2];
      const double a = mine.parser.Eval(), b = read.parser.Eval();
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      if (std::abs(a - b) > 1e-9 * std::max(std::abs(a), std::abs(b))) {
        std::ostringstream msg;
        msg << std::setprecision(17) << "its symbolic reading gives " << b << " where it is " << a << " at ("
            << p[0] << ", " << p[1] << ", " << p[2] << ")";
        not_symbolic_ = msg.str();
        return;
      }
      ++compared;
    }
    if (compared == 0) {
      not_symbolic_ = "its symbolic reading could not be checked (the expression is not finite at the check points)";
      return;
    }
    for (const std::string& t : texts) Evaluator check(t, false);  // muparser reads each derivative
    for (std::size_t i = 0; i < d->singular.size(); ++i) {  // and each singular factor it can (others are left out)
      try {
        Evaluator check(d->singular[i], false);
        singular_.push_back(d->singular[i]);
        singular_names_.push_back(d->singular_names[i]);
      } catch (const mu::Parser::exception_type&) {
      }
    }
  } catch (const mu::Parser::exception_type& e) {
    not_symbolic_ = "muparser: " + e.GetMsg();
    return;
  }
  derivatives_ = std::move(texts);
  symbolic_ = true;
}

std::string Expression::derivative_method(int order) const {
  if (symbolic_) return "symbolic (GiNaC)";
  return Function::derivative_method(order) + " (not symbolic: " + not_symbolic_ + ")";
}

void Expression::symbolic_derivatives(const Eigen::Matrix3Xd& x, std::size_t first, Eigen::Ref<Eigen::MatrixXd> out,
                                      const char* of) const {
  Evaluator& ev = evaluator();
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    ev.at(x, k);
    for (Eigen::Index r = 0; r < out.rows(); ++r) {
      out(r, k) = ev.derivative(derivatives_, first + static_cast<std::size_t>(r)).Eval();
    }
  }
  if (out.allFinite()) return;
  for (Eigen::Index r = 0; r < out.rows(); ++r) check_finite(x, out.row(r).transpose(), of);
}

void Expression::gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const {
  if (!symbolic_) {
    Function::gradients(x, out);
    return;
  }
  out.resize(3, x.cols());
  symbolic_derivatives(x, 0, out, "the gradient of ");
}

void Expression::hessians(const Eigen::Matrix3Xd& x, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const {
  if (!symbolic_) {
    Function::hessians(x, out);
    return;
  }
  out.resize(6, x.cols());
  symbolic_derivatives(x, 3, out, "the Hessian of ");
}

Expression::~Expression() = default;

Expression::Evaluator& Expression::evaluator() const {
  thread_local std::unordered_map<std::uint64_t, std::unique_ptr<Evaluator>> cache;
  auto& slot = cache[id_];
  if (!slot) slot = std::make_unique<Evaluator>(text_, allow_normal_);
  return *slot;
}

void Expression::singular_factors(const Eigen::Matrix3Xd& x, Eigen::MatrixXd& out) const {
  out.resize(static_cast<Eigen::Index>(singular_.size()), x.cols());
  if (singular_.empty()) return;
  Evaluator& ev = evaluator();
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    ev.at(x, k);
    for (std::size_t i = 0; i < singular_.size(); ++i) out(static_cast<Eigen::Index>(i), k) = ev.made(ev.singular, singular_, i).Eval();
  }
}

void Expression::values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const {
  values_unchecked(x, out);
  check_finite(x, out);
}

void Expression::values_unchecked(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const {
  Evaluator& ev = evaluator();
  out.resize(x.cols());
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    ev.x = x(0, k);
    ev.y = x(1, k);
    ev.z = x(2, k);
    out(k) = ev.parser.Eval();
  }
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
