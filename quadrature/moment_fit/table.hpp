#pragma once
// Plain-text tables of fitted rules (data/quadrature/cc_<space>_n<N>.txt) and the provider that uses them.
//
// Format (UTF-8 text, one item per line):
//   lines starting with '#' are comments and blank lines are skipped, anywhere;
//   then header lines "key value", in any order, all required:
//     valence N      the valence of the extraordinary vertex (3..16)
//     space S        phi | mass | stiffness (the functions the rule integrates exactly, see fit.hpp)
//     points Q       the number of points
//     residual R     ||Φ w − b||_2 when the table was written
//     seed S         the random seed (FitOptions::seed) and the attempt: "seed S attempt K"
//     symmetric Y    0, or 1 when the rule is symmetric about u = v
//   then the line "data", then Q lines "u v w" (17 significant digits), u, v in [0,1] with max(u,v) > 0
//   (the extraordinary vertex is at (0,0)), w > 0.
#include <memory>
#include <string>
#include <vector>

#include "quadrature/moment_fit/fit.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::quadrature::moment_fit {

struct Table {
  int valence = 0;
  Space space = Space::Phi;
  double residual = 0.0;
  unsigned seed = 0;
  int attempt = 0;
  bool symmetric = false;
  Rule rule;
  std::string note;  ///< written as a comment line (how the rule was made); not read back
};

/// "cc_<space>_n<N>.txt", plus "_sym" before ".txt" for symmetric tables.
std::string table_file_name(int valence, Space space, bool symmetric = false);

/// Writes a table (with a comment header) to path; InputError when the file cannot be written.
void write_table(const std::string& path, const Table& table);

/// Reads a table; InputError "path:line: reason" on any malformed, missing or out-of-range item.
Table load_table(const std::string& path);
/// The rule of load_table(path).
Rule load_rule(const std::string& path);

/// The fitted rules of the tables of one space (phi, mass or stiffness) in a directory on Irregular quads (by
/// valence), 4×4 Gauss on every other element (collapsed on triangles), 4 Gauss points on sides. The tables
/// are read on construction (all cc_<space>_n<N>.txt and cc_<space>_n<N>_sym.txt, N = 3..16, present in the
/// directory; of two tables for one valence the one with fewer points is used); immutable afterwards, hence
/// thread-safe. rule() throws UnsupportedError naming the valence and the space when no table for it was
/// found. Name "fitted" (phi) or "fitted:<space>". Elements at a boundary extraordinary vertex
/// (ElementKind::boundary) are not the interior element the tables were fitted for: they get the per-tile
/// rule tiled_rule(4, 12) instead.
class Fitted final : public RuleProvider {
 public:
  /// InputError when the directory does not exist or a table in it is malformed.
  explicit Fitted(const std::string& directory, Space space = Space::Phi);
  const Rule& rule(const basis::ElementKind& kind) const override;
  const Rule1D& edge_rule() const override { return gauss_.edge_rule(); }
  /// Sides of irregular elements follow their tiles (PerTile(4, 12)'s side rules).
  const Rule1D& side_rule(const basis::ElementKind& kind, int side) const override { return sides_.side_rule(kind, side); }
  std::string name() const override { return space_ == Space::Phi ? "fitted" : "fitted:" + to_string(space_); }
  /// PerTile(6, 12): the tiled rule of its boundary EVs with two more points per direction.
  std::unique_ptr<RuleProvider> error_rules() const override { return std::make_unique<PerTile>(6, 12); }
  Space space() const { return space_; }
  /// The valences with a table.
  std::vector<int> valences() const;

 private:
  std::string directory_;
  Space space_;
  Gauss gauss_;
  Rule tiled_;  // boundary extraordinary vertices
  std::vector<Rule> rules_;  // by valence; empty rule: none
  PerTile sides_;
};

std::unique_ptr<RuleProvider> make_fitted(const std::string& directory, Space space = Space::Phi);

}  // namespace iga::quadrature::moment_fit
