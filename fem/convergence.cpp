#include "fem/convergence.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.hpp"

namespace iga::fem {

ConvergenceTable::ConvergenceTable(std::vector<std::string> norms, int dim) : norms_(std::move(norms)), dim_(dim) {
  if (dim_ < 1) throw InputError("ConvergenceTable: dimension " + std::to_string(dim_) + " is not positive");
}

void ConvergenceTable::add_row(const ConvergenceRow& row) {
  if (row.errors.size() != norms_.size()) {
    throw InputError("ConvergenceTable: a row has " + std::to_string(row.errors.size()) + " errors for " +
                     std::to_string(norms_.size()) + " norms");
  }
  if (!(row.h > 0.0) || !std::isfinite(row.h) || row.dofs <= 0) {
    throw InputError("ConvergenceTable: level " + std::to_string(row.level) + " has no positive mesh size and dofs");
  }
  for (std::size_t i = 0; i < row.errors.size(); ++i) {
    if (!(row.errors[i] >= 0.0) || !std::isfinite(row.errors[i])) {
      throw InputError("ConvergenceTable: level " + std::to_string(row.level) + ": the " + norms_[i] +
                       " error is negative or not finite");
    }
  }
  rows_.push_back(row);
}

double ConvergenceTable::size(const ConvergenceRow& row, Against against) const {
  return against == Against::h ? row.h : std::pow(static_cast<double>(row.dofs), -1.0 / dim_);
}

std::vector<std::optional<double>> ConvergenceTable::rates(std::size_t norm, Against against) const {
  std::vector<std::optional<double>> out(rows_.size());
  for (std::size_t k = 1; k < rows_.size(); ++k) {
    const double e0 = rows_[k - 1].errors.at(norm), e1 = rows_[k].errors.at(norm);
    const double x0 = size(rows_[k - 1], against), x1 = size(rows_[k], against);
    if (e0 > 0.0 && e1 > 0.0 && x0 != x1) out[k] = std::log(e0 / e1) / std::log(x0 / x1);
  }
  return out;
}

std::optional<double> ConvergenceTable::fitted_rate(std::size_t norm, Against against) const {
  // Slope of the least-squares line through (log x_k, log e_k): Σ(X - X̄)(Y - Ȳ) / Σ(X - X̄)².
  std::vector<double> xs, ys;
  for (const ConvergenceRow& row : rows_) {
    if (row.errors.at(norm) > 0.0) {
      xs.push_back(std::log(size(row, against)));
      ys.push_back(std::log(row.errors.at(norm)));
    }
  }
  if (xs.size() < 2) return std::nullopt;
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    mx += xs[i];
    my += ys[i];
  }
  mx /= static_cast<double>(xs.size());
  my /= static_cast<double>(ys.size());
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    sxy += (xs[i] - mx) * (ys[i] - my);
    sxx += (xs[i] - mx) * (xs[i] - mx);
  }
  if (sxx == 0.0) return std::nullopt;
  return sxy / sxx;
}

namespace {
std::string cell(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}
std::string rate_cell(const std::optional<double>& r) { return r ? cell("%6.2f", *r) : std::string("     -"); }
}  // namespace

std::string ConvergenceTable::text() const {
  std::ostringstream out;
  out << "level       dofs   elements          h";
  for (const std::string& n : norms_) {
    const std::string title = n + " error";
    out << "  " << std::string(title.size() < 10 ? 10 - title.size() : 0, ' ') << title << "    rate";
  }
  out << "   seconds\n";
  std::vector<std::vector<std::optional<double>>> r;
  for (std::size_t i = 0; i < norms_.size(); ++i) r.push_back(rates(i));
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const ConvergenceRow& row = rows_[k];
    out << cell("%5.0f", row.level) << cell(" %10.0f", static_cast<double>(row.dofs))
        << cell(" %10.0f", static_cast<double>(row.elements)) << cell(" %10.3e", row.h);
    for (std::size_t i = 0; i < norms_.size(); ++i) out << "  " << cell("%10.3e", row.errors[i]) << "  " << rate_cell(r[i][k]);
    out << cell(" %9.3f", row.seconds) << "\n";
  }
  out << "fitted rate (least squares over " << rows_.size() << " levels):";
  for (std::size_t i = 0; i < norms_.size(); ++i) {
    const std::optional<double> f = fitted_rate(i);
    out << " " << norms_[i] << " " << (f ? cell("%.3f", *f) : std::string("-"));
  }
  out << "\n";
  return out.str();
}

}  // namespace iga::fem
