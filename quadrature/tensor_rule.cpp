#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature {

Rule tensor_rule(const Rule1D& u, const Rule1D& v) {
  const Eigen::Index nu = u.size(), nv = v.size();
  Rule r;
  r.points.resize(2, nu * nv);
  r.weights.resize(nu * nv);
  for (Eigen::Index j = 0; j < nv; ++j) {
    for (Eigen::Index i = 0; i < nu; ++i) {
      r.points(0, i + nu * j) = u.points(i);
      r.points(1, i + nu * j) = v.points(j);
      r.weights(i + nu * j) = u.weights(i) * v.weights(j);
    }
  }
  return r;
}

Rule collapsed_triangle_rule(const Rule1D& s, const Rule1D& t) {
  Rule r = tensor_rule(s, t);
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    const double u = r.points(0, k);
    r.points(1, k) *= 1.0 - u;
    r.weights(k) *= 1.0 - u;
  }
  return r;
}

}  // namespace iga::quadrature
