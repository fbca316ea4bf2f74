#include "mesh/MshCheck.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unordered_set>
#include <vector>

#include "core/Errors.hpp"

namespace unilag
{
namespace
{

using Tokens = std::vector<std::string>;

//! Nodes of gmsh's element types (1 .. 19: points, lines, triangles, quadrangles, tetrahedra, ... to order 2); 0 if
//! the type is not one of them.
int nodesOfType(long long type)
{
    static const int nodes[20] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
    return type >= 1 && type <= 19 ? nodes[type] : 0;
}

//! Whether gmsh's element type is of order 2 (types 8-14, 16-19): gmsh corrupted its heap on a linear mesh with one.
bool secondOrder(long long type) { return (type >= 8 && type <= 14) || (type >= 16 && type <= 19); }

std::string secondOrderText(long long type)
{
    return " has type " + std::to_string(type) + ", a second-order element: unilag takes linear triangles and " +
           "tetrahedra only (gmsh's Mesh.ElementOrder = 1)";
}

//! Line-by-line reader of one .msh file whose failures name the file and line.
class MshLines
{
  public:
    explicit MshLines(const std::string& path) : path_(path), in_(path) {}
    bool good() const { return bool(in_); }

    bool next(std::string& line)
    {
        if (!std::getline(in_, line))
            return false;
        ++number_;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
            line.pop_back();
        return true;
    }

    [[noreturn]] void fail(const std::string& what) const
    {
        throw InputError(path_ + ": line " + std::to_string(number_) + ": " + what);
    }

    //! The next line's fields: exactly n of them (n > 0), or any number (n = 0). what names the record.
    Tokens record(std::size_t n, const std::string& what)
    {
        std::string line;
        if (!next(line))
            fail("the file ends where " + what + " belongs");
        Tokens t;
        std::istringstream is(line);
        for (std::string s; is >> s;)
            t.push_back(s);
        if (n > 0 && t.size() != n)
            fail(what + ": expected " + std::to_string(n) + " fields, found " + std::to_string(t.size()));
        return t;
    }

    long long integer(const std::string& s, const std::string& what) const
    {
        char* end = nullptr;
        const long long v = std::strtoll(s.c_str(), &end, 10);
        if (s.empty() || *end != '\0')
            fail(what + ": '" + s + "' is not an integer");
        return v;
    }

    long long count(const std::string& s, const std::string& what) const
    {
        const long long v = integer(s, what);
        if (v < 0)
            fail(what + ": " + s + " is negative");
        return v;
    }

    double real(const std::string& s, const std::string& what) const
    {
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0' || !std::isfinite(v))
            fail(what + ": '" + s + "' is not a finite number");
        return v;
    }

    //! The next line must close the section: a count too small leaves records before it.
    void end(const std::string& section)
    {
        std::string line;
        if (!next(line))
            fail("the file ends inside $" + section + " (no $End" + section + ")");
        if (line != "$End" + section)
            fail("expected $End" + section + ", found '" + line.substr(0, 60) + "' (the section's count is wrong)");
    }

    void skip(const std::string& section)
    {
        std::string line;
        while (next(line))
            if (line == "$End" + section)
                return;
        fail("the file ends inside $" + section + " (no $End" + section + ")");
    }

  private:
    std::string path_;
    std::ifstream in_;
    long long number_ = 0;
};

using NodeTags = std::unordered_set<long long>;
using ElementTags = std::unordered_set<long long>;

void addNode(MshLines& in, NodeTags& nodes, const std::string& tag)
{
    if (!nodes.insert(in.integer(tag, "a node tag")).second)
        in.fail("node " + tag + " is defined twice");
}

//! The node tags of an element (fields first .. end of t), each defined in $Nodes; its own tag used once (gmsh
//! kept one of two elements with the same tag and the other's face was said to be in no boundary group).
void checkElementNodes(MshLines& in, const NodeTags& nodes, ElementTags& elements, const Tokens& t, std::size_t first)
{
    if (!elements.insert(in.integer(t[0], "an element tag")).second)
        in.fail("element " + t[0] + " is defined twice");
    for (std::size_t k = first; k < t.size(); ++k)
        if (!nodes.count(in.integer(t[k], "an element's node")))
            in.fail("element " + t[0] + " refers to node " + t[k] + ", which $Nodes does not define");
}

void nodes22(MshLines& in, NodeTags& nodes)
{
    const long long n = in.count(in.record(1, "the node count")[0], "the node count");
    for (long long k = 0; k < n; ++k)
    {
        const Tokens t = in.record(4, "a node 'tag x y z'");
        addNode(in, nodes, t[0]);
        for (int d = 1; d < 4; ++d)
            in.real(t[d], "node " + t[0] + "'s coordinate");
    }
    in.end("Nodes");
}

void elements22(MshLines& in, const NodeTags& nodes)
{
    const long long n = in.count(in.record(1, "the element count")[0], "the element count");
    ElementTags elements;
    for (long long k = 0; k < n; ++k)
    {
        const Tokens t = in.record(0, "an element 'tag type ntags tags... nodes...'");
        if (t.size() < 3)
            in.fail("an element needs 'tag type ntags' first, found " + std::to_string(t.size()) + " fields");
        const long long type = in.integer(t[1], "an element type");
        const int nv = nodesOfType(type);
        if (nv == 0)
            in.fail("element " + t[0] + " has type " + t[1] + ", not a gmsh element type of order 1 or 2");
        if (secondOrder(type))
            in.fail("element " + t[0] + secondOrderText(type));
        const long long ntags = in.count(t[2], "element " + t[0] + "'s tag count");
        if (ntags > 100 || t.size() != std::size_t(3 + ntags + nv))
            in.fail("element " + t[0] + " of type " + t[1] + " with " + t[2] + " tags needs " +
                    std::to_string(3 + ntags + nv) + " fields, found " + std::to_string(t.size()));
        for (long long g = 0; g < ntags; ++g)
            in.integer(t[3 + g], "element " + t[0] + "'s tag");
        checkElementNodes(in, nodes, elements, t, std::size_t(3 + ntags));
    }
    in.end("Elements");
}

void entities41(MshLines& in)
{
    const Tokens c = in.record(4, "the entity counts 'points curves surfaces volumes'");
    for (int dim = 0; dim < 4; ++dim)
        for (long long k = 0, n = in.count(c[dim], "an entity count"); k < n; ++k)
        {
            const Tokens t = in.record(0, "an entity");
            const std::size_t box = dim == 0 ? 4 : 7; // tag and point, or tag and bounding box
            if (t.size() < box + 1)
                in.fail("an entity of dimension " + std::to_string(dim) + " has too few fields");
            for (std::size_t x = 1; x < box; ++x)
                in.real(t[x], "entity " + t[0] + "'s coordinate");
            std::size_t size = box + 1 + std::size_t(in.count(t[box], "an entity's physical tag count"));
            if (dim > 0 && t.size() > size) // then its bounding entities
                size += 1 + std::size_t(in.count(t[size], "an entity's bounding entity count"));
            else if (dim > 0)
                size += 1;
            if (t.size() != size)
                in.fail("entity " + t[0] + " of dimension " + std::to_string(dim) + ": its counts do not match its " +
                        std::to_string(t.size()) + " fields");
        }
    in.end("Entities");
}

void nodes41(MshLines& in, NodeTags& nodes)
{
    const Tokens h = in.record(4, "the node header 'blocks nodes min-tag max-tag'");
    const long long blocks = in.count(h[0], "the node block count"), total = in.count(h[1], "the node count");
    long long seen = 0;
    for (long long b = 0; b < blocks; ++b)
    {
        const Tokens t = in.record(4, "a node block 'dim entity parametric count'");
        const long long dim = in.count(t[0], "a block's dimension"), parametric = in.count(t[2], "parametric");
        const long long n = in.count(t[3], "a block's node count");
        for (long long k = 0; k < n; ++k)
            addNode(in, nodes, in.record(1, "a node tag")[0]);
        for (long long k = 0; k < n; ++k)
            for (const auto& x : in.record(std::size_t(3 + (parametric ? dim : 0)), "a node's coordinates"))
                in.real(x, "a node's coordinate");
        seen += n;
    }
    if (seen != total)
        in.fail("the node header counts " + h[1] + " nodes, its blocks " + std::to_string(seen));
    in.end("Nodes");
}

void elements41(MshLines& in, const NodeTags& nodes)
{
    const Tokens h = in.record(4, "the element header 'blocks elements min-tag max-tag'");
    const long long blocks = in.count(h[0], "the element block count"), total = in.count(h[1], "the element count");
    long long seen = 0;
    ElementTags elements;
    for (long long b = 0; b < blocks; ++b)
    {
        const Tokens t = in.record(4, "an element block 'dim entity type count'");
        const long long type = in.integer(t[2], "an element type");
        const int nv = nodesOfType(type);
        if (nv == 0)
            in.fail("element type " + t[2] + " is not a gmsh element type of order 1 or 2");
        if (secondOrder(type))
            in.fail("the element block of entity " + t[1] + secondOrderText(type));
        const long long n = in.count(t[3], "a block's element count");
        for (long long k = 0; k < n; ++k)
            checkElementNodes(in, nodes, elements, in.record(std::size_t(1 + nv), "an element 'tag nodes...'"), 1);
        seen += n;
    }
    if (seen != total)
        in.fail("the element header counts " + h[1] + " elements, its blocks " + std::to_string(seen));
    in.end("Elements");
}

void physicalNames(MshLines& in)
{
    const long long n = in.count(in.record(1, "the physical name count")[0], "the physical name count");
    for (long long k = 0; k < n; ++k)
    {
        const Tokens t = in.record(0, "a physical name 'dim tag \"name\"'");
        if (t.size() < 3 || t[2].front() != '"' || t.back().back() != '"' || (t.size() == 3 && t[2].size() < 2))
            in.fail("a physical name needs 'dim tag \"name\"'");
        in.count(t[0], "a physical name's dimension");
        in.integer(t[1], "a physical name's tag");
    }
    in.end("PhysicalNames");
}

} // namespace

void checkMshFile(const std::string& path)
{
    MshLines in(path);
    if (!in.good())
        return; // the scene reader has said whether the file exists
    std::string line, version;
    NodeTags nodes;
    while (in.next(line))
    {
        if (line.empty())
            continue;
        if (version.empty() && line != "$MeshFormat")
            return; // not gmsh's .msh (gmsh reads other formats too), or its format 1 ($NOD): unchecked
        if (line[0] != '$')
            in.fail("expected a section ($Name), found '" + line.substr(0, 60) + "'");
        const std::string section = line.substr(1);
        if (version.empty())
        {
            const Tokens t = in.record(3, "the format line 'version file-type data-size'");
            // A binary file has its one-integer endianness record here; a text file says file-type 0 (with 1,
            // gmsh read the text as binary and named an element type of 824193312).
            if (t[1] == "1" && in.next(line) && line == "$EndMeshFormat")
                in.fail("after a format line of file-type 1 (binary) the file goes on as text: file-type 0 is text");
            if (t[1] != "0" || (t[0] != "2.2" && t[0] != "4.1"))
                return; // binary, or another version: unchecked
            version = t[0];
            in.end(section);
        }
        else if (section == "Nodes")
            version == "2.2" ? nodes22(in, nodes) : nodes41(in, nodes);
        else if (section == "Elements")
            version == "2.2" ? elements22(in, nodes) : elements41(in, nodes);
        else if (section == "PhysicalNames")
            physicalNames(in);
        else if (section == "Entities" && version == "4.1")
            entities41(in);
        else
            in.skip(section);
    }
}

} // namespace unilag
