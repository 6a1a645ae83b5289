#include "benchmarks/study.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "benchmarks/python_script.hpp"
#include "core/error.hpp"
#include "fem/convergence.hpp"
#include "io/forecast.hpp"
#include "io/report.hpp"
#include "io/vtu_writer.hpp"

namespace iga::bench {

namespace {

using Log = std::function<void(const std::string&)>;
using Against = fem::ConvergenceTable::Against;
const std::vector<std::string> kNorms{"L2", "H1"};      // columns of the table
const std::vector<std::string> kNormKeys{"l2", "h1"};   // their report keys: l2_error, h1_error, l2_rate, ...

bool whole(const std::string& text, int lo, int hi, int& value) {
  std::size_t used = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    return false;
  }
  return used == text.size() && value >= lo && value <= hi && text.find_first_of("+- ") == std::string::npos;
}

// One series: the levels of one degree.
struct Series {
  int degree = 0;                  // as asked (0: the run's own)
  fem::ConvergenceTable table{kNorms};
  nlohmann::json levels = nlohmann::json::array();
  std::string pvd;
};

std::string name_part(int degree) { return degree > 0 ? "_p" + std::to_string(degree) : std::string(); }

std::string vtu_base(const StudyOptions& o) {
  if (o.vtu.empty() || o.vtu == "none") return std::string();
  return o.vtu.size() > 4 && o.vtu.substr(o.vtu.size() - 4) == ".vtu" ? o.vtu.substr(0, o.vtu.size() - 4) : o.vtu;
}

std::string file_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

std::string level_name(int degree, int k) {
  return std::to_string(k) + (degree > 0 ? " (degree " + std::to_string(degree) + ")" : std::string());
}

// The levels of one degree: each solved by the program's pipeline, its row added to the table. Before each level
// but the study's first, the time limit (forecast, over the levels of this degree): `stopped` set and no more levels
// when it says stop.
Series run_series(const StudyOptions& o, const StudyHooks& hooks, int degree, bool first_series,
                  io::StepForecast& forecast, std::string& stopped, const Log& log) {
  Series s;
  s.degree = degree;
  const std::string base = vtu_base(o);
  std::vector<io::SeriesEntry> entries;
  forecast.restart();  // a new degree starts on the coarse level again
  for (int k = o.levels.first; k <= o.levels.last; ++k) {
    if (k > o.levels.first || !first_series) {  // the study's first level runs: nothing to predict it from
      stopped = forecast.stop_reason(level_name(degree, k), false, forecast.elapsed());
      if (!stopped.empty()) break;
    }
    const std::string vtu = base.empty() ? std::string() : base + name_part(degree) + "_k" + std::to_string(k) + ".vtu";
    nlohmann::json level = hooks.solve(degree, k, vtu);
    if (level["l2_error"].is_null() || level["h1_error"].is_null()) {
      throw InputError("--study needs an exact solution for its error norms (--problem, or --exact with --source)");
    }
    // h: the side of a square of the mean element area, sqrt(|Ω| / elements); each uniform step halves it.
    const double h = std::sqrt(level["domain_measure"].get<double>() / level["elements"].get<double>());
    level["h"] = h;
    const double seconds = level["assembly_seconds"].get<double>() + level["solve_seconds"].get<double>();
    s.table.add_row({k, level["dofs"].get<Index>(), level["elements"].get<Index>(), h,
                     {level["l2_error"].get<double>(), level["h1_error"].get<double>()}, seconds});
    forecast.done(level["dofs"].get<double>(), false, forecast.elapsed());
    log("study: degree " + std::to_string(level["degree"].get<int>()) + ", level " + std::to_string(k) + " done: " +
        std::to_string(level["dofs"].get<Index>()) + " dofs; " +
        forecast.progress(k < o.levels.last ? level_name(degree, k + 1) : std::string(), false));
    if (!vtu.empty()) {
      entries.push_back({static_cast<double>(k), file_name(vtu)});
      s.pvd = base + name_part(degree) + ".pvd";
      io::write_pvd(s.pvd, entries);
    }
    s.levels.push_back(level);
  }
  for (std::size_t n = 0; n < kNorms.size(); ++n) {
    const auto rates = s.table.rates(n, Against::h), rates_dofs = s.table.rates(n, Against::dofs);
    for (std::size_t k = 0; k < rates.size(); ++k) {
      s.levels[k][kNormKeys[n] + "_rate"] = optional_json(rates[k]);
      s.levels[k][kNormKeys[n] + "_rate_dofs"] = optional_json(rates_dofs[k]);
    }
  }
  return s;
}

nlohmann::json series_json(const Series& s) {
  nlohmann::json j;
  j["degree"] = s.levels.at(0)["degree"];
  j["levels"] = s.levels;
  for (std::size_t n = 0; n < kNorms.size(); ++n) {
    const std::string& key = kNormKeys[n];
    for (const auto& [name, against] : {std::pair{"", Against::h}, std::pair{"_dofs", Against::dofs}}) {
      nlohmann::json rates = nlohmann::json::array();
      for (const auto& r : s.table.rates(n, against)) rates.push_back(optional_json(r));
      j[std::string("rates") + name][key] = rates;
      j[std::string("fitted_rates") + name][key] = optional_json(s.table.fitted_rate(n, against));
    }
  }
  if (!s.pvd.empty()) j["pvd"] = s.pvd;
  return j;
}

std::string csv_number(const nlohmann::json& v) {
  if (v.is_null()) return std::string();
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v.get<double>());
  return buffer;
}

// One line per level; rates empty on the first level (and where an error is 0).
std::string study_csv(const std::vector<Series>& series) {
  std::ostringstream out;
  out << "degree,level,dofs,elements,h,l2_error,l2_rate,h1_error,h1_rate,l2_rate_dofs,h1_rate_dofs,"
         "assembly_seconds,solve_seconds\n";
  for (const Series& s : series) {
    for (const nlohmann::json& l : s.levels) {
      out << l["degree"].get<int>() << "," << l["refine"].get<int>();
      for (const char* key : {"dofs", "elements", "h", "l2_error", "l2_rate", "h1_error", "h1_rate", "l2_rate_dofs",
                              "h1_rate_dofs", "assembly_seconds", "solve_seconds"}) {
        out << "," << csv_number(l[key]);
      }
      out << "\n";
    }
  }
  return out.str();
}

// The plots of plot_study.py from PREFIX.json; the outcome for the report.
nlohmann::json draw_plots(const StudyOptions& o, const std::string& json_path, const Log& log) {
  nlohmann::json p = {{"formats", o.plots}, {"drawn", false}};
  auto not_drawn = [&](const std::string& reason) {
    p["reason"] = reason;
    std::cerr << "iga-poisson: plots not drawn: " << reason << "; " << o.output << ".csv and " << o.output
              << ".json are written (--plots none skips plotting)" << std::endl;
    return p;
  };
  std::vector<std::string> looked;
  const std::string script = find_share_file("plot_study.py", looked);
  if (script.empty()) {
    std::string where;
    for (const std::string& l : looked) where += (where.empty() ? "" : ", ") + l;
    return not_drawn("plot_study.py not found (looked at " + where + ")");
  }
  const std::string python = python_interpreter();
  const ScriptRun run = run_script(python, {script, json_path, o.output, "--formats", o.plots});
  std::string last = run.output;
  while (!last.empty() && (last.back() == '\n' || last.back() == '\r')) last.pop_back();
  if (last.find('\n') != std::string::npos) last = last.substr(last.find_last_of('\n') + 1);
  if (!run.started) return not_drawn("cannot run " + run.output);
  // Exit code 3: the script could not import matplotlib (its line says what failed).
  if (run.exit_code == 3) return not_drawn(python + " " + last);
  if (run.exit_code != 0) {
    throw Error(script + " failed (exit code " + std::to_string(run.exit_code) + "): " + last);
  }
  p["drawn"] = true;
  p["script"] = script;
  for (const char* plot : {"_dofs", "_seconds"}) {
    for (const char* format : {"png", "svg"}) {
      if (o.plots.find(format) != std::string::npos) p["files"].push_back(o.output + plot + "." + format);
    }
  }
  log("plotted " + p["files"].dump());
  return p;
}

}  // namespace

std::string check_levels(const std::string& text) {
  const std::size_t colon = text.find(':');
  int first = 0, last = 0;
  if (colon == std::string::npos || !whole(text.substr(0, colon), 0, kMaxStudyLevel, first) ||
      !whole(text.substr(colon + 1), 0, kMaxStudyLevel, last)) {
    return "'" + text + "' is not K0:K1 (refinement levels, whole numbers from 0 to " + std::to_string(kMaxStudyLevel) + ")";
  }
  if (last - first + 1 < kMinStudyLevels) {
    return "'" + text + "' has " + std::to_string(std::max(0, last - first + 1)) + " levels; a study needs at least " +
           std::to_string(kMinStudyLevels) + " (K1 >= K0 + " + std::to_string(kMinStudyLevels - 1) + ")";
  }
  return std::string();
}

StudyLevels parse_levels(const std::string& text) {
  if (const std::string why = check_levels(text); !why.empty()) throw InputError("--study: " + why);
  const std::size_t colon = text.find(':');
  return {std::stoi(text.substr(0, colon)), std::stoi(text.substr(colon + 1))};
}

std::string check_degrees(const std::string& text) {
  std::vector<int> seen;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    int d = 0;
    if (!whole(item, 1, 12, d)) return "'" + item + "' is not a degree (a whole number from 1 to 12)";
    if (std::find(seen.begin(), seen.end(), d) != seen.end()) return "degree " + item + " is listed twice";
    seen.push_back(d);
  }
  if (seen.empty() || text.back() == ',') return "'" + text + "' is not a comma-separated list of degrees";
  return std::string();
}

std::vector<int> parse_degrees(const std::string& text) {
  if (const std::string why = check_degrees(text); !why.empty()) throw InputError("--degrees: " + why);
  std::vector<int> degrees;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) degrees.push_back(std::stoi(item));
  return degrees;
}

int run_study(const StudyOptions& o, const StudyHooks& hooks) {
  const auto t_start = std::chrono::steady_clock::now();
  const Log log = [quiet = o.quiet](const std::string& s) {
    if (!quiet) std::cerr << "iga-poisson: " << s << std::endl;
  };
  const std::vector<int> degrees = o.degrees.empty() ? std::vector<int>{0} : o.degrees;
  for (int d : degrees) hooks.check_size(d, o.levels.last);  // the finest levels, before any work
  io::StepForecast forecast(o.max_seconds, "--max-seconds", "level");
  std::string stopped;
  std::vector<Series> series;
  for (int d : degrees) {
    Series done = run_series(o, hooks, d, series.empty(), forecast, stopped, log);
    if (done.levels.empty()) break;  // stopped before its first level
    series.push_back(std::move(done));
    const nlohmann::json& first = series.back().levels.at(0);
    if (!o.quiet) {
      std::cerr << "\nconvergence study: " << first["basis"].get<std::string>() << ", degree " << first["degree"]
                << ", " << first["mesh"].get<std::string>() << "; rates e ~ h^r, h = sqrt(area / elements)\n"
                << series.back().table.text() << std::endl;
    }
    if (!stopped.empty()) break;
  }
  if (!stopped.empty()) {
    const nlohmann::json& done = series.back().levels.back();
    log("study stopped after degree " + std::to_string(done["degree"].get<int>()) + ", level " +
        std::to_string(done["refine"].get<int>()) + ": " + stopped);
  }
  nlohmann::json j;
  const nlohmann::json& first = series.front().levels.at(0);
  for (const char* key : {"program", "version", "git_revision", "schema_version", "settings", "basis", "mesh", "dimension",
                          "problem", "quadrature", "solver"}) {
    j[key] = first[key];
  }
  j["study"] = {{"levels", {o.levels.first, o.levels.last}},
                {"degrees", o.degrees},
                {"h", "sqrt(domain_measure / elements): the side of a square of the mean element area"},
                {"rates", "log(e_{k-1} / e_k) / log(h_{k-1} / h_k), e ~ h^r; fitted_rates: least-squares slope of "
                          "log e over log h of all levels; *_dofs: the same with N^(-1/dimension), N = dofs"},
                {"max_seconds", o.max_seconds},
                {"stopped", stopped.empty() ? std::string("levels") : stopped}};
  for (const Series& s : series) j["series"].push_back(series_json(s));
  const bool files = o.output != "none";
  if (files) {
    j["csv"] = o.output + ".csv";
    io::write_text(o.output + ".csv", study_csv(series));
    j["plots"] = {{"formats", o.plots}, {"drawn", false}, {"reason", "not requested"}};
    j["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
    io::write_json(o.output + ".json", j);
    if (o.plots != "none") {
      j["plots"] = draw_plots(o, o.output + ".json", log);
      io::write_json(o.output + ".json", j);  // again, with what the plots became
    }
    log("wrote " + o.output + ".csv and " + o.output + ".json");
  } else if (o.plots != "none") {
    log("no plots: --study-output none writes no files to plot from");
  }
  j["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if (!o.json.empty() && o.json != "none") io::write_json(o.json, j);
  return 0;
}

}  // namespace iga::bench
