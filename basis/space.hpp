#pragma once
// The one interface every basis backend implements (DESIGN.md, "basis::Space").
#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/element_kind.hpp"
#include "basis/subdivision_view.hpp"
#include "core/types.hpp"

namespace iga::basis {

/// One side of an element that lies on the boundary of the domain; sides as in side_point() for the element's
/// shape. `part` is the index of the boundary part (a name in Space::boundary_part_names()).
struct BoundaryEdge {
  Index element = 0;
  int side = 0;
  int part = 0;
};

/// Two elements that share (part of) a side inside the domain. The shared piece is traversed by s in [0, 1]:
/// on element[i] it is side[i] at side parameter t0[i] + s (t1[i] - t0[i]) (side_point() of that element's
/// shape), and both ends give the same physical point. Conforming neighbours have t0 = 0, t1 = 1 on one
/// element and t0 = 1, t1 = 0 on the other (sides run counter-clockwise on each element); a side of a coarse
/// element that meets several finer ones (hierarchical spaces) appears once per finer neighbour, with the
/// piece's sub-range on the coarse side. `continuity` is the smoothness of the space across the edge: 0 where
/// the functions are only C0 there (normal-flux jumps of a discrete solution are possible), >= 1 otherwise.
struct InteriorEdge {
  Index element[2] = {0, 0};
  int side[2] = {0, 0};
  double t0[2] = {0.0, 1.0};
  double t1[2] = {1.0, 0.0};
  int continuity = 1;
};

/// Number of sides of a reference element: 4 for the unit square, 3 for the unit triangle.
int num_sides(Shape shape);
/// Reference-domain point of side `side` at parameter t in [0,1], and d(u,v)/dt; sides are traversed
/// counter-clockwise. Unit square [0,1]²:
///   0: (t, 0)   1: (1, t)   2: (1 - t, 1)   3: (0, 1 - t).
/// Unit triangle {u, v >= 0, u + v <= 1} with corners (0,0), (1,0), (0,1):
///   0: (t, 0)   1: (1 - t, t)   2: (0, 1 - t).
/// InputError naming the side and shape when side is not 0..num_sides(shape) - 1.
Eigen::Vector2d side_point(Shape shape, int side, double t);
Eigen::Vector2d side_tangent(Shape shape, int side);

/// The form of a NURBS element: its functions are R_i = w_i N_i / Σ_j w_j N_j with N_i polynomials of degree at
/// most `degree` in each of u and v and w_i the weights of its dofs, in dofs(e) order.
struct RationalForm {
  int degree = 0;
  Eigen::VectorXd weights;
};

class Space {
 public:
  virtual ~Space() = default;
  virtual std::string name() const = 0;  ///< backend name as on the command line, e.g. "bspline"
  virtual Index num_dofs() const = 0;
  virtual Index num_elements() const = 0;
  virtual ElementKind kind(Index e) const = 0;
  /// Global dofs whose functions are non-zero on element e; the local order of evaluate()'s rows.
  virtual std::span<const Index> dofs(Index e) const = 0;
  /// The largest dofs(e).size() over all elements (for buffer sizes).
  virtual Index max_local_dofs() const = 0;
  /// Values (and, for derivatives >= 1 or 2, first or second parametric derivatives) of element e's local
  /// functions at pts (2 × q, reference coordinates). Allocation-free when `out` already has the sizes.
  virtual void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const = 0;
  /// Element sides on the boundary of the domain, in a fixed order.
  virtual std::vector<BoundaryEdge> boundary_edges() const = 0;
  /// Names of the boundary parts that BoundaryEdge::part indexes.
  virtual std::vector<std::string> boundary_part_names() const = 0;
  /// Every interior edge once (InteriorEdge), in a fixed order. Backends without adjacency information throw
  /// UnsupportedError naming themselves.
  virtual std::vector<InteriorEdge> interior_edges() const;
  /// Refinement level of element e in a hierarchical space (0 = the coarsest); 0 for single-level spaces.
  virtual int level(Index) const { return 0; }
  /// Whether refining an element into `level` must first build that level of the space's hierarchy (Catmull–Clark
  /// builds each level on first use, the dominant cost of a deep adaptive step): for time forecasts. False for
  /// single-level spaces and hierarchies whose levels cost nothing to reach.
  virtual bool builds_level(int) const { return false; }
  /// For exact integration of an infinitely piecewise element (subdivision_view.hpp): its tiles and
  /// subdivision structure; std::nullopt for polynomial elements and backends without one.
  virtual std::optional<SubdivisionElement> subdivision_element(Index) const { return std::nullopt; }
  /// The degree d such that every local function of element e is, on the element's whole reference domain, one
  /// polynomial of degree at most d in each of u and v (Quad shape) or of total degree at most d (Triangle shape);
  /// std::nullopt (the default) for an infinitely piecewise element (at an extraordinary vertex or face) and for
  /// backends that do not say. Output uses it to write such elements exactly as Bézier cells (io/bezier_writer).
  virtual std::optional<int> polynomial_degree(Index) const { return std::nullopt; }
  /// The rational form of element e when it is a NURBS element (output writes it exactly as a rational Bézier cell);
  /// std::nullopt (the default) for every other element.
  virtual std::optional<RationalForm> rational_form(Index) const { return std::nullopt; }
  /// Twin classes (issue 17): the lowest-numbered element whose reference values (evaluate_reference()) element e
  /// derives its local functions from with from_reference(); e itself, the default, unless the backend knows such a
  /// twin. For the default hooks twins have the same functions in reference coordinates and local order (every
  /// interior element of a uniform B-spline space); a NURBS space's twins share B-spline values and each applies its
  /// own weights. The assembler evaluates a class's reference values once per rule and reuses them; they are always
  /// those of the class's lowest element, so results do not depend on the order elements are visited.
  virtual Index reference_element(Index e) const { return e; }
  /// The values element `twin` (a class's lowest) shares with its class: by default its own functions.
  virtual void evaluate_reference(Index twin, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
    evaluate(twin, pts, derivatives, out);
  }
  /// Element e's local functions from its class's reference values (the blocks needed for `derivatives`): by
  /// default a copy.
  virtual void from_reference(Index e, const BasisValues& reference, int derivatives, BasisValues& out) const;
};

}  // namespace iga::basis
