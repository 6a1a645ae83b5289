// Moment-fitted rules (quadrature/moment_fit): every stored table re-verified against the moments, a small
// fit from a fixed seed, the table format and its errors, the Fitted provider.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "quadrature/moment_fit/fit.hpp"
#include "quadrature/moment_fit/table.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/rule_provider.hpp"

using namespace iga::quadrature;
using namespace iga::quadrature::moment_fit;

namespace {
const std::filesystem::path kTables = std::filesystem::path(IGA_SOURCE_DIR) / "data" / "quadrature";

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "iga_test_moment_fit";
  std::filesystem::create_directories(dir);
  return dir / name;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// The table must integrate its space exactly: residual, points, weights.
void verify(const Table& t, const std::string& label) {
  SCOPED_TRACE(label);
  ASSERT_GT(t.rule.size(), 0);
  EXPECT_LE(residual(t.valence, t.space, t.rule), 1e-13);
  EXPECT_GT(t.rule.weights.minCoeff(), 0.0);
  EXPECT_GE(t.rule.points.minCoeff(), 0.0);
  EXPECT_LE(t.rule.points.maxCoeff(), 1.0);
  EXPECT_GT(t.rule.points.colwise().maxCoeff().minCoeff(), 0.0);  // never the extraordinary vertex
  // The splines are a partition of unity, so 1 is in the phi space and (as (Σφ)²) in the mass space; the
  // stiffness space (gradients) does not contain the constants, so its weights need not sum to the area.
  // For mass, Σ w = Σ_{a,b} (Φw)_{ab} is a sum of the M = num_functions residual entries with factors 1 or 2,
  // so |Σ w − 1| <= 2 √M ||Φw − b|| <= 2 √M 1e-13 (the bound the residual check above implies).
  if (t.space == Space::Phi) {
    EXPECT_NEAR(t.rule.weights.sum(), 1.0, 1e-13);
  } else if (t.space == Space::Mass) {
    EXPECT_NEAR(t.rule.weights.sum(), 1.0, 2.0 * std::sqrt(num_functions(t.valence, t.space)) * 1e-13);
  }
  if (t.symmetric) {  // (u, v) and (v, u) both present with equal weights
    for (Eigen::Index i = 0; i < t.rule.size(); ++i) {
      bool mirrored = false;
      for (Eigen::Index j = 0; j < t.rule.size() && !mirrored; ++j) {
        mirrored = std::abs(t.rule.points(0, i) - t.rule.points(1, j)) < 1e-14 &&
                   std::abs(t.rule.points(1, i) - t.rule.points(0, j)) < 1e-14 &&
                   std::abs(t.rule.weights(i) - t.rule.weights(j)) < 1e-15;
      }
      EXPECT_TRUE(mirrored) << "point " << i;
    }
  }
}
}  // namespace

// Every table in data/quadrature/ still integrates its space to 1e-13 (so no table can silently rot).
TEST(MomentFit, EveryStoredTableIsExact) {
  ASSERT_TRUE(std::filesystem::is_directory(kTables)) << kTables;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kTables)) {
    if (entry.path().extension() != ".txt") continue;
    const Table t = load_table(entry.path().string());
    EXPECT_EQ(entry.path().filename().string(), table_file_name(t.valence, t.space, t.symmetric));
    verify(t, entry.path().string());
    ++count;
  }
  EXPECT_GE(count, 4);  // at least the phi rules of n = 3..6
}

// The check above covers every space: the stored mass and stiffness tables are among the files it reads.
// Their moments are exact (geometric series); cross-check them against a fine per-tile rule (exact on the
// tiles of levels 1..40, the corner square left is 4^-40 of the element), so a wrong moment cannot make a
// table look exact.
TEST(MomentFit, MassAndStiffnessMomentsMatchTheTiledRule) {
  const Rule fine = tiled_rule(4, 40);
  for (int n : {3, 4, 5, 8}) {
    for (const Space space : {Space::Mass, Space::Stiffness}) {
      SCOPED_TRACE(to_string(space) + " n=" + std::to_string(n));
      const Eigen::VectorXd& b = moments(n, space);
      ASSERT_EQ(b.size(), num_functions(n, space));
      Eigen::MatrixXd f;
      evaluate_functions(n, space, fine.points, f);
      EXPECT_LE((f * fine.weights - b).norm(), 1e-13 * b.norm());
    }
    // Σ_a,b φ_a φ_b = 1 (partition of unity): the off-diagonal products count twice.
    const Eigen::VectorXd& m = moments(n, Space::Mass);
    double total = 0;
    Eigen::Index k = 0;
    for (int a = 0; a < 2 * n + 8; ++a) {
      for (int c = a; c < 2 * n + 8; ++c, ++k) total += (a == c ? 1.0 : 2.0) * m(k);
    }
    EXPECT_NEAR(total, 1.0, 1e-14);
  }
}

TEST(MomentFit, ExactMomentsArePartitionOfUnityAndMatchTheTiledRule) {
  for (int n : {3, 5, 8}) {
    const Eigen::VectorXd& b = moments(n, Space::Phi);
    ASSERT_EQ(b.size(), 2 * n + 8);
    EXPECT_NEAR(b.sum(), 1.0, 1e-14);
    const Rule fine = tiled_rule(6, 40);
    Eigen::MatrixXd f;
    evaluate_functions(n, Space::Phi, fine.points, f);
    EXPECT_LE((f * fine.weights - b).norm(), 1e-15);
  }
}

TEST(MomentFit, FitsValence3WithAFixedSeed) {
  FitOptions o;
  o.seed = 7;
  o.attempts = 10;
  const FitResult r = fit_rule(3, 7, o);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.rule.size(), 7);
  EXPECT_LE(r.residual, 1e-13);
  EXPECT_LE(residual(3, Space::Phi, r.rule), 1e-13);
  EXPECT_GT(r.rule.weights.minCoeff(), 0.0);
  EXPECT_GE(r.rule.points.minCoeff(), o.lower_bound);
  EXPECT_LE(r.rule.points.maxCoeff(), 1.0);
  ASSERT_FALSE(r.attempts.empty());
  EXPECT_TRUE(r.attempts.back().converged);  // stop_at_first: the last attempt is the converged one
  // Same seed, same rule.
  const FitResult again = fit_rule(3, 7, o);
  EXPECT_EQ(again.best_attempt, r.best_attempt);
  EXPECT_EQ((again.rule.points - r.rule.points).norm(), 0.0);
}

TEST(MomentFit, SymmetricFitValence3) {
  FitOptions o;
  o.symmetric = true;
  o.attempts = 20;
  o.seed = 11;
  const FitResult r = fit_rule(3, 8, o);
  ASSERT_TRUE(r.converged) << "best residual " << r.residual;
  Table t;
  t.valence = 3;
  t.symmetric = true;
  t.rule = r.rule;
  verify(t, "symmetric n=3 q=8");
}

// Node elimination: from the per-tile rule (exact for n = 4, where the functions are polynomials of degree
// <= 6 per direction and every tile has a 4 × 4 Gauss rule) down to a smaller rule that still integrates the
// stiffness space to 1e-13, with positive weights and points inside the element.
TEST(MomentFit, EliminationShrinksAnExactRule) {
  FitOptions o;
  o.space = Space::Stiffness;
  o.attempts = 2;
  o.polish_iterations = 1000;  // the LM polish converges slowly; with 100-300 iterations no point can be removed
  const Rule start = tiled_rule(4, 1);  // 64 points
  const FitResult r = eliminate_points(4, start, o, 40);
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.points, r.rule.size());
  EXPECT_LE(r.rule.size(), 40);  // min_points reached: every removal down to 40 re-converged
  Table t;
  t.valence = 4;
  t.space = Space::Stiffness;
  t.rule = r.rule;
  verify(t, "elimination n=4 stiffness");
  EXPECT_THROW(eliminate_points(2, start, o), iga::InputError);
}

TEST(MomentFit, RejectsBadArguments) {
  EXPECT_THROW(fit_rule(2, 7, FitOptions{}), iga::InputError);
  FitOptions o;
  o.symmetric = true;
  o.diagonal_points = 2;
  EXPECT_THROW(fit_rule(3, 7, o), iga::InputError);
  o = FitOptions{};
  o.algorithm = "LD_NOPE";
  EXPECT_THROW(fit_rule(3, 7, o), iga::InputError);
  EXPECT_THROW(parse_space("stiff"), iga::InputError);
}

TEST(MomentFitTable, WriteLoadRoundTripIsExact) {
  FitOptions o;
  o.seed = 3;
  const FitResult r = fit_rule(3, 7, o);
  ASSERT_TRUE(r.converged);
  Table t;
  t.valence = 3;
  t.residual = r.residual;
  t.seed = r.seed;
  t.attempt = r.best_attempt;
  t.rule = r.rule;
  const auto path = scratch("round_trip.txt");
  write_table(path.string(), t);
  const Table back = load_table(path.string());
  EXPECT_EQ(back.valence, 3);
  EXPECT_EQ(back.space, Space::Phi);
  EXPECT_EQ(back.seed, r.seed);
  EXPECT_EQ(back.attempt, r.best_attempt);
  EXPECT_EQ((back.rule.points - r.rule.points).norm(), 0.0);  // 17 significant digits round-trip exactly
  EXPECT_EQ((back.rule.weights - r.rule.weights).norm(), 0.0);
}

TEST(MomentFitTable, BadInputNamesFileAndLine) {
  const std::string header = "# c\nvalence 3\nspace phi\npoints 2\nresidual 1e-16\nseed 1 attempt 0\nsymmetric 0\ndata\n";
  const auto path = scratch("bad.txt");
  auto expect_error_at = [&](const std::string& text, long line) {
    write_text(path, text);
    try {
      load_rule(path.string());
      ADD_FAILURE() << "no error for:\n" << text;
    } catch (const iga::InputError& e) {
      EXPECT_EQ(e.file(), path.string());
      EXPECT_EQ(e.line(), line) << e.what();
    }
  };
  expect_error_at(header + "0.5 0.5 0.5\n0.2 0.3\n", 10);          // missing weight
  expect_error_at(header + "0.5 0.5 0.5\n0.0 0.0 0.5\n", 10);      // the extraordinary vertex
  expect_error_at(header + "0.5 0.5 0.5\n0.5 1.5 0.5\n", 10);      // outside
  expect_error_at(header + "0.5 0.5 -0.5\n0.5 0.5 0.5\n", 9);      // negative weight
  expect_error_at(header + "0.5 0.5 0.5\n", 9);                    // too few lines (end of file)
  expect_error_at(header + "0.5 0.5 0.5\n0.5 0.5 0.5\n0.5 0.5 0.5\n", 11);  // too many
  expect_error_at("valence 3\nspace phi\ndata\n", 3);               // missing headers
  expect_error_at("valence 30\n", 1);
  expect_error_at("valence 3\nspace nurbs\n", 2);
  expect_error_at("colour red\n", 1);
  write_text(path, header + "0.5 0.5 0.5\n0.25 0.75 0.5\n");
  EXPECT_EQ(load_rule(path.string()).size(), 2);
  EXPECT_THROW(load_rule(scratch("missing.txt").string()), iga::InputError);
}

TEST(MomentFitProvider, UsesTablesOnIrregularQuadsAndGaussElsewhere) {
  const auto provider = make_fitted(kTables.string());
  EXPECT_EQ(provider->name(), "fitted");
  iga::basis::ElementKind kind;
  kind.family = iga::basis::Family::Irregular;
  kind.scheme = iga::basis::Scheme::CatmullClark;
  kind.valence = 3;
  const Rule& r3 = provider->rule(kind);
  EXPECT_EQ(r3.size(), 5);  // cc_phi_n3.txt (5 points) beats cc_phi_n3_sym.txt (6)
  EXPECT_EQ(provider->rule(iga::basis::ElementKind{}).size(), 16);  // 4 × 4 Gauss on regular quads
  EXPECT_EQ(provider->edge_rule().size(), 4);
  kind.valence = 7;  // only a symmetric table exists for n = 7
  EXPECT_EQ(provider->rule(kind).size(), load_rule((kTables / table_file_name(7, Space::Phi, true)).string()).size());
  // An element at a boundary extraordinary vertex is not the element of the tables: the per-tile rule.
  kind.valence = 4;
  kind.boundary = true;
  const Rule& rb = provider->rule(kind);
  const Rule tiles = tiled_rule(4, 12);
  ASSERT_EQ(rb.size(), tiles.size());
  EXPECT_EQ((rb.points - tiles.points).cwiseAbs().maxCoeff(), 0.0);
  kind.boundary = false;
  kind.valence = 17;
  EXPECT_THROW(provider->rule(kind), iga::UnsupportedError);
  // An empty directory: every irregular valence is unsupported, the message names it.
  const auto empty = scratch("empty_dir");
  std::filesystem::create_directories(empty);
  const Fitted none(empty.string());
  kind.valence = 5;
  try {
    none.rule(kind);
    ADD_FAILURE();
  } catch (const iga::UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("valence 5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Fitted("/nonexistent/iga"), iga::InputError);
}

// The spec "fitted[:SPACE][:DIR]": phi by default (fitted, fitted:DIR as before), fitted:mass, fitted:stiffness,
// fitted:SPACE:DIR; a valence without a table of the space is an UnsupportedError naming valence and space.
TEST(MomentFitProvider, SpecSelectsTheSpaceAndNamesMissingTables) {
  // A directory holding one mass table (valence 5) and one stiffness table (valence 3); their contents are
  // a per-tile rule, which is enough to see which table the provider picked.
  const auto dir = scratch("spec_dir");
  std::filesystem::create_directories(dir);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) std::filesystem::remove(entry.path());
  Table mass;
  mass.valence = 5;
  mass.space = Space::Mass;
  mass.rule = tiled_rule(2, 3);  // 40 points
  write_table((dir / table_file_name(5, Space::Mass)).string(), mass);
  Table stiff;
  stiff.valence = 3;
  stiff.space = Space::Stiffness;
  stiff.rule = tiled_rule(3, 1);  // 36 points
  write_table((dir / table_file_name(3, Space::Stiffness)).string(), stiff);

  iga::basis::ElementKind kind;
  kind.family = iga::basis::Family::Irregular;
  kind.scheme = iga::basis::Scheme::CatmullClark;
  kind.valence = 5;
  const auto m = make_rule_provider("fitted:mass:" + dir.string(), 4);
  EXPECT_EQ(m->name(), "fitted:mass");
  EXPECT_EQ(m->rule(kind).size(), 40);
  EXPECT_EQ(m->rule(iga::basis::ElementKind{}).size(), 16);  // 4 × 4 Gauss on regular quads
  kind.valence = 3;
  try {
    m->rule(kind);
    ADD_FAILURE() << "no error for a missing mass table";
  } catch (const iga::UnsupportedError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("valence 3"), std::string::npos) << what;
    EXPECT_NE(what.find("mass"), std::string::npos) << what;
  }
  const auto k = make_rule_provider("fitted:stiffness:" + dir.string(), 4);
  EXPECT_EQ(k->name(), "fitted:stiffness");
  EXPECT_EQ(k->rule(kind).size(), 36);
  kind.valence = 5;
  try {
    k->rule(kind);
    ADD_FAILURE() << "no error for a missing stiffness table";
  } catch (const iga::UnsupportedError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("valence 5"), std::string::npos) << what;
    EXPECT_NE(what.find("stiffness"), std::string::npos) << what;
  }
  // fitted:DIR and fitted:phi:DIR: the phi tables (none in this directory).
  for (const std::string& spec : {"fitted:" + dir.string(), "fitted:phi:" + dir.string()}) {
    const auto p = make_rule_provider(spec, 4);
    EXPECT_EQ(p->name(), "fitted") << spec;
    EXPECT_THROW(p->rule(kind), iga::UnsupportedError) << spec;
  }
  // The default directory (the source tree's tables): fitted is phi, as before.
  const auto def = make_rule_provider("fitted", 4);
  EXPECT_EQ(def->name(), "fitted");
  kind.valence = 3;
  EXPECT_EQ(def->rule(kind).size(), 5);  // cc_phi_n3.txt
  EXPECT_EQ(make_rule_provider("fitted:phi", 4)->rule(kind).size(), 5);
  // Bad specifications: InputError naming the specification.
  for (const std::string& spec : {std::string("fitted:"), std::string("fitted:mass:"), "fitted:mass:" + dir.string() + "/nope"}) {
    EXPECT_THROW(make_rule_provider(spec, 4), iga::InputError) << spec;
  }
  // A table of the wrong space under a mass name is rejected when the provider reads it.
  write_table((dir / table_file_name(3, Space::Mass)).string(), stiff);
  EXPECT_THROW(make_rule_provider("fitted:mass:" + dir.string(), 4), iga::InputError);
}
