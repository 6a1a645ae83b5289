#include "basis/catmull_clark/exact_view.hpp"

#include <map>
#include <memory>
#include <mutex>

#include "basis/catmull_clark/regular_patch.hpp"
#include "basis/catmull_clark/stam.hpp"

namespace iga::basis::catmull_clark {

SubdivisionView quad_view(const Eigen::MatrixXd& a, const Eigen::VectorXd& w, const std::array<Eigen::MatrixXd, 3>& tiles) {
  SubdivisionView v;
  v.patch_shape = Shape::Quad;
  v.patch_degree = 3;
  v.patch_functions = [](const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) {
    bicubic_values(pts, derivatives, 1.0, out);
  };
  v.subdivision = a;
  v.limit = w;
  for (std::size_t k = 0; k < 3; ++k) v.tiles[k] = {tiles[k], 2.0 * Eigen::Matrix2d::Identity()};
  return v;
}

const SubdivisionView& stam_view(int n) {
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const SubdivisionView>> cache;
  const StamEvaluator& st = stam_evaluator(n);
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[n];
  if (!slot) {
    std::array<Eigen::MatrixXd, 3> tiles;
    for (int k = 1; k <= 3; ++k) tiles[static_cast<std::size_t>(k - 1)] = st.picking_matrix(k) * st.extended_subdivision_matrix();
    slot = std::make_unique<const SubdivisionView>(quad_view(st.subdivision_matrix(), st.limit_stencil(), tiles));
  }
  return *slot;
}

}  // namespace iga::basis::catmull_clark
