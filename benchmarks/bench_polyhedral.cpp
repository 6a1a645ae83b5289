// bench-polyhedral: the one-off cost of the polyhedral mask derivations (constrained least squares per
// configuration and valence, uncached), with the size of each system. JSON on stdout (and --json FILE).
// The assembly cost on a large net is measured with iga-poisson (benchmarks/README.md).
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "basis/polyhedral/ngon_cap.hpp"
#include "basis/polyhedral/polar_cap.hpp"
#include "basis/polyhedral/star_cap.hpp"
#include "basis/polyhedral/tjunction_cap.hpp"
#include "io/report.hpp"

int main(int argc, char** argv) {
  CLI::App app{"bench-polyhedral: mask derivation time per configuration"};
  std::string json;
  int repeat = 3;
  app.add_option("--repeat", repeat, "derivations per configuration (the fastest counts)")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--json", json, "write the report here too");
  CLI11_PARSE(app, argc, argv);
  try {
    namespace poly = iga::basis::polyhedral;
    nlohmann::json report = {{"program", "bench-polyhedral"}, {"repeat", repeat}};
    auto record = [&](const std::string& name, auto&& derive) {
      poly::CapDerivation best;
      for (int r = 0; r < repeat; ++r) {
        poly::CapDerivation d = derive();
        if (r == 0 || d.seconds < best.seconds) best = std::move(d);
      }
      report["configurations"][name] = {{"patches", best.mask.patches.size()}, {"gathered", best.mask.gathered},
                                        {"unknowns", best.unknowns}, {"equations", best.equations},
                                        {"rank", best.rank}, {"null_dimension", best.null_dimension},
                                        {"constraint_residual", best.constraint_residual},
                                        {"seconds", best.seconds}};
      std::cerr << "bench-polyhedral: " << name << " " << best.seconds << " s" << std::endl;
    };
    for (int n : {3, 5, 6, 7, 8}) {
      record("star" + std::to_string(n), [&] { return poly::derive_star_cap(n); });
      record("ngon" + std::to_string(n), [&] { return poly::derive_ngon_cap(n); });
    }
    for (int n = 3; n <= 8; ++n) record("polar" + std::to_string(n), [&] { return poly::derive_polar_cap(n); });
    record("T0", [] { return poly::derive_t0_cap(); });
    record("T1", [] { return poly::derive_t1_cap(); });
    record("T2", [] { return poly::derive_t2_cap(); });
    std::cout << report.dump(2) << std::endl;
    if (!json.empty()) iga::io::write_json(json, report);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench-polyhedral: error: " << e.what() << std::endl;
    return 1;
  }
}
