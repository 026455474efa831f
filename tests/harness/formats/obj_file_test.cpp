// read_obj_file: FCL's test meshes load with the counts, faces and exactly rounded coordinates
// their text gives; headers are skipped and quads triangulated; every bad file is refused with a
// MeshFileError that names the file (and the line, when one is to blame).
#include "harness/formats/obj_file.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "temp_folder.h"

namespace cc::harness {
namespace {

const std::filesystem::path kData = CROSSCHECK_TEST_DATA;
const std::filesystem::path kMeshes = kData / ".." / ".." / "corpora" / "meshes";
const std::filesystem::path kBadMeshes = kData / "bad_meshes";

// The whitespace-separated words of each line of a file (CRLF or LF).
std::vector<std::vector<std::string>> words_of_lines(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  std::vector<std::vector<std::string>> lines;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string word; words >> word;) w.push_back(word);
    lines.push_back(w);
  }
  return lines;
}

std::vector<std::vector<std::string>> lines_starting(const std::filesystem::path& path, const std::string& keyword) {
  std::vector<std::vector<std::string>> out;
  for (auto& words : words_of_lines(path)) {
    if (!words.empty() && words[0] == keyword) out.push_back(words);
  }
  return out;
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// A file in a fresh folder of its own (named for the test and the file), removed with it.
class TempObj {
 public:
  TempObj(const std::string& name, const std::string& text)
      : folder_("crosscheck_obj_file_test_" + name), path_(folder_.write(name, text)) {}
  const std::filesystem::path& path() const { return path_; }

 private:
  test::TempFolder folder_;
  std::filesystem::path path_;
};

// The message of the MeshFileError that reading `path` throws ("" if none is thrown).
std::string error_reading(const std::filesystem::path& path) {
  try {
    read_obj_file(path);
  } catch (const MeshFileError& e) {
    return e.what();
  }
  return "";
}

// The message starts with the file's path and names the line: "FILE:LINE: ..." (or tinyobjloader's
// "FILE: ... (line LINE.)").
void expect_names_file_and_line(const std::string& message, const std::filesystem::path& path, int line) {
  const std::string file = path.string();
  ASSERT_EQ(message.substr(0, file.size()), file) << message;
  const std::string rest = message.substr(file.size());
  const std::string n = std::to_string(line);
  EXPECT_TRUE(rest.starts_with(":" + n + ": ") || rest.find("line " + n + ".") != std::string::npos)
      << message << "\n(expected line " << n << ")";
}

// The message starts with "FILE: " (no line is to blame).
void expect_names_file(const std::string& message, const std::filesystem::path& path) {
  EXPECT_TRUE(message.starts_with(path.string() + ": ")) << message;
}

TEST(ObjFile, LoadsFclsEnvironmentMeshWithItsCounts) {
  const Mesh mesh = read_obj_file(kMeshes / "env.obj");
  EXPECT_EQ(mesh.vertices.size(), 6540u);
  EXPECT_EQ(mesh.faces.size(), 2180u);
  EXPECT_EQ(mesh.vertices.size(), lines_starting(kMeshes / "env.obj", "v").size());
  EXPECT_EQ(mesh.faces.size(), lines_starting(kMeshes / "env.obj", "f").size());
  EXPECT_EQ(mesh_problem(mesh), std::nullopt);
}

TEST(ObjFile, LoadsFclsRobotMeshWithItsCounts) {
  const Mesh mesh = read_obj_file(kMeshes / "rob.obj");
  EXPECT_EQ(mesh.vertices.size(), 648u);
  EXPECT_EQ(mesh.faces.size(), 216u);
  EXPECT_EQ(mesh.vertices.size(), lines_starting(kMeshes / "rob.obj", "v").size());
  EXPECT_EQ(mesh.faces.size(), lines_starting(kMeshes / "rob.obj", "f").size());
  EXPECT_EQ(mesh_problem(mesh), std::nullopt);
}

TEST(ObjFile, EveryCoordinateIsStrtodOfItsTextBitForBit) {
  for (const char* name : {"env.obj", "rob.obj"}) {
    const Mesh mesh = read_obj_file(kMeshes / name);
    const auto v_lines = lines_starting(kMeshes / name, "v");
    ASSERT_EQ(mesh.vertices.size(), v_lines.size()) << name;
    int differ = 0;
    for (std::size_t i = 0; i < v_lines.size(); ++i) {
      ASSERT_GE(v_lines[i].size(), 4u) << name << " vertex " << i;
      for (int k = 0; k < 3; ++k) {
        const double expected = std::strtod(v_lines[i][k + 1].c_str(), nullptr);
        if (bits(mesh.vertices[i][k]) != bits(expected) && ++differ <= 5) {
          ADD_FAILURE() << name << " vertex " << i << " coordinate " << k << ": text " << v_lines[i][k + 1];
        }
      }
    }
    EXPECT_EQ(differ, 0) << name;
  }
}

TEST(ObjFile, FacesAreTheFileFaceLinesFromZero) {
  const Mesh mesh = read_obj_file(kMeshes / "rob.obj");
  const auto f_lines = lines_starting(kMeshes / "rob.obj", "f");
  ASSERT_EQ(mesh.faces.size(), f_lines.size());
  for (std::size_t i = 0; i < f_lines.size(); ++i) {
    ASSERT_EQ(f_lines[i].size(), 4u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(mesh.faces[i][k] + 1, std::stoul(f_lines[i][k + 1])) << "face " << i;
    }
  }
}

TEST(ObjFile, AByteOrderMarkIsNoPartOfTheFirstVertex) {
  const std::string body = "v 0.5 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const Mesh marked = read_obj_text("\xEF\xBB\xBF" + body, "marked.obj");
  EXPECT_EQ(marked, read_obj_text(body, "plain.obj"));
  EXPECT_EQ(marked.vertices.front(), (Vec3{0.5, 0, 0}));
}

TEST(ObjFile, ADeviceIsRefusedAtOnce) {
  EXPECT_THROW(read_obj_file("/dev/zero"), MeshFileError);
}

TEST(ObjFile, SkipsFclsHeaderLine) {
  // FCL's files begin with "<vertices> <faces>", which is not OBJ.
  const auto first = words_of_lines(kMeshes / "env.obj").front();
  ASSERT_EQ(first, (std::vector<std::string>{"6540", "2180"}));
  const std::string body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const TempObj with("with_header.obj", "3 1\r\n" + body);
  const TempObj without("without_header.obj", body);
  const Mesh mesh = read_obj_file(with.path());
  EXPECT_EQ(mesh, read_obj_file(without.path()));
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.faces.size(), 1u);
}

TEST(ObjFile, KeepsNegativeZeroSubnormalsAndSigns) {
  const TempObj obj("signs.obj", "v -0 5e-324 +2.5\nv 1e308 -1e-310 0.1\nv 0 1 0\nf 1 2 3\n");
  const Mesh mesh = read_obj_file(obj.path());
  ASSERT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(bits(mesh.vertices[0].x), bits(-0.0));
  EXPECT_EQ(bits(mesh.vertices[0].y), bits(std::strtod("5e-324", nullptr)));
  EXPECT_EQ(mesh.vertices[0].z, 2.5);
  EXPECT_EQ(mesh.vertices[1].x, 1e308);
  EXPECT_EQ(bits(mesh.vertices[1].y), bits(std::strtod("-1e-310", nullptr)));
  EXPECT_EQ(mesh.vertices[1].z, 0.1);
}

TEST(ObjFile, TriangulatesAQuadIntoTwoTriangles) {
  const TempObj obj("quad.obj", "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const Mesh mesh = read_obj_file(obj.path());
  ASSERT_EQ(mesh.vertices.size(), 4u);
  ASSERT_EQ(mesh.faces.size(), 2u);
  // Two triangles of the quad's corners that share a diagonal and together use all four corners.
  std::set<std::uint32_t> a(mesh.faces[0].begin(), mesh.faces[0].end());
  std::set<std::uint32_t> b(mesh.faces[1].begin(), mesh.faces[1].end());
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  std::set<std::uint32_t> both = a;
  both.insert(b.begin(), b.end());
  EXPECT_EQ(both, (std::set<std::uint32_t>{0, 1, 2, 3}));
  std::vector<std::uint32_t> shared;
  for (std::uint32_t v : a) {
    if (b.contains(v)) shared.push_back(v);
  }
  ASSERT_EQ(shared.size(), 2u);
  EXPECT_EQ(shared[1] - shared[0], 2u);  // a diagonal (0-2 or 1-3), not a side
}

TEST(ObjFile, RefusesAFaceNamingAMissingVertex) {
  const auto path = kBadMeshes / "missing_vertex.obj";
  const std::string message = error_reading(path);
  ASSERT_FALSE(message.empty());
  expect_names_file_and_line(message, path, 5);
}

TEST(ObjFile, RefusesANanCoordinate) {
  const auto path = kBadMeshes / "nan_coordinate.obj";
  const std::string message = error_reading(path);
  ASSERT_FALSE(message.empty());
  expect_names_file_and_line(message, path, 3);
}

TEST(ObjFile, RefusesAnInfiniteCoordinate) {
  const auto path = kBadMeshes / "inf_coordinate.obj";
  const std::string message = error_reading(path);
  ASSERT_FALSE(message.empty());
  expect_names_file_and_line(message, path, 4);
}

TEST(ObjFile, RefusesAVertexWithTwoCoordinates) {
  const auto path = kBadMeshes / "two_coordinates.obj";
  const std::string message = error_reading(path);
  ASSERT_FALSE(message.empty());
  expect_names_file_and_line(message, path, 3);
}

TEST(ObjFile, RefusesAnEmptyFile) {
  const auto path = kBadMeshes / "empty.obj";
  ASSERT_TRUE(std::filesystem::exists(path));
  expect_names_file(error_reading(path), path);
}

TEST(ObjFile, RefusesVerticesWithoutFaces) {
  const auto path = kBadMeshes / "no_faces.obj";
  expect_names_file(error_reading(path), path);
}

TEST(ObjFile, RefusesAFolderSayingItIsOne) {
  const std::string message = error_reading(kBadMeshes);
  expect_names_file(message, kBadMeshes);
  EXPECT_NE(message.find("a folder, not a mesh file"), std::string::npos) << message;
}

TEST(ObjFile, ReadsTextAsItReadsTheFile) {
  const Mesh mesh = read_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "inline.obj");
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.faces.size(), 1u);
}

TEST(ObjFile, RefusesAMissingFile) {
  const auto path = kBadMeshes / "no_such_file.obj";
  ASSERT_FALSE(std::filesystem::exists(path));
  expect_names_file(error_reading(path), path);
}

}  // namespace
}  // namespace cc::harness
