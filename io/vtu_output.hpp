#pragma once
// The .vtu output of a program in the format chosen on its command line (--vtu-format bezier|linear), so the
// programs share one rule and stay thin.
#include <Eigen/Core>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/function.hpp"
#include "io/vtu_writer.hpp"

namespace iga::io {

struct VtuOutput {
  std::string format = "bezier";  ///< "bezier" (bezier_writer.hpp) or "linear" (vtu_writer.hpp)
  int samples = 5;                ///< linear: points per direction per element
  int degree = 6;                 ///< bezier: degree of the cells of elements that are not polynomial
  std::shared_ptr<const fem::Function> exact;
  std::vector<SampledField> fields = {};  ///< vector and tensor point arrays (vtu_writer.hpp), in either format
  Pieces pieces;  ///< a distributed run's pieces (vtk_file.hpp): each rank writes its own, rank 0 the .pvtu

  /// The settings a program's --vtu-format, --vtu-samples and --vtu-degree give.
  static VtuOutput of(const std::string& format, int samples, int degree) {
    VtuOutput out;
    out.format = format;
    out.samples = samples;
    out.degree = degree;
    return out;
  }
  /// Points per direction of an element's output (for memory forecasts): the samples, or a Bézier cell's degree + 1.
  int points_per_direction() const { return format == "linear" ? samples : degree + 1; }

  /// The effective settings for a JSON report ({"format", "samples"} or {"format", "degree"}; "fields": their names).
  nlohmann::json settings() const;
};

/// Writes u (nullptr: the geometry alone, no "u") and output.fields to path in the chosen format; Bézier output also writes
/// outline_path(path). Returns the files written (a distributed output: the .pvtu summaries, pieces beside them).
/// InputError for an unknown format.
std::vector<std::string> write_output(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd* u,
                                      const VtuOutput& output, const ElementData& element_data = {});

/// Names of the formats, for --vtu-format's check.
std::vector<std::string> vtu_formats();

}  // namespace iga::io
