#pragma once
// What every solver program (iga-poisson, iga-biharmonic, iga-elasticity) does before it solves, in one place: the
// backend from the registry and its options, the control net, the refined geometry and the quadrature rules, from
// the options a user gives on the command line (io/discretisation_options.hpp adds them to a CLI11 app). No backend
// policy here: the registry (basis/registry.hpp) holds it.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "basis/registry.hpp"
#include "mesh/poly_mesh.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::io {

/// The command line's discretisation, as given.
struct DiscretisationOptions {
  std::string mesh;               ///< --mesh: an OBJ control net; empty: the backend's default geometry
  std::string basis = "bspline";  ///< --basis: a registered backend
  std::string geometry;           ///< --geometry (bspline): a built-in geometry or a patch file
  std::string cc_boundary = "natural", cc_enrich = "none";
  std::string cc_corners;         ///< --cc-corners (cc): net vertices, 1-based as the OBJ's f lines, comma-separated
  std::string refine_intervals;   ///< --refine-intervals (bspline): 0-based knot intervals, comma-separated
  std::string coarse_split;       ///< --coarse-split (bspline): "U,V", parts per knot interval along u and v
  std::string quadrature;         ///< --quadrature; empty: the backend's default for the degree
  std::string fit_to;             ///< --fit-to (any backend): an exact surface the built geometry is fitted to
  int degree = 3, refine = -1, presubdivide = 0;  ///< refine < 0: the backend's default
  int grade_evs = -1;  ///< --grade-evs (cc): local refinements toward extraordinary vertices after --refine; < 0: the backend's default_grading
  /// The backend options given on the command line (names without dashes): only these reach the backend.
  std::vector<std::string> given;
  bool count(const std::string& option) const;
};

/// The backend, its options and the coarse net: what every run (and every level of a study) starts from.
struct Discretisation {
  const basis::Backend* backend = nullptr;
  basis::BackendOptions options;
  int degree = 0;  ///< per direction, as the backend uses it
  std::optional<mesh::PolyMesh> net;
};

/// The backend (UnsupportedError for an unknown one), its options checked against what it takes (InputError naming
/// the first it does not take), and the net read (InputError naming file and line).
Discretisation make_discretisation(const DiscretisationOptions& o);

/// The backend options of the words given (--degree, --cc-boundary, ...; not the lists, which make_discretisation
/// parses). Never throws for a backend the command line's --basis check admits.
basis::BackendOptions backend_options(const DiscretisationOptions& o);

/// --refine, or the backend's default number of steps.
int refine_steps(const DiscretisationOptions& o, const Discretisation& d);

/// The elements a run will have after its refinement steps (each splits every element in four, --presubdivide's
/// too), predicted before it is made.
double predicted_elements(const DiscretisationOptions& o, const Discretisation& d);

/// "3,4" → {3, 4}; InputError naming --refine-intervals for an item that is not a 0-based index.
std::vector<Index> parse_intervals(const std::string& list);

/// "41,7" → {40, 6}: vertex numbers from 1 as an OBJ's f lines write them, returned 0-based; InputError naming
/// `option` for an item that is not one, or an empty list.
std::vector<Index> parse_vertex_numbers(const std::string& option, const std::string& list);

/// The geometry refined as asked (uniformly, or --refine-intervals' refine-and-smooth steps); check(elements, dofs)
/// runs on the refined space before anything is assembled on it (a program's memory check). keep_steps (--solver
/// mg): each step's prolongation too (Refinement::steps); UnsupportedError for a backend whose spaces are not nested.
basis::Refinement refined_geometry(const DiscretisationOptions& o, const Discretisation& d,
                                    basis::BackendFacts& facts,
                                    const std::function<void(Index elements, Index dofs)>& check = {},
                                    bool keep_steps = false);

/// The rules of --quadrature (or the backend's default); InputError naming --quadrature for a bad specification and
/// for Gauss rules with fewer than degree + 1 points per direction.
std::unique_ptr<quadrature::RuleProvider> make_rules(const DiscretisationOptions& o, const Discretisation& d);

/// The report's description of the discretisation: basis, mesh ("default:<geometry>" without a net), dimension,
/// orientation, degree, refine, nested_refinement, refine_intervals and the backend's counts.
nlohmann::json discretisation_report(const DiscretisationOptions& o, const Discretisation& d,
                                     const basis::Refinement& refined, const basis::BackendFacts& facts);

}  // namespace iga::io
