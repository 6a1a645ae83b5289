#include "fem/symbolic.hpp"

#include <ginac/ginac.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

namespace iga::fem {

// muparser's operations that GiNaC has no function for, as GiNaC functions that only carry their arguments:
// a condition (a comparison, && and ||) and sign and rint are piecewise constant (derivative 0), abs' derivative is
// sign, and c ? a : b differentiates its branches. Written back by write() below.
DECLARE_FUNCTION_3P(iga_if)
DECLARE_FUNCTION_2P(iga_lt)
DECLARE_FUNCTION_2P(iga_le)
DECLARE_FUNCTION_2P(iga_gt)
DECLARE_FUNCTION_2P(iga_ge)
DECLARE_FUNCTION_2P(iga_eq)
DECLARE_FUNCTION_2P(iga_ne)
DECLARE_FUNCTION_2P(iga_and)
DECLARE_FUNCTION_2P(iga_or)
DECLARE_FUNCTION_1P(iga_sign)
DECLARE_FUNCTION_1P(iga_rint)
DECLARE_FUNCTION_1P(iga_abs)

namespace {
GiNaC::ex if_derivative(const GiNaC::ex& c, const GiNaC::ex& a, const GiNaC::ex& b, const GiNaC::symbol& s) {
  return iga_if(c, a.diff(s), b.diff(s));
}
GiNaC::ex zero_2(const GiNaC::ex&, const GiNaC::ex&, unsigned) { return 0; }
GiNaC::ex zero_1(const GiNaC::ex&, unsigned) { return 0; }
GiNaC::ex abs_derivative(const GiNaC::ex& a, unsigned) { return iga_sign(a); }
}  // namespace

REGISTER_FUNCTION(iga_if, expl_derivative_func(if_derivative))
REGISTER_FUNCTION(iga_lt, derivative_func(zero_2))
REGISTER_FUNCTION(iga_le, derivative_func(zero_2))
REGISTER_FUNCTION(iga_gt, derivative_func(zero_2))
REGISTER_FUNCTION(iga_ge, derivative_func(zero_2))
REGISTER_FUNCTION(iga_eq, derivative_func(zero_2))
REGISTER_FUNCTION(iga_ne, derivative_func(zero_2))
REGISTER_FUNCTION(iga_and, derivative_func(zero_2))
REGISTER_FUNCTION(iga_or, derivative_func(zero_2))
REGISTER_FUNCTION(iga_sign, derivative_func(zero_1))
REGISTER_FUNCTION(iga_rint, derivative_func(zero_1))
REGISTER_FUNCTION(iga_abs, derivative_func(abs_derivative))

namespace {

using GiNaC::ex;

struct Unreadable {
  std::string why;
};

struct Symbols {
  GiNaC::realsymbol x{"x"}, y{"y"}, z{"z"};
};

// muparser's grammar, by recursive descent; the precedences are muparser's (muParserDef.h, checked against the
// library's values in tests/fem/test_symbolic.cpp): ?: (right) < || < && < comparisons < + - < * / and the unary
// signs < ^ (right), where a sign after ^ takes the power chain that follows it (2^-x^2 = 2^(-(x^2))).
class Reader {
 public:
  Reader(const std::string& text, const Symbols& s) : t_(text), s_(s) {}

  ex read() {
    ex e = conditional();
    skip();
    if (k_ != t_.size()) fail("unexpected '" + std::string(1, t_[k_]) + "'");
    return e;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw Unreadable{what + " at position " + std::to_string(k_ + 1)};
  }
  void skip() {
    while (k_ < t_.size() && std::isspace(static_cast<unsigned char>(t_[k_]))) ++k_;
  }
  bool take(const char* op) {
    skip();
    const std::size_t n = std::char_traits<char>::length(op);
    if (t_.compare(k_, n, op) != 0) return false;
    k_ += n;
    return true;
  }
  // One character that must not be the start of a longer operator ("<" but not "<=", "*" but not "**").
  bool take_single(char c, const char* not_followed_by) {
    skip();
    if (k_ >= t_.size() || t_[k_] != c) return false;
    if (k_ + 1 < t_.size() && std::string(not_followed_by).find(t_[k_ + 1]) != std::string::npos) return false;
    ++k_;
    return true;
  }

  ex conditional() {
    ex c = either();
    if (!take("?")) return c;
    ex a = conditional();
    if (!take(":")) fail("':' expected");
    ex b = conditional();
    return iga_if(c, a, b);
  }
  ex either() {
    ex e = both();
    while (take("||")) e = iga_or(e, both());
    return e;
  }
  ex both() {
    ex e = comparison();
    while (take("&&")) e = iga_and(e, comparison());
    return e;
  }
  ex comparison() {
    ex e = sum();
    for (;;) {
      if (take("<=")) e = iga_le(e, sum());
      else if (take(">=")) e = iga_ge(e, sum());
      else if (take("==")) e = iga_eq(e, sum());
      else if (take("!=")) e = iga_ne(e, sum());
      else if (take_single('<', "=")) e = iga_lt(e, sum());
      else if (take_single('>', "=")) e = iga_gt(e, sum());
      else return e;
    }
  }
  ex sum() {
    ex e = product();
    for (;;) {
      if (take("+")) e = e + product();
      else if (take("-")) e = e - product();
      else return e;
    }
  }
  ex product() {
    ex e = signed_power();
    for (;;) {
      if (take("*")) e = e * signed_power();
      else if (take("/")) e = e / signed_power();
      else return e;
    }
  }
  ex signed_power() {
    if (take("-")) return -signed_power();
    if (take("+")) return signed_power();
    return power();
  }
  ex power() {
    ex base = primary();
    if (!take("^")) return base;
    return GiNaC::pow(base, signed_power());  // right-associative; a sign takes the chain after it
  }
  ex primary() {
    skip();
    if (k_ >= t_.size()) fail("operand expected");
    const char c = t_[k_];
    if (c == '(') {
      ++k_;
      ex e = conditional();
      if (!take(")")) fail("')' expected");
      return e;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return name();
    fail("unexpected '" + std::string(1, c) + "'");
  }
  ex number() {
    const char* start = t_.c_str() + k_;
    char* end = nullptr;
    const double v = std::strtod(start, &end);
    if (end == start || !std::isfinite(v)) fail("not a number");
    const std::string digits(start, static_cast<std::size_t>(end - start));
    k_ += static_cast<std::size_t>(end - start);
    // An integer literal stays exact (2/3 is a rational, as muparser's 2/3 is its double).
    if (digits.find_first_not_of("0123456789") == std::string::npos && digits.size() <= 15) {
      return GiNaC::numeric(digits.c_str());
    }
    return GiNaC::numeric(v);
  }
  ex name() {
    const std::size_t start = k_;
    while (k_ < t_.size() && (std::isalnum(static_cast<unsigned char>(t_[k_])) || t_[k_] == '_')) ++k_;
    const std::string id = t_.substr(start, k_ - start);
    skip();
    if (k_ < t_.size() && t_[k_] == '(') {
      ++k_;
      std::vector<ex> args;
      skip();
      if (!take(")")) {
        do args.push_back(conditional());
        while (take(","));
        if (!take(")")) fail("')' expected");
      }
      return call(id, args);
    }
    if (id == "x") return s_.x;
    if (id == "y") return s_.y;
    if (id == "z") return s_.z;
    if (id == "pi" || id == "_pi") return GiNaC::Pi;
    if (id == "e" || id == "_e") return GiNaC::exp(ex(1));
    throw Unreadable{"'" + id + "' is not a variable or constant it reads"};
  }
  ex call(const std::string& f, const std::vector<ex>& a) {
    using Unary = ex (*)(const ex&);
    static const std::map<std::string, Unary> unary = {
        {"sin", [](const ex& u) -> ex { return GiNaC::sin(u); }},
        {"cos", [](const ex& u) -> ex { return GiNaC::cos(u); }},
        {"tan", [](const ex& u) -> ex { return GiNaC::tan(u); }},
        {"asin", [](const ex& u) -> ex { return GiNaC::asin(u); }},
        {"acos", [](const ex& u) -> ex { return GiNaC::acos(u); }},
        {"atan", [](const ex& u) -> ex { return GiNaC::atan(u); }},
        {"sinh", [](const ex& u) -> ex { return GiNaC::sinh(u); }},
        {"cosh", [](const ex& u) -> ex { return GiNaC::cosh(u); }},
        {"tanh", [](const ex& u) -> ex { return GiNaC::tanh(u); }},
        {"asinh", [](const ex& u) -> ex { return GiNaC::asinh(u); }},
        {"acosh", [](const ex& u) -> ex { return GiNaC::acosh(u); }},
        {"atanh", [](const ex& u) -> ex { return GiNaC::atanh(u); }},
        {"exp", [](const ex& u) -> ex { return GiNaC::exp(u); }},
        {"sqrt", [](const ex& u) -> ex { return GiNaC::sqrt(u); }},
        {"ln", [](const ex& u) -> ex { return GiNaC::log(u); }},
        {"log", [](const ex& u) -> ex { return GiNaC::log(u); }},  // muparser 2.3: log is ln
        {"log2", [](const ex& u) -> ex { return GiNaC::log(u) / GiNaC::log(ex(2)); }},
        {"log10", [](const ex& u) -> ex { return GiNaC::log(u) / GiNaC::log(ex(10)); }},
        {"abs", [](const ex& u) -> ex { return iga_abs(u); }},
        {"sign", [](const ex& u) -> ex { return iga_sign(u); }},
        {"rint", [](const ex& u) -> ex { return iga_rint(u); }},
    };
    if (auto it = unary.find(f); it != unary.end()) {
      if (a.size() != 1) fail(f + " takes one argument");
      return it->second(a[0]);
    }
    if (f == "atan2" || f == "pow") {
      if (a.size() != 2) fail(f + " takes two arguments");
      return f == "pow" ? GiNaC::pow(a[0], a[1]) : ex(GiNaC::atan2(a[0], a[1]));
    }
    if (f == "min" || f == "max" || f == "sum" || f == "avg") {
      if (a.empty()) fail(f + " needs an argument");
      ex e = a[0];
      for (std::size_t i = 1; i < a.size(); ++i) {
        if (f == "min") e = iga_if(iga_lt(a[i], e), a[i], e);  // muparser keeps the first of equal values
        else if (f == "max") e = iga_if(iga_gt(a[i], e), a[i], e);
        else e = e + a[i];
      }
      return f == "avg" ? e / static_cast<int>(a.size()) : e;
    }
    throw Unreadable{"the function '" + f + "' is not one it differentiates"};
  }

  const std::string& t_;
  const Symbols& s_;
  std::size_t k_ = 0;
};

// An expression written back as muparser text, fully parenthesised.
class Writer {
 public:
  std::string write(const ex& e) {
    if (GiNaC::is_a<GiNaC::numeric>(e)) return number(GiNaC::ex_to<GiNaC::numeric>(e));
    if (GiNaC::is_a<GiNaC::symbol>(e)) return GiNaC::ex_to<GiNaC::symbol>(e).get_name();
    if (GiNaC::is_a<GiNaC::constant>(e)) {
      if (e.is_equal(GiNaC::Pi)) return "pi";
      throw Unreadable{"the constant " + text(e) + " has no muparser name"};
    }
    if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e)) {
      const char* op = GiNaC::is_a<GiNaC::add>(e) ? "+" : "*";
      std::string s = "(";
      for (std::size_t i = 0; i < e.nops(); ++i) {
        if (i) s += op;
        s += write(e.op(i));
      }
      return s + ")";
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      std::string s("((");  // built by appending: GCC 12's -Wrestrict misreads "((" + std::string
      s += write(e.op(0));
      s += ")^(";
      s += write(e.op(1));
      s += "))";
      return s;
    }
    if (GiNaC::is_a<GiNaC::function>(e)) return function(GiNaC::ex_to<GiNaC::function>(e));
    throw Unreadable{"the term " + text(e) + " has no muparser form"};
  }

 private:
  static std::string text(const ex& e) {
    std::ostringstream s;
    s << e;
    std::string t = s.str();
    return t.size() > 40 ? t.substr(0, 37) + "..." : t;
  }
  static std::string number(const GiNaC::numeric& n) {
    if (!n.is_real()) throw Unreadable{"a complex number appeared"};
    std::ostringstream s;
    if (n.is_rational() && GiNaC::abs(n.numer()) < GiNaC::numeric(1L << 52) && n.denom() < GiNaC::numeric(1L << 52)) {
      s << "(" << n.numer().to_long();
      if (!n.is_integer()) s << "/" << n.denom().to_long();
      s << ")";
      return s.str();
    }
    const double v = n.to_double();
    if (!std::isfinite(v)) throw Unreadable{"a number out of the range of a double appeared"};
    s << std::setprecision(17) << "(" << v << ")";
    return s.str();
  }
  std::string function(const GiNaC::function& f) {
    const std::string name = f.get_name();
    std::vector<std::string> a;
    for (std::size_t i = 0; i < f.nops(); ++i) a.push_back(write(f.op(i)));
    static const std::map<std::string, std::string> comparisons = {
        {"iga_lt", "<"}, {"iga_le", "<="}, {"iga_gt", ">"}, {"iga_ge", ">="},
        {"iga_eq", "=="}, {"iga_ne", "!="}, {"iga_and", "&&"}, {"iga_or", "||"}};
    if (auto it = comparisons.find(name); it != comparisons.end()) return "(" + a[0] + it->second + a[1] + ")";
    if (name == "iga_if") return "(" + a[0] + "?" + a[1] + ":" + a[2] + ")";
    static const std::map<std::string, std::string> named = {
        {"sin", "sin"}, {"cos", "cos"}, {"tan", "tan"}, {"asin", "asin"}, {"acos", "acos"}, {"atan", "atan"},
        {"sinh", "sinh"}, {"cosh", "cosh"}, {"tanh", "tanh"}, {"asinh", "asinh"}, {"acosh", "acosh"},
        {"atanh", "atanh"}, {"exp", "exp"}, {"log", "ln"}, {"atan2", "atan2"}, {"csgn", "sign"},
        {"iga_sign", "sign"}, {"iga_rint", "rint"}, {"iga_abs", "abs"}};
    auto it = named.find(name);
    if (it == named.end()) throw Unreadable{"the function " + name + " has no muparser form"};
    std::string s = it->second + "(";
    for (std::size_t i = 0; i < a.size(); ++i) s += (i ? "," : "") + a[i];
    return s + ")";
  }
};

// The factors of `base` whose zeros are those of base: products split, positive powers and abs(a) read as their
// base, polynomials factored over the rationals; constants left out.
void split_factors(const ex& base, const Symbols& s, std::vector<ex>& out) {
  if (!base.has(s.x) && !base.has(s.y) && !base.has(s.z)) return;
  if (GiNaC::is_a<GiNaC::mul>(base)) {
    for (std::size_t i = 0; i < base.nops(); ++i) split_factors(base.op(i), s, out);
    return;
  }
  if (GiNaC::is_a<GiNaC::power>(base) && GiNaC::is_a<GiNaC::numeric>(base.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(base.op(1)).is_positive()) {
    split_factors(base.op(0), s, out);
    return;
  }
  if (GiNaC::is_a<GiNaC::function>(base) && GiNaC::ex_to<GiNaC::function>(base).get_name() == "iga_abs") {
    split_factors(base.op(0), s, out);
    return;
  }
  if (base.is_polynomial(GiNaC::lst{s.x, s.y, s.z}) && !GiNaC::is_a<GiNaC::symbol>(base)) {
    ex f = base;
    try {
      f = GiNaC::factor(base);
    } catch (const std::exception&) {  // float coefficients: not a polynomial over the rationals, kept whole
    }
    if (GiNaC::is_a<GiNaC::mul>(f) || GiNaC::is_a<GiNaC::power>(f)) {
      split_factors(f, s, out);
      return;
    }
  }
  for (const ex& o : out) {
    if (o.is_equal(base)) return;
  }
  out.push_back(base);
}

// The singular factors of e (SymbolicDerivatives::singular), with what each is to e (kinds[i]).
void singular_factors(const ex& e, const Symbols& s, std::vector<ex>& out, std::vector<std::string>& kinds) {
  if (GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::numeric>(e.op(1)) &&
      GiNaC::ex_to<GiNaC::numeric>(e.op(1)).is_negative()) {
    split_factors(e.op(0), s, out);
    kinds.resize(out.size(), "the denominator ");
  } else if (GiNaC::is_a<GiNaC::function>(e)) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name == "log") split_factors(e.op(0), s, out);
    if (name == "tan") split_factors(GiNaC::cos(e.op(0)), s, out);
    kinds.resize(out.size(), name == "log" ? "the argument of log " : "the denominator ");
  }
  for (std::size_t i = 0; i < e.nops(); ++i) singular_factors(e.op(i), s, out, kinds);
}

std::mutex& ginac_lock() {
  static std::mutex m;  // GiNaC's reference counts are not atomic
  return m;
}

}  // namespace

std::optional<std::string> symbolic_reading(const std::string& text, std::string& why) {
  std::lock_guard<std::mutex> lock(ginac_lock());
  try {
    const Symbols s;
    return Writer().write(Reader(text, s).read());
  } catch (const Unreadable& u) {
    why = u.why;
  } catch (const std::exception& e) {
    why = std::string("GiNaC: ") + e.what();
  }
  return std::nullopt;
}

std::optional<SymbolicDerivatives> differentiate(const std::string& text, std::string& why) {
  std::lock_guard<std::mutex> lock(ginac_lock());
  try {
    const Symbols s;
    const ex u = Reader(text, s).read();
    const GiNaC::realsymbol* v[3] = {&s.x, &s.y, &s.z};
    SymbolicDerivatives d;
    Writer w;
    d.reading = w.write(u);
    ex g[3];
    for (int i = 0; i < 3; ++i) {
      g[i] = u.diff(*v[i]);
      d.gradient[static_cast<std::size_t>(i)] = w.write(g[i]);
    }
    // Rows xx, xy, yy, xz, yz, zz.
    const int rows[6][2] = {{0, 0}, {0, 1}, {1, 1}, {0, 2}, {1, 2}, {2, 2}};
    for (std::size_t r = 0; r < 6; ++r) d.hessian[r] = w.write(g[rows[r][0]].diff(*v[rows[r][1]]));
    std::vector<ex> factors;
    std::vector<std::string> kinds;
    singular_factors(u, s, factors, kinds);
    for (std::size_t i = 0; i < factors.size() && d.singular.size() < 16; ++i) {
      std::ostringstream name;
      name << kinds[i] << factors[i];
      d.singular.push_back(w.write(factors[i]));
      d.singular_names.push_back(name.str());
    }
    return d;
  } catch (const Unreadable& u) {
    why = u.why;
  } catch (const std::exception& e) {
    why = std::string("GiNaC: ") + e.what();
  }
  return std::nullopt;
}

}  // namespace iga::fem
