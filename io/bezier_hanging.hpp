#pragma once
// Hanging sides in the Bézier output (bezier_writer.cpp): in a locally refined space a side of a coarse element may
// meet several finer ones. Where the coarse element is polynomial, its cell and theirs are exact and agree. Where it
// is not, its one interpolating cell cannot follow the finer cells; instead the finer cells take the coarse cell's
// side curve (restricted to their piece and degree-raised), so the output stays watertight — those finer cells are
// then exact everywhere except along that side, where they carry the coarse cell's interpolation error.
#include <Eigen/Core>
#include <vector>

#include "basis/space.hpp"
#include "io/bezier_layout.hpp"

namespace iga::io {

/// Control points of one cell before merging, rows in its layout's point order: x (n × 3), u and exact (n; empty
/// when not written), fields (n × the components of all sampled fields; empty without).
struct CellControl {
  Eigen::MatrixXd x;
  Eigen::VectorXd u, exact;
  Eigen::MatrixXd fields;
  Eigen::VectorXd weights;  ///< rational weights of the points (NURBS elements); empty for polynomial cells
};

/// Side fine_side of element `fine`, at its side parameter τ ∈ [0, 1], is side coarse_side of element `coarse` at
/// a + τ (b − a).
struct HangingSide {
  Index coarse = 0, fine = 0;
  int coarse_side = 0, fine_side = 0;
  double a = 0.0, b = 1.0;
};

/// The hanging sides of the space's non-polynomial elements (from Space::interior_edges(); none for backends without
/// adjacency information), coarser elements first; raises degree[fine] to degree[coarse] where it is lower.
std::vector<HangingSide> hanging_sides(const basis::Space& space, std::vector<int>& degree);

/// Replaces the control points of side h.fine_side of the fine cell by the coarse cell's side curve on [a, b]
/// (x, u, exact and the fields alike). layout[e] is the layout of cell e (the fine one's degree >= the coarse one's).
void follow_coarse_side(const HangingSide& h, const std::vector<const BezierLayout*>& layout,
                        std::vector<CellControl>& control);

}  // namespace iga::io
