#include "quadrature/exact/geometry_integrals.hpp"

#include <string>

#include "core/error.hpp"
#include "quadrature/exact/subdivision_integrals.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature::exact {

namespace {

void check(const basis::Geometry& g, int dim, int degree, const char* what) {
  if (g.dim() != dim) {
    throw InputError(std::string(what) + ": needs a " + (dim == 2 ? "planar (dim 2)" : "3D surface (dim 3)") +
                     " geometry, got dim " + std::to_string(g.dim()));
  }
  if (degree < 1 || degree > 20) throw InputError(std::string(what) + ": degree must be 1..20, got " + std::to_string(degree));
}

Eigen::MatrixXd local_coordinates(const basis::Geometry& g, Index e) {
  const auto dofs = g.space().dofs(e);
  Eigen::MatrixXd x(static_cast<Eigen::Index>(dofs.size()), g.dim());
  for (std::size_t i = 0; i < dofs.size(); ++i) x.row(static_cast<Eigen::Index>(i)) = g.control_points().row(dofs[i]);
  return x;
}

double triple_form(const Tensor3& t, const Eigen::VectorXd& z, const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  double s = 0;
  for (std::size_t a = 0; a < t.size(); ++a) {
    const double za = z(static_cast<Eigen::Index>(a));
    if (za != 0.0) s += za * (x.dot(t[a] * y) - y.dot(t[a] * x));
  }
  return s;
}

// The two Gauss rules of a polynomial element with `points` per direction: square and collapsed triangle.
struct PolynomialRules {
  Rule quad, triangle;
  explicit PolynomialRules(int points) {
    const Rule1D line = gauss_legendre(points);
    quad = tensor_rule(line, line);
    triangle = collapsed_triangle_rule(line, line);
  }
  const Rule& of(const basis::ElementKind& k) const { return k.shape == basis::Shape::Quad ? quad : triangle; }
};

double gauss_sum(const basis::Geometry& g, Index e, const Rule& rule, bool volume) {
  basis::GeometryValues gv;
  g.evaluate(e, rule.points, gv);
  double s = 0;
  for (Eigen::Index q = 0; q < rule.size(); ++q) {
    const double det = gv.xu(0, q) * gv.xv(1, q) - gv.xu(1, q) * gv.xv(0, q);
    s += rule.weights(q) * det * (volume ? gv.x(2, q) : 1.0);
  }
  return s;
}

// The subdivision view of an irregular element; UnsupportedError naming it when there is none.
basis::SubdivisionElement subdivision_of(const basis::Space& space, Index e, const char* what) {
  auto se = space.subdivision_element(e);
  if (!se) {
    throw UnsupportedError(std::string(what) + ": element " + std::to_string(e + 1) + " (" +
                           basis::to_string(space.kind(e)) + ") has no exact integration data");
  }
  return std::move(*se);
}

}  // namespace

double exact_area(const basis::Geometry& g, int degree) {
  check(g, 2, degree, "exact_area");
  const basis::Space& space = g.space();
  const PolynomialRules rules(degree);
  double area = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.kind(e).family != basis::Family::Irregular) {
      area += gauss_sum(g, e, rules.of(space.kind(e)), false);
      continue;
    }
    const Eigen::MatrixXd d = element_gram(subdivision_of(space, e, "exact_area"), 0, 1);
    const Eigen::MatrixXd xy = local_coordinates(g, e);
    area += xy.col(0).dot(d * xy.col(1)) - xy.col(1).dot(d * xy.col(0));
  }
  return area;
}

double exact_volume(const basis::Geometry& g, int degree) {
  check(g, 3, degree, "exact_volume");
  const basis::Space& space = g.space();
  const PolynomialRules rules((3 * degree + 1) / 2);
  double volume = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.kind(e).family != basis::Family::Irregular) {
      volume += gauss_sum(g, e, rules.of(space.kind(e)), true);
      continue;
    }
    const Tensor3 t = element_triple(subdivision_of(space, e, "exact_volume"), -1, 0, 1);
    const Eigen::MatrixXd p = local_coordinates(g, e);
    volume += triple_form(t, p.col(2), p.col(0), p.col(1));
  }
  return volume;
}

}  // namespace iga::quadrature::exact
