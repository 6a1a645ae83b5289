#include "basis/registry.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include "basis/boundary_overlap.hpp"
#include "basis/fold_certificate.hpp"
#include "core/error.hpp"

namespace iga::basis {

const std::vector<Backend>& backends() {
  // One registration per backend folder; the order is the order of --help and of backend_names().
  static const std::vector<Backend> all = {bspline_backend(), catmull_clark_backend(), polyhedral_backend(),
                                            half_box_backend()};
  return all;
}

std::string backend_names() {
  std::string names;
  for (const Backend& b : backends()) names += (names.empty() ? "" : ", ") + b.name;
  return names;
}

const Backend& backend(const std::string& name) {
  for (const Backend& b : backends()) {
    if (b.name == name) return b;
  }
  throw UnsupportedError("--basis " + name + ": not available in this build (available: " + backend_names() + ")");
}

const Backend& backend_of(const Space& space) {
  for (const Backend& b : backends()) {
    if (b.name == space.name()) return b;
  }
  throw UnsupportedError("a '" + space.name() + "' space belongs to no registered backend (" + backend_names() + ")");
}

void check_options(const Backend& backend, const std::vector<std::string>& given) {
  for (const std::string& option : given) {
    if (std::find(backend.options.begin(), backend.options.end(), option) != backend.options.end()) continue;
    std::string takes;
    for (const std::string& o : backend.options) takes += (takes.empty() ? "--" : ", --") + o;
    throw InputError("--" + option + " is not an option of --basis " + backend.name +
                     " (its options: " + (takes.empty() ? "none" : takes) + ")");
  }
}

int degree(const Backend& backend, const BackendOptions& options) {
  if (backend.degree_of) return backend.degree_of(options);
  return options.degree == BackendOptions::kUnset ? backend.default_degree : options.degree;
}

namespace {
// The built geometry, fitted to options.fit_to when given (its distance a note).
Geometry fitted(Geometry g, const BackendOptions& options, BackendFacts& facts) {
  if (!options.fit_to) return g;
  if (g.dim() != 3) throw InputError("--fit-to: the geometry is planar; a surface in 3D is fitted to a cylinder or a sphere");
  SurfaceFit fit = fit_to_surface(g, *options.fit_to);
  std::ostringstream note;
  note << "--fit-to: control points fitted to the " << options.fit_to->description()
       << "; the surface's samples lie within " << fit.distance << " of it";
  facts.notes.push_back(note.str());
  facts.fit_distance = fit.distance;
  return std::move(fit.geometry);
}

// Every geometry a program builds is proved not to fold where its elements have a polynomial form, and a planar
// domain to be bounded by simple closed curves and covered once (folds between the points of a rule, slits and
// self-overlapping nets were solved with exit 0 before: issue 38).
Geometry certified(Geometry g) {
  if (const std::string why = fold_certificate(g); !why.empty()) throw NumericalError(why);
  if (const std::string why = boundary_overlap(g); !why.empty()) throw InputError(why);
  return g;
}
// A planar net whose boundary polygon meets itself (a crack or slit: duplicated vertices, or two sides along the
// same segment) is refused before any backend reads it.
void refuse_cracks(const mesh::PolyMesh& net) {
  if (const std::string why = net_boundary_overlap(net); !why.empty()) throw InputError(why);
}
// A backend refining one step names it "refinement 1: "; the caller refining step by step names the step itself.
std::string strip_step_label(const std::string& message) {
  const std::string label = "refinement 1: ";
  return message.rfind(label, 0) == 0 ? message.substr(label.size()) : message;
}
}  // namespace

Geometry make_geometry(const Backend& backend, const mesh::PolyMesh* net, const BackendOptions& options,
                       BackendFacts& facts) {
  if (net && !options.geometry.empty()) throw InputError("--geometry and --mesh exclude each other");
  if (net) refuse_cracks(*net);
  if (!net && !backend.default_geometry) {
    throw InputError("--basis " + backend.name + " needs --mesh (a control net)");
  }
  return certified(fitted(net ? backend.from_net(*net, options, facts) : backend.default_geometry(options), options, facts));
}

mesh::PolyMesh net_with_control_points(const mesh::PolyMesh& net, const Geometry& geometry,
                                       const std::function<Index(Index)>& vertex_of_dof) {
  std::vector<Eigen::Vector3d> points = net.points();
  for (Index d = 0; d < geometry.space().num_dofs(); ++d) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head(geometry.dim()) = geometry.control_points().row(d).transpose();
    points[static_cast<std::size_t>(vertex_of_dof(d))] = p;
  }
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < net.num_faces(); ++f) faces.emplace_back(net.face(f).begin(), net.face(f).end());
  return mesh::PolyMesh::build(std::move(points), std::move(faces));
}

Refinement make_refined_geometry(const Backend& backend, const mesh::PolyMesh* net, const BackendOptions& options,
                                 int steps, BackendFacts& facts, bool keep_steps) {
  if (steps < 0) throw InputError("refinement steps must be >= 0, got " + std::to_string(steps));
  if (!backend.nested && net && steps > 0 && backend.refine_net) {
    refuse_cracks(*net);
    Geometry g = certified(fitted(backend.from_net(backend.refine_net(*net, steps, options, facts), options, facts), options, facts));
    return {std::move(g), Eigen::SparseMatrix<double>(), false};
  }
  return refine_uniform(make_geometry(backend, net, options, facts), steps, facts, keep_steps);
}

Refinement refine_uniform(const Geometry& geometry, int steps, BackendFacts& facts, bool keep_steps) {
  if (steps < 0) throw InputError("refinement steps must be >= 0, got " + std::to_string(steps));
  if (steps == 0) {
    const Index n = geometry.space().num_dofs();
    Eigen::SparseMatrix<double> identity(n, n);
    identity.setIdentity();
    return {geometry, std::move(identity), true};
  }
  const Backend& b = backend_of(geometry.space());
  if (!b.refine) throw UnsupportedError("uniform refinement of a '" + b.name + "' space is not implemented");
  if (!keep_steps || !b.nested) return b.refine(geometry, steps, facts);
  // One step at a time, each step's prolongation kept. A step's refusal names the step, as the backends do when
  // they refine several steps at once.
  Refinement out{geometry, Eigen::SparseMatrix<double>(), true};
  for (int k = 0; k < steps; ++k) {
    std::optional<Refinement> next;
    try {
      next = b.refine(out.geometry, 1, facts);
    } catch (const InputError& e) {
      throw InputError("refinement " + std::to_string(k + 1) + ": " + strip_step_label(e.what()));
    }
    if (k == 0) {
      out.prolongation = next->prolongation;
    } else {
      Eigen::SparseMatrix<double> composed = next->prolongation * out.prolongation;
      out.prolongation.swap(composed);
    }
    out.geometry = std::move(next->geometry);
    out.steps.push_back(std::move(next->prolongation));
  }
  return out;
}

Refinement refine_marked(const Geometry& geometry, std::span<const Index> marked, int admissibility,
                         BackendFacts& facts, bool with_prolongation) {
  const Backend& b = backend_of(geometry.space());
  if (!b.refine_marked) throw UnsupportedError("local refinement of a '" + b.name + "' space is not implemented");
  return b.refine_marked(geometry, marked, admissibility, facts, with_prolongation);
}

}  // namespace iga::basis
