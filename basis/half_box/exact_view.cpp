#include "basis/half_box/exact_view.hpp"

#include <map>
#include <memory>
#include <mutex>

#include "basis/half_box/regular_patch.hpp"
#include "basis/half_box/subdivision_structure.hpp"

namespace iga::basis::half_box {

const SubdivisionView& half_box_view(int n) {
  const SubdivisionStructure& s = subdivision_structure(n);
  static std::mutex mutex;
  static std::map<int, std::unique_ptr<const SubdivisionView>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& slot = cache[n];
  if (!slot) {
    auto v = std::make_unique<SubdivisionView>();
    v->patch_shape = Shape::Triangle;
    v->patch_degree = 3;
    v->patch_functions = [](const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) {
      evaluate_regular(pts, derivatives, out);
    };
    v->subdivision = s.patch_matrix;
    v->limit = s.limit_stencil.transpose();
    for (int k = 0; k < 3; ++k) {
      v->tiles[static_cast<std::size_t>(k)] = {s.picking_matrix(k) * s.extended_matrix, s.tiles[static_cast<std::size_t>(k)].jacobian};
    }
    slot = std::move(v);
  }
  return *slot;
}

}  // namespace iga::basis::half_box
