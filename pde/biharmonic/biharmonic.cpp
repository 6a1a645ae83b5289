#include "pde/biharmonic/biharmonic.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "fem/dirichlet.hpp"
#include "fem/linear_system.hpp"
#include "fem/nitsche.hpp"
#include "fem/smoothness.hpp"
#include "pde/biharmonic/forms.hpp"

namespace iga::pde {

namespace {

class Biharmonic final : public fem::Problem {
 public:
  explicit Biharmonic(BiharmonicData data) : d_(std::move(data)) {
    if (d_.source) source_ = std::make_unique<fem::SourceForm>(d_.source);
  }
  std::string name() const override { return "biharmonic"; }

  void check(const basis::Geometry& geometry) const override {
    if (geometry.dim() != 2) {
      throw UnsupportedError("biharmonic: planar domains only (this geometry is a surface in 3D)");
    }
    if (!(d_.nitsche_penalty >= 0.0) || !std::isfinite(d_.nitsche_penalty)) {
      throw InputError("biharmonic: Nitsche penalty must be a finite number >= 0 (0: the local estimate), got " +
                       std::to_string(d_.nitsche_penalty));
    }
    const std::vector<std::string> names = geometry.space().boundary_part_names();
    for (int p : d_.simply_supported) {
      if (p < 0 || p >= static_cast<int>(names.size())) {
        throw InputError("biharmonic: simply supported boundary part " + std::to_string(p) + " does not exist (" +
                         std::to_string(names.size()) + " parts)");
      }
    }
    smoothness_ = fem::check_c1(geometry, "biharmonic", "Δ²u = f");
    clamped_.clear();
    supported_.clear();
    all_ = geometry.space().boundary_edges();
    if (all_.empty()) throw InputError("biharmonic: the domain has no boundary to hold the plate");
    for (const basis::BoundaryEdge& e : all_) {
      const bool ss = std::find(d_.simply_supported.begin(), d_.simply_supported.end(), e.part) !=
                      d_.simply_supported.end();
      (ss ? supported_ : clamped_).push_back(e);
    }
    part_names_ = names;
  }

  std::vector<const fem::BilinearForm*> bilinear_forms() const override { return {&form_}; }
  std::vector<const fem::LinearForm*> linear_forms() const override {
    if (source_) return {source_.get()};
    return {};
  }

  void add_boundary_terms(const fem::Assembler& assembler, fem::LinearSystem& system,
                          fem::Choices& choices) const override {
    choices.emplace_back("smoothness", smoothness_);
    const Eigen::SparseMatrix<double> none;
    if (!clamped_.empty()) {
      double gamma = d_.nitsche_penalty;
      const fem::NitschePenalty penalty = fem::nitsche_penalty(
          assembler, clamped_, gamma, [](const fem::BoundaryContext& ctx, Eigen::MatrixXd& s) { s = ctx.laplacian; },
          [](const fem::ElementContext& ctx) -> const Eigen::MatrixXd& { return ctx.laplacian; }, 2, &gamma);
      const std::shared_ptr<const fem::BoundaryFunction> h =
          d_.slope ? d_.slope : fem::normal_flux(fem::constant_function(0.0));
      const ClampedNitscheForm form(penalty);
      const ClampedNitscheLoad load(h, penalty);
      Eigen::SparseMatrix<double> a;
      Eigen::VectorXd b;
      assembler.assemble_boundary(clamped_, &form, &load, &a, &b);
      system.add(a, b);
      std::ostringstream s;
      s << parts(clamped_) << ": u strong, du/dn by Nitsche ("
        << (d_.nitsche_penalty > 0 ? "gamma / h, gamma = " : "local penalty, max beta h = ") << gamma << ")";
      choices.emplace_back("clamped", s.str());
    }
    if (!supported_.empty()) {
      if (d_.moment) {
        const MomentLoad load(d_.moment);
        Eigen::VectorXd b;
        assembler.assemble_boundary(supported_, nullptr, &load, nullptr, &b);
        system.add(none, b);
      }
      choices.emplace_back("simply supported", parts(supported_) + ": u strong, Laplacian natural");
    }
  }

  fem::DirichletConditions constraints(const fem::Assembler& assembler, fem::Choices&) const override {
    return fem::project_dirichlet(assembler, all_, d_.value ? d_.value : fem::constant_function(0.0));
  }

  /// L2, the H1 and H2 seminorms, and the energy norm ‖Δe‖ of the bilinear form.
  std::vector<std::string> error_names() const override {
    if (!d_.exact) return {};
    return {"L2", "H1", "H2", "energy"};
  }
  std::vector<std::string> error_derivatives() const override {
    if (!d_.exact) return {};
    return {fem::derivatives_in(fem::Norm::kL2, *d_.exact), fem::derivatives_in(fem::Norm::kH1, *d_.exact),
            fem::derivatives_in(fem::Norm::kH2, *d_.exact), fem::derivatives_in(fem::Norm::kLaplacian, *d_.exact)};
  }
  Eigen::VectorXd error_squares(const fem::Assembler& by, const Eigen::VectorXd& u,
                                const fem::LinearSystem& system) const override {
    const fem::Norm norms[4] = {fem::Norm::kL2, fem::Norm::kH1, fem::Norm::kH2, fem::Norm::kLaplacian};
    return fem::summed_squares(system, [&](const std::vector<char>* only) {
      return fem::norm_squares(by, u, *d_.exact, norms, only);
    });
  }

 private:
  std::string parts(const std::vector<basis::BoundaryEdge>& edges) const {
    std::vector<int> seen;
    for (const basis::BoundaryEdge& e : edges) {
      if (std::find(seen.begin(), seen.end(), e.part) == seen.end()) seen.push_back(e.part);
    }
    std::sort(seen.begin(), seen.end());
    std::string out;
    for (int p : seen) out += (out.empty() ? "" : ", ") + part_names_[static_cast<std::size_t>(p)];
    return out;
  }

  BiharmonicData d_;
  BiharmonicForm form_;
  std::unique_ptr<fem::SourceForm> source_;
  // From check(): the boundary split and what was checked (check() runs once, in setup, before the rest).
  mutable std::vector<basis::BoundaryEdge> all_, clamped_, supported_;
  mutable std::vector<std::string> part_names_;
  mutable std::string smoothness_;
};

}  // namespace

BiharmonicData biharmonic_data_from_exact(std::shared_ptr<const fem::Function> exact,
                                          std::shared_ptr<const fem::Function> source,
                                          std::vector<int> simply_supported) {
  BiharmonicData d;
  d.source = std::move(source);
  d.value = exact;
  d.slope = fem::normal_flux(exact);
  d.moment = fem::laplacian_of(exact);
  d.simply_supported = std::move(simply_supported);
  d.exact = std::move(exact);
  return d;
}

std::shared_ptr<const fem::Problem> make_biharmonic(BiharmonicData data) {
  return std::make_shared<Biharmonic>(std::move(data));
}

}  // namespace iga::pde
