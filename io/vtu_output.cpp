#include "io/vtu_output.hpp"

#include "core/error.hpp"
#include "io/bezier_writer.hpp"

namespace iga::io {

nlohmann::json VtuOutput::settings() const {
  nlohmann::json out = format == "linear" ? nlohmann::json{{"format", format}, {"samples", samples}}
                                          : nlohmann::json{{"format", format}, {"degree", degree}};
  if (!fields.empty()) {
    out["fields"] = nlohmann::json::array();
    for (const SampledField& f : fields) out["fields"].push_back(f.name);
  }
  return out;
}

std::vector<std::string> vtu_formats() { return {"bezier", "linear"}; }

std::vector<std::string> write_output(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd* u,
                                      const VtuOutput& output, const ElementData& element_data) {
  if (output.format == "bezier") {
    BezierOptions bo;
    bo.degree = output.degree;
    bo.exact = output.exact;
    bo.fields = output.fields;
    write_bezier(path, geometry, u, bo, element_data, output.pieces);
    if (output.pieces.ranks > 1) return {summary_path(path), summary_path(outline_path(path))};
    return {path, outline_path(path)};
  }
  if (output.format != "linear") throw InputError("--vtu-format: '" + output.format + "' is not bezier or linear");
  VtuOptions vo;
  vo.samples = output.samples;
  vo.exact = output.exact;
  vo.fields = output.fields;
  if (u != nullptr) {
    write_vtu(path, geometry, *u, vo, element_data, output.pieces);
  } else {
    write_vtu(path, geometry, vo, element_data, output.pieces);
  }
  if (output.pieces.ranks > 1) return {summary_path(path)};
  return {path};
}

}  // namespace iga::io
