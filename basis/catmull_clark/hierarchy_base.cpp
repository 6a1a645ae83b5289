#include "basis/catmull_clark/hierarchy_base.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace iga::basis::catmull_clark {

namespace {

// Native corner j of a face at (0,0), (1,0), (1,1), (0,1).
Eigen::Vector2d corner(int j) {
  static const double c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const int k = ((j % 4) + 4) % 4;
  return {c[k][0], c[k][1]};
}

// The element frame of rotation r in native coordinates: native = corner(r) + frame(r) · reference
// (reference u runs c_r → c_{r+1}, v runs c_r → c_{r+3}; space.hpp).
Eigen::Matrix2d frame(int r) {
  Eigen::Matrix2d m;
  m.col(0) = corner(r + 1) - corner(r);
  m.col(1) = corner(r + 3) - corner(r);
  return m;
}

}  // namespace

CatmullClarkHierarchy::CatmullClarkHierarchy(std::shared_ptr<const CatmullClarkSpace> level0) : level0_(std::move(level0)) {
  if (!level0_) throw InputError("Catmull–Clark levels: no level-0 space given");
  max_local_ = static_cast<int>(std::max<Index>(level0_->max_local_dofs(), 2 * 16 + 8));
}

void CatmullClarkHierarchy::child_map(int l, Key cell, int slot, Eigen::Matrix2d& a, Eigen::Vector2d& b) const {
  // parent native s = (c_k + t) / 2 (refine_net), child native t = c_rc + F_rc y, parent reference
  // x = F_rp^T (s - c_rp) (F orthogonal).
  const int rp = rotation(l, cell), rc = rotation(l + 1, 4 * cell + slot);
  const Eigen::Matrix2d fp = frame(rp);
  a = 0.5 * fp.transpose() * frame(rc);
  b = fp.transpose() * (0.5 * (corner(slot) + corner(rc)) - corner(rp));
}

std::optional<int> CatmullClarkHierarchy::polynomial_degree(int l, Key cell) const {
  if (kind(l, cell).family == Family::Regular) return 3;
  return std::nullopt;
}

int CatmullClarkHierarchy::continuity(int l, Key cell, int side) const {
  return kind(l, cell).family == Family::Irregular && (side == 0 || side == 3) ? 1 : 2;
}

}  // namespace iga::basis::catmull_clark
