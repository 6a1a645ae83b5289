// libFuzzer target: the OBJ reader (mesh::parse_obj, which builds the PolyMesh) on arbitrary bytes. Refusing
// input with an iga::Error of one line is fine; a crash, a sanitizer report, any other exception or a hang is
// a finding. A mesh that parses is walked (faces, half-edges, boundary loops) to exercise its adjacency.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "mesh/obj_reader.hpp"
#include "tests/fuzz/fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const iga::mesh::PolyMesh mesh = iga::mesh::parse_obj(in, "fuzz.obj");
    iga::Index corners = 0;
    for (iga::Index f = 0; f < mesh.num_faces(); ++f) corners += mesh.face_size(f);
    if (corners != mesh.num_half_edges()) std::abort();  // one half-edge per face corner
    for (iga::Index h = 0; h < mesh.num_half_edges(); ++h) {
      const iga::Index twin = mesh.half_edge(h).twin;
      if (twin >= 0 && mesh.half_edge(twin).twin != h) std::abort();
    }
    (void)mesh.boundary_loops();
  } catch (const iga::Error& e) {
    iga::fuzz::check_one_line(e);
  }
  return 0;
}
