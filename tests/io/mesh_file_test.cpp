// SPDX-License-Identifier: MIT
// Mesh files: the strict OFF reader (counts, variants, every malformed case with its exact
// message), the assimp formats (OBJ, STL ascii/binary, PLY, DAE) and the mesh cache.
#include "core/io/mesh_file.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <utility>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/io/load_context.h"
#include "tests/common/test_support.h"

namespace lamina::core {
namespace {

using test::DataPath;
using test::WorldsPath;
using test::WriteScratchFile;
using ::testing::ElementsAre;
using ::testing::StartsWith;

// Coordinates in the fixtures are small decimals; float storage in assimp limits agreement
// to about 1e-7 relative, so bounds are compared with this absolute tolerance (metres).
constexpr double kFloatTolerance = 1e-6;

std::optional<TriangleMesh> Read(const std::string& path, Diagnostics* diagnostics) {
  return ReadMeshFile(path, SourceLocation{"/refs/world.xml", 7}, *diagnostics);
}

void ExpectBounds(const TriangleMesh& mesh, const Vec3& low, const Vec3& high) {
  const Eigen::AlignedBox3d box = mesh.Bounds();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(box.min()[i], low[i], kFloatTolerance) << "axis " << i;
    EXPECT_NEAR(box.max()[i], high[i], kFloatTolerance) << "axis " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// OFF

TEST(OffFile, FractalTerrainHasAllTriangles) {
  Diagnostics diagnostics;
  const auto mesh = Read(WorldsPath("klampt/terrains/fractal_terrain_1.off"), &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(diagnostics.entries().size(), 0u) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->vertex_count(), 16641);
  EXPECT_EQ(mesh->triangle_count(), 32768);
}

TEST(OffFile, CubeIsClosedUnitCube) {
  Diagnostics diagnostics;
  const auto mesh = Read(WorldsPath("klampt/objects/cube.off"), &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->vertex_count(), 8);
  EXPECT_EQ(mesh->triangle_count(), 12);
  EXPECT_TRUE(test::IsClosedAndConsistent(*mesh));
  ExpectBounds(*mesh, Vec3::Zero(), Vec3::Ones());
  // first face line "3 0 1 3" kept verbatim
  EXPECT_EQ(mesh->triangles[0], Eigen::Vector3i(0, 1, 3));
}

TEST(OffFile, VariantsCommentsAndPolygons) {
  // COFF with counts on the header line, colours after the coordinates and after a face,
  // comments, a quad and a pentagon (fan-triangulated from their first vertex)
  const std::string text =
      "COFF 5 2 0  # counts on the header line\n"
      "0 0 0  1 0 0 1\n"
      "1 0 0  1 0 0 1\n"
      "1 1 0  1 0 0 1\n"
      "0 1 0  1 0 0 1\n"
      "0.5 1.5 0  1 0 0 1\n"
      "# a quad and a pentagon\n"
      "4 0 1 2 3  0.5 0.5 0.5\n"
      "5 0 1 2 4 3\n";
  Diagnostics diagnostics;
  const auto mesh = ParseOff(text, "/x/variants.off", diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(diagnostics.entries().size(), 0u);
  EXPECT_EQ(mesh->vertex_count(), 5);
  EXPECT_THAT(mesh->triangles, ElementsAre(Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 3),
                                           Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(0, 2, 4),
                                           Eigen::Vector3i(0, 4, 3)));
  EXPECT_EQ(mesh->vertices[4], Vec3(0.5, 1.5, 0.0));
}

TEST(OffFile, NoffHeaderAndNoEdgeCount) {
  Diagnostics diagnostics;
  const auto mesh = ParseOff("NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n",
                             "/x/n.off", diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->triangle_count(), 1);
}

TEST(OffFile, ExtraLinesAfterLastFaceWarn) {
  Diagnostics diagnostics;
  const auto mesh =
      ParseOff("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n", "/x/extra.off", diagnostics);
  ASSERT_TRUE(mesh.has_value());
  EXPECT_EQ(mesh->triangle_count(), 1);
  EXPECT_THAT(diagnostics.Messages(Severity::kWarning),
              ElementsAre("/x/extra.off:7: warning: ignoring 1 extra line(s) after the last face"));
}

// Malformed OFF files: one exact message each, located at the offending line.
struct BadOff {
  const char* file;
  std::vector<std::string> errors;  // "line: message"
};

class MalformedOff : public ::testing::TestWithParam<BadOff> {};

TEST_P(MalformedOff, ReportsExactErrors) {
  const std::string path = DataPath(std::string("bad/") + GetParam().file);
  Diagnostics diagnostics;
  EXPECT_FALSE(Read(path, &diagnostics).has_value());
  std::vector<std::string> expected;
  for (const std::string& error : GetParam().errors) {
    const size_t colon = error.find(": ");
    expected.push_back(path + ":" + error.substr(0, colon) + ": error: " + error.substr(colon + 2));
  }
  EXPECT_EQ(diagnostics.Messages(Severity::kError), expected);
}

INSTANTIATE_TEST_SUITE_P(
    Files, MalformedOff,
    ::testing::Values(
        BadOff{"truncated_vertices.off",
               {"4: unexpected end of file: expected 4 vertices, read 2"}},
        BadOff{"truncated_faces.off", {"9: unexpected end of file: expected 4 faces, read 2"}},
        BadOff{"bad_count.off", {"2: vertex count must be a non-negative integer, got '-3'"}},
        BadOff{"bad_header.off", {"1: expected 'OFF' header, got 'OFX'"}},
        BadOff{"index_out_of_range.off",
               {"6: vertex index 3 is out of range (the file has 3 vertices)"}},
        BadOff{"nan_coordinate.off", {"4: 'nan' is not a number"}},
        BadOff{"short_face.off", {"6: face with 2 vertices, expected at least 3"}},
        BadOff{"multiple_errors.off",
               {"4: 'x' is not a number", "5: vertex 2 expects 3 coordinates, got 2",
                "6: vertex coordinate must be finite, got 'inf'",
                "8: vertex index -1 is out of range (the file has 4 vertices)",
                "9: 'q' is not a vertex index"}}),
    [](const ::testing::TestParamInfo<BadOff>& param_info) {
      std::string name = param_info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(OffFile, MoreMalformedTextCases) {
  const std::map<std::string, std::string> cases = {
      {"", "/x/t.off:1: error: missing 'OFF' header (the file is empty)"},
      {"# only a comment\n", "/x/t.off:1: error: missing 'OFF' header (the file is empty)"},
      {"OFF\n",
       "/x/t.off:1: error: unexpected end of file: expected the vertex, face and edge counts"},
      {"OFF\n3\n", "/x/t.off:2: error: expected vertex, face and edge counts, got 1 value(s)"},
      {"OFF\n0 two 0\n", "/x/t.off:2: error: face count must be a non-negative integer, got 'two'"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n",
       "/x/t.off:6: error: face expects 4 vertex indices, got 3"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\nthree 0 1 2\n",
       "/x/t.off:6: error: 'three' is not a face vertex count"},
  };
  for (const auto& [text, message] : cases) {
    Diagnostics diagnostics;
    EXPECT_FALSE(ParseOff(text, "/x/t.off", diagnostics).has_value()) << text;
    EXPECT_THAT(diagnostics.Messages(Severity::kError), ElementsAre(message)) << text;
  }
}

TEST(MeshFile, MissingFileIsReportedAtTheReference) {
  Diagnostics diagnostics;
  EXPECT_FALSE(Read("/nonexistent/dir/x.off", &diagnostics).has_value());
  EXPECT_THAT(
      diagnostics.Messages(Severity::kError),
      ElementsAre("/refs/world.xml:7: error: cannot open mesh file '/nonexistent/dir/x.off'"));
}

TEST(MeshFile, MissingFileWithoutReferenceNamesTheFile) {
  Diagnostics diagnostics;
  EXPECT_FALSE(ReadMeshFile("/nonexistent/y.stl", SourceLocation{}, diagnostics).has_value());
  EXPECT_THAT(diagnostics.Messages(Severity::kError),
              ElementsAre("/nonexistent/y.stl: error: cannot open mesh file '/nonexistent/y.stl'"));
}

// ---------------------------------------------------------------------------------------------
// assimp formats

TEST(AssimpMesh, WavefrontObjQuadBecomesTwoTrianglesAndLinesAreDropped) {
  Diagnostics diagnostics;
  const auto mesh = Read(DataPath("meshes/pyramid_quad.obj"), &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(diagnostics.error_count(), 0);
  EXPECT_EQ(mesh->triangle_count(), 6);  // quad -> 2, plus 4 sides; the 'l' element dropped
  ExpectBounds(*mesh, Vec3(0, 0, 0), Vec3(1, 1, 2));
}

TEST(AssimpMesh, AsciiStl) {
  Diagnostics diagnostics;
  const auto mesh = Read(DataPath("meshes/tetra_ascii.stl"), &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->triangle_count(), 4);
  EXPECT_EQ(mesh->vertex_count(), 4);  // JoinIdenticalVertices merges the STL's corners
  EXPECT_TRUE(test::IsClosedAndConsistent(*mesh));
  ExpectBounds(*mesh, Vec3(0, 0, 0), Vec3(1, 2, 3));
}

TEST(AssimpMesh, BinaryStlTriangleCountMatchesHeader) {
  const std::string path = WorldsPath("klampt/robots/mirobot/Link1.STL");
  std::ifstream in(path, std::ios::binary);
  char header[84] = {};
  ASSERT_TRUE(in.read(header, sizeof(header)));
  std::uint32_t count = 0;
  std::memcpy(&count, header + 80, sizeof(count));  // little-endian, as on the test hosts
  ASSERT_GT(count, 1000u);
  Diagnostics diagnostics;
  const auto mesh = Read(path, &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->triangle_count(), static_cast<int>(count));
}

TEST(AssimpMesh, PlyQuadsAreTriangulated) {
  Diagnostics diagnostics;
  const auto mesh = Read(DataPath("meshes/cube_quads.ply"), &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->triangle_count(), 12);
  EXPECT_TRUE(test::IsClosedAndConsistent(*mesh));
  ExpectBounds(*mesh, Vec3(-1, -1, -1), Vec3(1, 1, 1));
}

TEST(AssimpMesh, ColladaKeepsZUpAppliesUnitAndNodeTransform) {
  // centimetres -> metres; the node's 5 cm z translation is baked in; Z_UP is kept as written
  Diagnostics diagnostics;
  const auto mesh = Read(DataPath("meshes/tetra_cm_zup.dae"), &diagnostics);
  ASSERT_TRUE(mesh.has_value()) << diagnostics.FormatAll();
  EXPECT_EQ(mesh->triangle_count(), 4);
  ExpectBounds(*mesh, Vec3(0, 0, 0.05), Vec3(0.1, 0.2, 0.35));
}

TEST(AssimpMesh, UnreadableFileReportsAssimpMessage) {
  const std::string path = DataPath("meshes/garbage.stl");
  Diagnostics diagnostics;
  EXPECT_FALSE(Read(path, &diagnostics).has_value());
  const auto errors = diagnostics.Messages(Severity::kError);
  ASSERT_EQ(errors.size(), 1u);
  // the rest of the line is assimp's own wording, which varies between versions
  EXPECT_THAT(errors[0], StartsWith(path + ": error: cannot read mesh: "));
  EXPECT_GT(errors[0].size(), (path + ": error: cannot read mesh: ").size());
}

TEST(AssimpMesh, FileWithoutTrianglesIsAnError) {
  const std::string path = DataPath("meshes/lines_only.obj");
  Diagnostics diagnostics;
  EXPECT_FALSE(Read(path, &diagnostics).has_value());
  EXPECT_THAT(diagnostics.Messages(Severity::kError),
              ElementsAre(path + ": error: mesh file has no triangles"));
}

TEST(MeshFile, MeshExtensions) {
  for (const char* extension : {"off", "obj", "stl", "dae", "ply"}) {
    EXPECT_TRUE(IsMeshExtension(extension)) << extension;
  }
  for (const char* extension : {"", "geom", "rob", "urdf", "xml", "STL"}) {
    EXPECT_FALSE(IsMeshExtension(extension)) << extension;
  }
}

// ---------------------------------------------------------------------------------------------
// MeshCache

TEST(MeshCache, SharesOneMeshPerPath) {
  MeshCache cache;
  Diagnostics diagnostics;
  const std::string path = WorldsPath("klampt/objects/cube.off");
  const auto first = cache.Get(path, SourceLocation{"/a.xml", 1}, diagnostics);
  const auto second = cache.Get(path, SourceLocation{"/b.xml", 2}, diagnostics);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first.get(), second.get());
  EXPECT_EQ(cache.size(), 1);
  EXPECT_EQ(first->triangle_count(), 12);
  EXPECT_EQ(diagnostics.entries().size(), 0u);
}

TEST(MeshCache, FailuresAreNotCached) {
  MeshCache cache;
  Diagnostics diagnostics;
  const std::string path = test::ScratchDir() + "/late.off";
  std::filesystem::remove(path);  // left over from an earlier run
  EXPECT_EQ(cache.Get(path, SourceLocation{"/a.xml", 3}, diagnostics), nullptr);
  EXPECT_THAT(diagnostics.Messages(Severity::kError),
              ElementsAre("/a.xml:3: error: cannot open mesh file '" + path + "'"));
  EXPECT_EQ(cache.size(), 0);
  WriteScratchFile("late.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const auto mesh = cache.Get(path, SourceLocation{"/a.xml", 3}, diagnostics);
  ASSERT_NE(mesh, nullptr);
  EXPECT_EQ(mesh->triangle_count(), 1);
  EXPECT_EQ(cache.size(), 1);
  EXPECT_EQ(diagnostics.error_count(), 1);  // only the first attempt failed
}

}  // namespace
}  // namespace lamina::core
