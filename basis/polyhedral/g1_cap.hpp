#pragma once
// Constrained least-squares derivation of a G1 cap (Peters, Lo, Karčiauskas, "Bi-cubic splines for
// polyhedral control nets", eq. (4)): the BB coefficients of the cap's bi-3 patches are the unknowns, the
// surrounding (known) patches are linear in the gathered control-net vertices, every shared boundary
// contributes the linear equations of C0 plus
//     ∂_cross q(t) + a(t) ∂_cross p(t) = b(t) ∂_t p(t),   t ∈ [0, 1]                                   (4)
// (both cross derivatives pointing into their own patch), and the remaining freedom is fixed by
// minimising a fairness functional over the null space of the constraints.  The result is the cap's
// extraction operator: one PatchMask (BB coefficients × gathered vertices) per cap patch.
//
// All parameters are in the patches' own parameter domains [0, 1]²; nothing here knows about a
// particular configuration (star_cap.cpp, ngon_cap.cpp set the systems up).
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// A boundary of one patch of the system, as an affine map of the edge parameter t ∈ [0, 1] into the
/// patch's parameter domain: (u, v)(t) = origin + t·along; `cross` is the transversal direction (pointing
/// into the patch) whose directional derivative enters (4). Lengths matter: a cross vector of length 1/2
/// is the cross derivative of a half-size sub-patch.
struct CapEdge {
  int patch = 0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d along = Eigen::Vector2d::UnitX();
  Eigen::Vector2d cross = Eigen::Vector2d::UnitY();
};

/// A reparameterisation coefficient a(t) or b(t) of (4), t the edge parameter.
using EdgeFunction = std::function<double(double)>;

/// Fairness functional minimised over the null space of the constraints (sum over the cap patches, each in
/// its own parameter domain).
enum class Fairness {
  ThinPlate,         ///< ∫ |∂uu|² + 2|∂uv|² + |∂vv|²
  ThirdDerivatives,  ///< ∫ |∂uuu|² + 3|∂uuv|² + 3|∂uvv|² + |∂vvv|²
};

/// Facts about one derivation (for tests and reports).
struct CapDerivation {
  ConfigurationMask mask;
  int unknowns = 0;                  ///< scalar BB coefficients of the cap (per coordinate)
  int equations = 0;                 ///< rows of the constraint system A x = B g
  int rank = 0;                      ///< rank A
  int rank_augmented = 0;            ///< rank [A | B]
  int null_dimension = 0;            ///< unknowns − rank A: the freedom the fairness functional fixes
  double constraint_residual = 0.0;  ///< max |A x − B| of the result
  double seconds = 0.0;              ///< wall time of the derivation
};

class G1CapSystem {
 public:
  /// `cap_patches` unknown bi-3 patches (indices 0 … cap_patches−1) over `gathered` control-net vertices.
  G1CapSystem(int cap_patches, int gathered);

  /// A known patch (of the surrounding spline) given by its BB coefficients as rows (row j·(du+1)+i) of
  /// a (du+1)(dv+1) × gathered matrix. Returns its patch index.
  int add_known_patch(int degree_u, int degree_v, Eigen::MatrixXd coefficients);

  /// q(t) = p(t) on the shared boundary.
  void join_c0(const CapEdge& q, const CapEdge& p);
  /// C0 and (4) with the given a(t), b(t); q should be a cap patch (p may be either kind).
  void join_g1(const CapEdge& q, const CapEdge& p, const EdgeFunction& a, const EdgeFunction& b);

  /// Solve: checks rank A = rank [A | B] (throws std::runtime_error naming the configuration otherwise), then
  /// minimises the fairness functional over the null space of A.
  CapDerivation solve(Configuration configuration, int valence, Fairness fairness) const;

 private:
  struct Patch {
    int degree_u, degree_v;
    int offset;             ///< first unknown (cap patch) or −1 (known patch)
    Eigen::MatrixXd known;  ///< BB × gathered (known patch)
  };
  /// Row of the extended system [unknowns | gathered] for a derivative (du, dv) at (u, v) of a patch.
  Eigen::RowVectorXd evaluate(int patch, double u, double v, int du, int dv) const;
  Eigen::RowVectorXd directional(const CapEdge& e, double t, int order_cross, int order_along) const;
  void add_row(const Eigen::RowVectorXd& row);

  int cap_patches_;
  int gathered_;
  std::vector<Patch> patches_;
  std::vector<Eigen::RowVectorXd> rows_;
};

/// A cap of `sectors` sectors around a centre, each sector one bi-3 patch (index k) or, when `split`, 2 × 2
/// bi-3 sub-patches (index 4k + 2β + α covering [α/2, (α+1)/2] × [β/2, (β+1)/2] of the sector) joined C1
/// inside the sector. Joins are given on the sector level (CapEdge in sector parameters, t over the whole
/// sector edge, derivatives of the whole sector); a split sector imposes them on both halves of the edge,
/// rescaled so that the sector-level relation (4) holds with the same a(t), b(t).
class SectorCapSystem {
 public:
  SectorCapSystem(int sectors, bool split, int gathered);

  int add_known_patch(int degree_u, int degree_v, Eigen::MatrixXd coefficients) {
    return system_.add_known_patch(degree_u, degree_v, std::move(coefficients));
  }
  /// q: edge of sector q.patch; p: edge of sector p.patch (p_is_sector) or of known patch p.patch.
  void join(const CapEdge& q, const CapEdge& p, bool p_is_sector, const EdgeFunction& a,
            const EdgeFunction& b);
  CapDerivation solve(Configuration configuration, int valence, Fairness fairness) const {
    return system_.solve(configuration, valence, fairness);
  }

 private:
  CapEdge segment(const CapEdge& e, double t0) const;
  int sectors_;
  bool split_;
  G1CapSystem system_;
};

/// The constrained least-squares solve every cap shares: rows [A | −B] over `patches` patches of degree
/// (degree_u, degree_v) followed by `gathered` known columns; A X = B with rank A = rank [A|B] checked
/// (std::runtime_error naming `what` otherwise), X = particular solution + the null-space part minimising the
/// fairness functional. Fills everything of CapDerivation but configuration, valence and seconds.
CapDerivation solve_cap_constraints(const std::vector<Eigen::RowVectorXd>& rows, int patches, int degree_u,
                                    int degree_v, int gathered, Fairness fairness, const std::string& what);

/// Bernstein polynomial B^d_i(t) and its k-th derivative (private helpers, exposed for the cap builders).
double bernstein(int degree, int i, double t);
double bernstein_derivative(int degree, int i, double t, int order);

/// Gram matrix of the fairness functional on one patch of degree (degree_u, degree_v) ≤ (4, 4) over [0,1]²,
/// rows/columns j·(degree_u + 1) + i (exact: 5-point Gauss–Legendre per direction).
Eigen::MatrixXd fairness_gram(Fairness fairness, int degree_u, int degree_v);

}  // namespace iga::basis::polyhedral
