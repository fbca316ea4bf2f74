// The .msh check that runs before gmsh reads a mesh file (src/mesh/MshCheck.*): gmsh's own files in formats 2.2 and
// 4.1 pass, and each kind of defect (a field missing, a count that does not match, a coordinate that is not a finite
// number, an unknown element type, a node tag that does not exist, a section without its end) is refused naming the
// line, as InputError "PATH: line N: ...".
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "core/Errors.hpp"
#include "mesh/MshCheck.hpp"

namespace
{

// Two triangles of the unit square, with their boundary lines, as gmsh writes them.
const char* kMsh22 = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
2
1 1 "wall"
2 2 "gas"
$EndPhysicalNames
$Nodes
4
1 0 0 0
2 1 0 0
3 1 1 0
4 0 1 0
$EndNodes
$Elements
6
1 1 2 1 1 1 2
2 1 2 1 2 2 3
3 1 2 1 3 3 4
4 1 2 1 4 4 1
5 2 2 2 1 1 2 3
6 2 2 2 1 1 3 4
$EndElements
)";

const char* kMsh41 = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
1 1 1 0
1 0 0 0 0
1 0 0 0 1 0 0 1 1 2 1 -1
1 0 0 0 1 1 0 1 2 1 1
$EndEntities
$Nodes
2 4 1 4
0 1 0 1
1
0 0 0
2 1 0 3
2
3
4
1 0 0
1 1 0
0 1 0
$EndNodes
$Elements
1 2 1 2
2 1 2 2
1 1 2 3
2 1 3 4
$EndElements
)";

std::string check(const std::string& text)
{
    const std::string path = testing::TempDir() + "unilag_msh_check.msh";
    std::ofstream(path) << text;
    try
    {
        unilag::checkMshFile(path);
    }
    catch (const unilag::InputError& e)
    {
        std::remove(path.c_str());
        return std::string(e.what()).substr(path.size() + 2);
    }
    std::remove(path.c_str());
    return "ok";
}

std::string replaced(std::string text, const std::string& from, const std::string& to)
{
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

} // namespace

TEST(MshCheck, GmshFilesPass)
{
    EXPECT_EQ(check(kMsh22), "ok");
    EXPECT_EQ(check(kMsh41), "ok");
    // binary (its one-integer endianness record after the format line): gmsh's own business
    EXPECT_EQ(check(replaced(kMsh22, "2.2 0 8\n", std::string("2.2 1 8\n\x01\0\0\0\n", 13))), "ok");
    EXPECT_EQ(check("solid stl\nendsolid stl\n"), "ok");               // another format gmsh reads
}

TEST(MshCheck, Format22Defects)
{
    // file-type 1 over a text body: gmsh read it as binary ("Unknown type of element 824193312")
    EXPECT_EQ(check(replaced(kMsh22, "2.2 0 8", "2.2 1 8")),
              "line 3: after a format line of file-type 1 (binary) the file goes on as text: file-type 0 is text");
    EXPECT_EQ(check(replaced(kMsh22, "3 1 1 0\n", "3 1 1\n")),
              "line 13: a node 'tag x y z': expected 4 fields, found 3");
    EXPECT_EQ(check(replaced(kMsh22, "3 1 1 0\n", "3 1 nan 0\n")),
              "line 13: node 3's coordinate: 'nan' is not a finite number");
    EXPECT_EQ(check(replaced(kMsh22, "$Nodes\n4", "$Nodes\n3")),
              "line 14: expected $EndNodes, found '4 0 1 0' (the section's count is wrong)");
    EXPECT_EQ(check(replaced(kMsh22, "$Nodes\n4", "$Nodes\n5")),
              "line 15: a node 'tag x y z': expected 4 fields, found 1");
    EXPECT_EQ(check(replaced(kMsh22, "6 2 2 2 1 1 3 4", "6 2 2 2 1 1 3 9")),
              "line 23: element 6 refers to node 9, which $Nodes does not define");
    EXPECT_EQ(check(replaced(kMsh22, "6 2 2 2 1 1 3 4", "6 77 2 2 1 1 3 4")),
              "line 23: element 6 has type 77, not a gmsh element type of order 1 or 2");
    EXPECT_EQ(check(replaced(kMsh22, "6 2 2 2 1 1 3 4", "6 2 2 2 1 1 3")),
              "line 23: element 6 of type 2 with 2 tags needs 8 fields, found 7");
    EXPECT_EQ(check(replaced(kMsh22, "2 2 \"gas\"", "2 2 gas")), "line 7: a physical name needs 'dim tag \"name\"'");
    EXPECT_EQ(check(replaced(kMsh22, "$EndElements\n", "")),
              "line 23: the file ends inside $Elements (no $EndElements)");
}

TEST(MshCheck, Format41Defects)
{
    EXPECT_EQ(check(replaced(kMsh41, "2 1 0 3\n", "2 1 0 2\n")),
              "line 18: a node's coordinates: expected 3 fields, found 1");
    EXPECT_EQ(check(replaced(kMsh41, "2 4 1 4", "2 5 1 4")), "line 21: the node header counts 5 nodes, its blocks 4");
    EXPECT_EQ(check(replaced(kMsh41, "2 1 3 4", "2 1 3 5")),
              "line 27: element 2 refers to node 5, which $Nodes does not define");
    EXPECT_EQ(check(replaced(kMsh41, "1 0 0 0 1 0 0 1 1 2 1 -1", "1 0 0 0 1 0 0 1 1 2 1")),
              "line 7: entity 1 of dimension 1: its counts do not match its 11 fields");
}
