#include "io/bezier_layout.hpp"

#include <vtkCellType.h>
#include <vtkHigherOrderQuadrilateral.h>
#include <vtkHigherOrderTriangle.h>

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <utility>

#include "core/error.hpp"

namespace iga::io {

namespace {

double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * static_cast<double>(n - k + i) / static_cast<double>(i);
  return b;
}

/// Chebyshev–Lobatto points on [0, 1], exactly symmetric about 1/2.
std::vector<double> lobatto_nodes(int d) {
  std::vector<double> t(static_cast<std::size_t>(d + 1));
  for (int i = 0; 2 * i <= d; ++i) {
    const double ti = 2 * i == d ? 0.5 : 0.5 * (1.0 - std::cos(std::numbers::pi * i / d));
    t[static_cast<std::size_t>(i)] = i == 0 ? 0.0 : ti;
    t[static_cast<std::size_t>(d - i)] = 1.0 - t[static_cast<std::size_t>(i)];
  }
  return t;
}

/// Lattice and nodes in VTK's point order.
void fill_points(BezierLayout& l) {
  const int d = l.degree;
  if (l.shape == basis::Shape::Quad) {
    const std::vector<double> t = lobatto_nodes(d);
    const int order[3] = {d, d, 0};
    l.lattice.resize(static_cast<std::size_t>((d + 1) * (d + 1)));
    l.nodes.resize(2, (d + 1) * (d + 1));
    for (int j = 0; j <= d; ++j) {
      for (int i = 0; i <= d; ++i) {
        const int k = vtkHigherOrderQuadrilateral::PointIndexFromIJK(i, j, order);
        l.lattice[static_cast<std::size_t>(k)] = {i, j};
        l.nodes.col(k) << t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>(j)];
      }
    }
  } else {
    l.lattice.resize(static_cast<std::size_t>((d + 1) * (d + 2) / 2));
    l.nodes.resize(2, static_cast<Eigen::Index>(l.lattice.size()));
    for (int j = 0; j <= d; ++j) {
      for (int i = 0; i + j <= d; ++i) {
        const vtkIdType b[3] = {i, j, d - i - j};
        const auto k = static_cast<int>(vtkHigherOrderTriangle::Index(b, d));
        l.lattice[static_cast<std::size_t>(k)] = {i, j};
        l.nodes.col(k) << static_cast<double>(i) / d, static_cast<double>(j) / d;
      }
    }
  }
  l.on_side.resize(l.lattice.size());
  for (std::size_t k = 0; k < l.lattice.size(); ++k) {
    const auto [i, j] = l.lattice[k];
    l.on_side[k] = i == 0 || j == 0 || (l.shape == basis::Shape::Quad ? (i == d || j == d) : i + j == d);
  }
}

std::unique_ptr<BezierLayout> make_layout(basis::Shape shape, int degree) {
  auto l = std::make_unique<BezierLayout>();
  l->shape = shape;
  l->degree = degree;
  fill_points(*l);
  l->collocation.compute(l->bernstein(l->nodes).transpose());
  return l;
}

}  // namespace

Eigen::MatrixXd BezierLayout::bernstein(const Eigen::Matrix2Xd& pts) const {
  const int d = degree;
  Eigen::MatrixXd b(num_points(), pts.cols());
  for (Eigen::Index q = 0; q < pts.cols(); ++q) {
    const double u = pts(0, q), v = pts(1, q), w = 1.0 - u - v;
    for (int k = 0; k < num_points(); ++k) {
      const auto [i, j] = lattice[static_cast<std::size_t>(k)];
      if (shape == basis::Shape::Quad) {
        b(k, q) = binomial(d, i) * std::pow(u, i) * std::pow(1.0 - u, d - i) * binomial(d, j) * std::pow(v, j) *
                  std::pow(1.0 - v, d - j);
      } else {
        b(k, q) = binomial(d, i) * binomial(d - i, j) * std::pow(u, i) * std::pow(v, j) * std::pow(w, d - i - j);
      }
    }
  }
  return b;
}

std::vector<int> BezierLayout::side_points(int side) const {
  const int d = degree;
  std::vector<int> out;
  for (int t = 0; t <= d; ++t) {
    std::array<int, 2> ij{};
    if (shape == basis::Shape::Quad) {
      const std::array<std::array<int, 2>, 4> at = {{{t, 0}, {d, t}, {d - t, d}, {0, d - t}}};
      ij = at[static_cast<std::size_t>(side)];
    } else {
      const std::array<std::array<int, 2>, 3> at = {{{t, 0}, {d - t, t}, {0, d - t}}};
      ij = at[static_cast<std::size_t>(side)];
    }
    for (int k = 0; k < num_points(); ++k) {
      if (lattice[static_cast<std::size_t>(k)] == ij) out.push_back(k);
    }
  }
  return out;
}

unsigned char BezierLayout::vtk_type() const {
  return shape == basis::Shape::Quad ? VTK_BEZIER_QUADRILATERAL : VTK_BEZIER_TRIANGLE;
}

const BezierLayout& bezier_layout(basis::Shape shape, int degree) {
  if (degree < 1 || degree > kMaxBezierDegree) {
    throw InputError("Bézier output: degree " + std::to_string(degree) + " is outside 1.." +
                     std::to_string(kMaxBezierDegree));
  }
  static std::mutex mutex;
  static std::map<std::pair<int, int>, std::unique_ptr<BezierLayout>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[{static_cast<int>(shape), degree}];
  if (!slot) slot = make_layout(shape, degree);
  return *slot;
}

int curve_point_order(int degree, int k) {
  if (k == 0) return 0;
  if (k == 1) return degree;
  return k - 1;
}

}  // namespace iga::io
