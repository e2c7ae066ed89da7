// Gmsh MSH 4.1 reader: a small hexahedral mesh reads with its named boundary faces; every malformed
// or unusable file stops with one message naming the file, the line and what is allowed.
#include <gtest/gtest.h>


#include "helmholtz/mesh_import.hpp"
#include "io/gmsh_msh.hpp"
#include "support/error_messages.hpp"

namespace io = polymech::io;

namespace {

// Two unit hexahedra along x; physical surfaces "left" (x = 0) and "right" (x = 2).
const char* kMesh = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$PhysicalNames
3
2 1 "left"
2 2 "right"
3 3 "air"
$EndPhysicalNames
$Entities
0 0 2 1
1 0 0 0 0 1 1 1 1 0
2 2 0 0 2 1 1 1 2 0
1 0 0 0 2 1 1 1 3 0
$EndEntities
$Nodes
1 12 1 12
3 1 0 12
1
2
3
4
5
6
7
8
9
10
11
12
0 0 0
1 0 0
2 0 0
0 1 0
1 1 0
2 1 0
0 0 1
1 0 1
2 0 1
0 1 1
1 1 1
2 1 1
$EndNodes
$Elements
3 4 1 4
2 1 3 1
1 1 4 10 7
2 2 3 1
2 3 6 12 9
3 1 5 2
3 1 2 5 4 7 8 11 10
4 2 3 6 5 8 9 12 11
$EndElements
)";

// A hexahedral mesh with named boundary faces from a Gmsh file: the neutral reader, then the Helmholtz
// conversion (which checks inversion and matches the boundary facets to exterior faces).
polymech::helmholtz::HexMesh read_hex_mesh(const std::filesystem::path& file) {
  return polymech::helmholtz::hex_mesh_from(io::read_gmsh_mesh(file));
}

// The reader or the conversion refuses `text` (as mesh.msh) naming "mesh.msh:<line>:" and every fragment.
void expect_error(const std::string& text, int line, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const std::filesystem::path& p) { read_hex_mesh(p); }, line, fragments,
                                       "mesh.msh");
}

}  // namespace

TEST(GmshMsh, ReadsHexahedraAndNamedBoundaryFaces) {
  polymech::testing::TempDir dir;
  const auto m = read_hex_mesh(dir.write("mesh.msh", kMesh));
  EXPECT_EQ(m.vertex_count(), 12);
  EXPECT_EQ(m.element_count(), 2);
  ASSERT_EQ(m.boundary_names.size(), 2u);
  EXPECT_EQ(m.boundary_names[0], "left");
  EXPECT_EQ(m.boundary_names[1], "right");
  ASSERT_EQ(m.boundary_faces.size(), 2u);
  EXPECT_EQ(m.boundary_faces[0].element, 0);
  EXPECT_EQ(m.boundary_faces[0].face, 0);  // xi = -1 of the first hexahedron
  EXPECT_EQ(m.boundary_faces[1].element, 1);
  EXPECT_EQ(m.boundary_faces[1].face, 1);  // xi = +1 of the second
  EXPECT_NE(m.describe_element(1).find("mesh.msh:"), std::string::npos) << m.describe_element(1);
  EXPECT_EQ(polymech::helmholtz::exterior_faces(m).size(), 10u);
}

TEST(GmshMsh, MissingFile) {
  try {
    read_hex_mesh("/nonexistent/mesh.msh");
    FAIL() << "no error";
  } catch (const io::MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/mesh.msh: mesh file not found"), std::string::npos) << e.what();
  }
}

TEST(GmshMsh, OtherVersionsAndBinaryAreRefused) {
  expect_error(polymech::testing::replace_once(kMesh, "4.1 0 8", "2.2 0 8"), 2, {"MSH version 2.2 is not supported", "allowed: 4.1"});
  expect_error(polymech::testing::replace_once(kMesh, "4.1 0 8", "4.1 1 8"), 2, {"binary MSH files are not supported", "ASCII"});
}

TEST(GmshMsh, NonHexahedralVolumesAreRefused) {
  const std::string t = polymech::testing::replace_once(kMesh, "3 1 5 2", "3 1 4 2");
  expect_error(t, polymech::testing::line_of(t, "3 1 4 2"), {"4-node tetrahedron elements are not supported", "8-node hexahedra (type 5)"});
  const std::string q = polymech::testing::replace_once(kMesh, "3 1 5 2", "3 1 12 2");
  expect_error(q, polymech::testing::line_of(q, "3 1 12 2"), {"27-node hexahedron"});
}

TEST(GmshMsh, UnknownNodeTag) {
  const std::string t = polymech::testing::replace_once(kMesh, "4 2 3 6 5 8 9 12 11", "4 2 3 6 5 8 9 99 11");
  expect_error(t, polymech::testing::line_of(t, "4 2 3 6 5 8 9 99 11"), {"element 4 refers to node 99, which is not in $Nodes"});
}

TEST(GmshMsh, InvertedHexahedron) {
  const std::string t = polymech::testing::replace_once(kMesh, "3 1 2 5 4 7 8 11 10", "3 7 8 11 10 1 2 5 4");
  expect_error(t, polymech::testing::line_of(t, "3 7 8 11 10 1 2 5 4"),
               {"hexahedron 3 is inverted or degenerate", "allowed: > 0", "Gmsh's hexahedron order"});
  const std::string d = polymech::testing::replace_once(kMesh, "3 1 2 5 4 7 8 11 10", "3 1 2 5 4 7 8 11 11");
  expect_error(d, polymech::testing::line_of(d, "3 1 2 5 4 7 8 11 11"), {"repeats a node"});
}

TEST(GmshMsh, BoundaryQuadrangleThatIsNotOnTheBoundary) {
  const std::string t = polymech::testing::replace_once(kMesh, "2 3 6 12 9", "2 2 5 11 8");  // the interior face x = 1
  expect_error(t, polymech::testing::line_of(t, "2 2 5 11 8"), {"quadrangle 2 of boundary 'right' is not a face on the boundary"});
}

TEST(GmshMsh, MalformedNumbersAndTruncation) {
  const std::string t = polymech::testing::replace_once(kMesh, "2 1 1\n$EndNodes", "2 one 1\n$EndNodes");
  expect_error(t, polymech::testing::line_of(t, "2 one 1"), {"'one' is not a number"});
  const std::string cut = std::string(kMesh).substr(0, std::string(kMesh).find("0 1 1\n1 1 1"));
  expect_error(cut, -1, {"unexpected end of file"});
  const std::string count = polymech::testing::replace_once(kMesh, "1 12 1 12", "1 13 1 13");
  expect_error(count, -1, {"announced 13 nodes, found 12"});
  const std::string end = polymech::testing::replace_once(kMesh, "$EndNodes", "$EndNode");
  expect_error(end, polymech::testing::line_of(end, "$EndNode"), {"expected $EndNodes"});
  expect_error("hello\n", 1, {"expected a section header"});
  // an entity announcing 2e9 physical tags on a short line: an error at that line, not std::bad_alloc (issue 33 item 11)
  const std::string tags = polymech::testing::replace_once(kMesh, "1 0 0 0 0 1 1 1 1 0", "1 0 0 0 0 1 1 2000000000 1 0");
  expect_error(tags, polymech::testing::line_of(tags, "1 1 2000000000 1 0"), {"announces 2000000000 physical tags", "holds 2"});
}

// The neutral reader keeps triangles of named surfaces (a DEM surface may be triangulated); the
// Helmholtz conversion, which needs quadrilateral faces, refuses them at their line.
TEST(GmshMsh, TrianglesOfNamedSurfacesAreReadAndTheHexConversionRefusesThem) {
  std::string t = polymech::testing::replace_once(kMesh, "2 2 3 1\n2 3 6 12 9", "2 2 2 1\n2 3 6 12");
  polymech::testing::TempDir dir;
  const auto m = io::read_gmsh_mesh(dir.write("mesh.msh", t));
  ASSERT_EQ(m.facets.size(), 2u);
  EXPECT_EQ(m.facets[0].corners, 4);
  EXPECT_EQ(m.facets[1].corners, 3);
  EXPECT_EQ(m.groups[m.facets[1].group], "right");
  EXPECT_EQ(m.hexahedra.size(), 2u);
  EXPECT_EQ(m.node_count(), 12);
  expect_error(t, polymech::testing::line_of(t, "2 3 6 12\n"), {"3-node triangle elements on the physical surface 'right'"});
}
