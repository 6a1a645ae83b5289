// A refinement study written for ParaView: -Δu = f on the quarter annulus, u = sin(πx) sin(πy), quadratic
// B-splines on 3 uniform refinement levels; each level's solution goes to DIR/series_<level>.vtu and the levels
// to DIR/series.pvd, which ParaView plays as a time series (time = level). Exit 1 unless every file exists and is
// not empty and the L2 error falls at a rate of at least 2.5 (the optimal rate is p + 1 = 3).
#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>

#include "basis/bspline/patches.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "io/vtu_writer.hpp"
#include "refine/uniform.hpp"

int main(int argc, char** argv) {
  using namespace iga;
  namespace fs = std::filesystem;
  CLI::App app{"Poisson on 3 refinement levels, written as a ParaView series (.pvd)"};
  std::string dir = ".";
  app.add_option("--out", dir, "folder for series.pvd and series_<level>.vtu");
  CLI11_PARSE(app, argc, argv);
  fs::create_directories(dir);

  const fem::ManufacturedProblem m = fem::manufactured_problem("sine");
  fem::PoissonProblem p;
  p.source = m.source;
  p.dirichlet = p.exact = m.exact;
  const basis::Geometry coarse = basis::bspline::make_quarter_annulus(2);
  std::vector<io::SeriesEntry> series;
  std::vector<double> l2;
  for (int level = 0; level < 3; ++level) {
    const basis::Geometry g = refine::refine_uniform(coarse, level + 2).geometry;
    const fem::PoissonResult r = fem::solve_poisson(g, quadrature::Gauss(3), p);
    const std::string file = "series_" + std::to_string(level) + ".vtu";
    io::write_vtu((fs::path(dir) / file).string(), g, r.u, {.samples = 3, .exact = p.exact});
    series.push_back({static_cast<double>(level), file});
    l2.push_back(r.errors->l2);
    std::cout << "level " << level << ": " << r.dofs << " dofs, L2 error " << r.errors->l2 << "\n";
  }
  io::write_pvd((fs::path(dir) / "series.pvd").string(), series);

  bool ok = std::log2(l2[0] / l2[2]) / 2 >= 2.5;
  std::cout << "L2 rate " << std::log2(l2[0] / l2[2]) / 2 << "\n";
  for (const std::string& f : {std::string("series.pvd"), series[0].file, series[1].file, series[2].file}) {
    const fs::path path = fs::path(dir) / f;
    const bool written = fs::exists(path) && fs::file_size(path) > 0;
    std::cout << path.string() << (written ? " written" : " MISSING") << "\n";
    ok = ok && written;
  }
  std::cout << (ok ? "OK" : "FAILED") << "\n";
  return ok ? 0 : 1;
}
