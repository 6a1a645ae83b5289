#include "mesh/obj_reader.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace iga::mesh {
namespace {

PolyMesh parse(const std::string& text) {
  std::istringstream in(text);
  return parse_obj(in, "test.obj");
}

// Parses `text` expecting an InputError whose message starts with "test.obj:LINE:" and contains `word`.
void expect_error(const std::string& text, long line, const std::string& word) {
  try {
    (void)parse(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    const std::string message = e.what();
    const std::string where = "test.obj:" + std::to_string(line) + ":";
    EXPECT_EQ(message.rfind(where, 0), 0U) << "expected '" << where << "' in: " << message;
    EXPECT_NE(message.find(word), std::string::npos) << "expected '" << word << "' in: " << message;
    EXPECT_EQ(e.file(), "test.obj");
    EXPECT_EQ(e.line(), line);
  }
}

const std::string kSquare =  // lines 1-4: a unit square's vertices
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

TEST(ObjReader, AllIndexFormsCommentsAndCrlf) {
  const std::string text =
      "# exported by a test\r\n"
      "mtllib scene.mtl\r\n"
      "o thing\r\n"
      "v 0 0 0\r\n"
      "v 1.0 0 0 1.0\r\n"
      "v\t1\t1e0\t0   \r\n"
      "v 0 +1 -0 # trailing comment\r\n"
      "vt 0 0\r\n"
      "vn 0 0 1\r\n"
      "\r\n"
      "   \t \r\n"
      "g group\r\n"
      "s off\r\n"
      "usemtl red\r\n"
      "f -4 -3/1 -2//1 -1/1/1\r\n"
      "v 2 0 0\r\n"
      "v 2 1 0\r\n"
      "f 2//1 5//1 6//1\r\n"
      "f -5/1/1 -1/1/1 -4/1/1\r\n"
      "l 1 2\r\n"
      "p 3\r\n"
      "#f 1 2 3 is commented out\r\n";
  const PolyMesh mesh = parse(text);
  ASSERT_EQ(mesh.num_vertices(), 6);
  ASSERT_EQ(mesh.num_faces(), 3);
  EXPECT_EQ(mesh.point(2), Eigen::Vector3d(1.0, 1.0, 0.0));
  EXPECT_EQ(mesh.point(3), Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_EQ(mesh.point(5), Eigen::Vector3d(2.0, 1.0, 0.0));
  const std::vector<std::vector<Index>> expected = {{0, 1, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  for (Index f = 0; f < 3; ++f) {
    const auto face = mesh.face(f);
    EXPECT_EQ(std::vector<Index>(face.begin(), face.end()), expected[static_cast<std::size_t>(f)]);
  }
  EXPECT_TRUE(mesh.is_planar());
  EXPECT_EQ(mesh.boundary_loops().size(), 1U);
}

TEST(ObjReader, LastLineWithoutNewlineAndUnusedVertices) {
  const PolyMesh mesh = parse(kSquare + "v 5 5 5\nf 1 2 3 4");
  EXPECT_EQ(mesh.num_vertices(), 5);
  EXPECT_EQ(mesh.num_faces(), 1);
  EXPECT_EQ(mesh.valence(4), 0);
}

TEST(ObjReader, RejectsIndexZero) { expect_error(kSquare + "f 0 1 2\n", 5, "index 0"); }

TEST(ObjReader, RejectsIndexOutOfRange) {
  expect_error(kSquare + "# four vertices so far\nf 1 2 9\n", 6, "vertex index 9 out of range (4 vertices defined)");
}

TEST(ObjReader, RejectsIndexDefinedOnlyLater) { expect_error(kSquare + "f 1 2 5\nv 1 2 3\n", 5, "out of range"); }

TEST(ObjReader, RejectsNegativeIndexBeforeFirstVertex) {
  expect_error(kSquare + "f -1 -2 -5\n", 5, "vertex index -5 out of range");
}

TEST(ObjReader, RejectsFaceWithTwoVertices) {
  expect_error(kSquare + "f 1 2 3\n\nf 3 4\n", 7, "face has 2 vertices; a face needs at least 3");
}

TEST(ObjReader, RejectsEmptyFace) { expect_error(kSquare + "f   # nothing\n", 5, "face has 0 vertices"); }

TEST(ObjReader, RejectsRepeatedVertex) {
  expect_error(kSquare + "f 1 2 3 -3\n", 5, "vertex 2 appears more than once");
}

TEST(ObjReader, RejectsMalformedCoordinate) { expect_error("v 0 0 0\nv 1 abc 2\n", 2, "malformed number 'abc'"); }

TEST(ObjReader, RejectsTrailingGarbageInCoordinate) { expect_error("v 0 0 0\nv 1 2 3x\n", 2, "malformed"); }

TEST(ObjReader, RejectsMalformedExtraCoordinate) { expect_error("v 0 0 0 w\n", 1, "malformed"); }

TEST(ObjReader, RejectsMalformedFaceIndex) { expect_error(kSquare + "f 1 2 x\n", 5, "malformed face vertex 'x'"); }

TEST(ObjReader, RejectsMalformedFaceIndexForms) {
  expect_error(kSquare + "f 1 2 3.5\n", 5, "malformed");
  expect_error(kSquare + "f 1 2/ 3\n", 5, "malformed");
  expect_error(kSquare + "f 1 2// 3\n", 5, "malformed");
  expect_error(kSquare + "f 1 /2 3\n", 5, "malformed");
  expect_error(kSquare + "f 1 2/a/3 3\n", 5, "malformed");
  expect_error(kSquare + "f 1 2/1/1/1 3\n", 5, "malformed");
}

TEST(ObjReader, RejectsTooFewCoordinates) { expect_error("v 0 0 0\nv 1 2\n", 2, "vertex has 2 coordinates"); }

TEST(ObjReader, RejectsNonFiniteCoordinates) {
  expect_error("v 0 0 0\nv nan 0 0\n", 2, "non-finite");
  expect_error("v 0 0 0\nv 1 1 0\nv 0 inf 0\n", 3, "non-finite");
  expect_error("v 0 0 -infinity\n", 1, "non-finite");
}

TEST(ObjReader, RejectsOutOfRangeNumber) { expect_error("v 0 0 1e999\n", 1, "out of range"); }

TEST(ObjReader, RejectsNonManifoldEdge) {
  const std::string text = kSquare +
                           "v 0 -1 0\n"        // 5
                           "f 1 2 3\n"         // 6
                           "# comment\n"       // 7
                           "f 2 1 5\n"         // 8
                           "\n"                // 9
                           "f 1 2 4\n";        // 10
  expect_error(text, 10, "edge (1,2) is shared by more than two faces");
}

TEST(ObjReader, RejectsInconsistentOrientation) {
  const std::string text = kSquare +
                           "v 0 2 0\n"   // 5
                           "f 1 2 3\n"   // 6
                           "g other\n"   // 7
                           "f 1 3 4\n"   // 8
                           "f 3 4 5\n";  // 9: traverses 3 -> 4 like the face at line 8
  expect_error(text, 9, "face orientation inconsistent with a neighbouring face across edge (3,4)");
}

TEST(ObjReader, RejectsNonManifoldVertex) {
  const std::string text =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\n"  // 1-5
      "f 1 2 3\n"                                          // 6
      "f 1 4 5\n";                                         // 7
  expect_error(text, 7, "vertex 1 is non-manifold");
}

TEST(ObjReader, RejectsEmptyInput) {
  expect_error("", 0, "file is empty");
  expect_error("# only a comment\n\n", 0, "no vertices");
}

TEST(ObjReader, RejectsFileWithoutFaces) { expect_error(kSquare + "l 1 2\n", 0, "no faces"); }

TEST(ObjReader, ReadObjMissingFile) {
  const std::string path = testing::TempDir() + "iga_mesh_definitely_missing.obj";
  try {
    (void)read_obj(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":0: cannot open file");
  }
}

TEST(ObjReader, ReadObjDirectory) {
  // Issue 14: a directory opens as a stream on Linux and read as an empty file; it is named as a directory.
  const std::string path = testing::TempDir();
  try {
    (void)read_obj(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":0: cannot read (is a directory)");
  }
}

TEST(ObjReader, ReadObjFiles) {
  const std::string path = testing::TempDir() + "iga_mesh_reader_square.obj";
  {
    std::ofstream out(path, std::ios::binary);
    out << kSquare << "f 1 2 3 4\r\n";
  }
  const PolyMesh mesh = read_obj(path);
  EXPECT_EQ(mesh.num_faces(), 1);
  EXPECT_EQ(mesh.num_vertices(), 4);

  const std::string empty = testing::TempDir() + "iga_mesh_reader_empty.obj";
  { std::ofstream out(empty, std::ios::binary); }
  try {
    (void)read_obj(empty);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), empty + ":0: file is empty");
  }
  std::remove(path.c_str());
  std::remove(empty.c_str());
}

// Issue 14, text encodings: a byte-order mark, CRLF and CR-only line ends are read as an editor shows them;
// binary data is refused with its line and column.
TEST(ObjReader, Utf8ByteOrderMarkIsDropped) {
  // Before the fix the BOM made line 1 an unknown statement: vertex 1 was silently lost.
  const PolyMesh mesh = parse("\xEF\xBB\xBF" + kSquare + "f 1 2 3 4\n");
  EXPECT_EQ(mesh.num_vertices(), 4);
  EXPECT_EQ(mesh.point(0), Eigen::Vector3d(0.0, 0.0, 0.0));
  expect_error("\xEF\xBB\xBFv 0 0 0\nf 1 2 3\n", 2, "vertex index 2 out of range (1 vertices defined)");
}

TEST(ObjReader, CrOnlyLineEndsAreLines) {
  // Before the fix a CR-only file was one line (a comment here: "no vertices").
  const std::string text = "# old Mac file\rv 0 0 0\rv 1 0 0\rv 1 1 0\rv 0 1 0\rf 1 2 3 4\r";
  const PolyMesh mesh = parse(text);
  EXPECT_EQ(mesh.num_vertices(), 4);
  EXPECT_EQ(mesh.num_faces(), 1);
  expect_error("v 0 0 0\rv 1 0 0\r\rv 1 x 0\r", 4, "malformed number 'x'");
}

TEST(ObjReader, MixedLineEndsCountLikeAnEditor) {
  // \n, \r\n and a lone \r are one line end each; "\r\n" is never two.
  expect_error("v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\r\n\rf 1 2 9\r\n", 6, "vertex index 9 out of range");
  const PolyMesh mesh = parse("v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf 1 2 3");
  EXPECT_EQ(mesh.num_faces(), 1);
}

TEST(ObjReader, BinaryDataIsRefusedWithLineAndColumn) {
  expect_error(kSquare + std::string("f 1 2\0 3 4\n", 11), 5, "binary data (byte 0x00 at column 6)");
  expect_error(kSquare + "# a comment \x01\n", 5, "binary data (byte 0x01 at column 13)");
  expect_error("v 0 0 0\nv 1 \x7F 0\n", 2, "binary data (byte 0x7F at column 5)");
  // Columns count characters: "é" is two bytes, one column.
  expect_error("# caf\xC3\xA9 \x1B\n", 1, "binary data (byte 0x1B at column 8)");
  // Tab, vertical tab and form feed are blanks, not binary.
  const PolyMesh mesh = parse("v\t0 0 0\nv 1\v0 0\nv 1 1\f0\nf 1 2 3\n");
  EXPECT_EQ(mesh.num_faces(), 1);
}

TEST(ObjReader, Utf16IsNamed) {
  expect_error(std::string("\xFF\xFEv\0 \0", 6), 1, "UTF-16");
}

}  // namespace
}  // namespace iga::mesh
