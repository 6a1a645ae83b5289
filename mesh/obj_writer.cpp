#include "mesh/obj_writer.hpp"

#include <array>
#include <charconv>
#include <fstream>
#include <system_error>

namespace iga::mesh {

namespace {

// Appends the shortest decimal text that round-trips to exactly `value`.
void append_number(std::string& buffer, double value) {
  std::array<char, 64> text{};
  const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc{}) {
    throw InputError("cannot format coordinate for OBJ output");
  }
  buffer.append(text.data(), end);
}

void append_index(std::string& buffer, Index value) {
  std::array<char, 24> text{};
  const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
  (void)ec;  // 24 characters always hold a 64-bit integer
  buffer.append(text.data(), end);
}

}  // namespace

void write_obj(const PolyMesh& mesh, std::ostream& out) {
  constexpr std::size_t kFlushSize = 1 << 16;
  std::string buffer = "# iga PolyMesh: " + std::to_string(mesh.num_vertices()) + " vertices, " +
                       std::to_string(mesh.num_faces()) + " faces\n";
  auto flush = [&](bool force) {
    if (force || buffer.size() >= kFlushSize) {
      out.write(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      buffer.clear();
    }
  };
  for (const Eigen::Vector3d& p : mesh.points()) {
    buffer += 'v';
    for (int k = 0; k < 3; ++k) {
      buffer += ' ';
      append_number(buffer, p[k]);
    }
    buffer += '\n';
    flush(false);
  }
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    buffer += 'f';
    for (const Index v : mesh.face(f)) {
      buffer += ' ';
      append_index(buffer, v + 1);
    }
    buffer += '\n';
    flush(false);
  }
  flush(true);
  out.flush();
  if (!out) {
    throw InputError("cannot write OBJ output: the stream failed");
  }
}

void write_obj(const PolyMesh& mesh, const std::string& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out.is_open()) {
    throw InputError(path, 0, "cannot write file");
  }
  try {
    write_obj(mesh, out);
  } catch (const InputError&) {
    throw InputError(path, 0, "cannot write file");
  }
  out.close();
  if (!out) {
    throw InputError(path, 0, "cannot write file");
  }
}

}  // namespace iga::mesh
