#include "mesh/GlobalMesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

#include <gmsh.h>

#include "config/Scene.hpp"
#include "core/Format.hpp"
#include "mesh/FaceKey.hpp"
#include "mesh/GmshCrashGuard.hpp"
#include "mesh/LatticeMesh.hpp"
#include "mesh/MshCheck.hpp"

namespace unilag
{
namespace
{

std::string gmshError()
{
    std::string err;
    try
    {
        gmsh::logger::getLastError(err);
    }
    catch (...)
    {
    }
    return err.empty() ? "gmsh failed" : err;
}

/*! Refuses an entity of the regions that holds elements other than linear simplices (quadrangles from
 *  Mesh.RecombineAll, second-order triangles from Mesh.ElementOrder = 2): unilag would drop them and leave a hole,
 *  reported as an unnamed boundary at best. */
void rejectOtherElements(const std::string& source, int dim, int entity, int cellType)
{
    std::vector<int> types; // the types alone: the cells' own tags and nodes are read once, by the caller
    gmsh::model::mesh::getElementTypes(types, dim, entity);
    for (int type : types)
    {
        if (type == cellType)
            continue;
        std::vector<std::size_t> tags, nodes;
        gmsh::model::mesh::getElementsByType(type, tags, nodes, entity);
        if (tags.empty())
            continue;
        std::string name;
        int elementDim = 0, order = 0, nodeCount = 0, primaryNodes = 0;
        std::vector<double> local;
        gmsh::model::mesh::getElementProperties(type, name, elementDim, order, nodeCount, local, primaryNodes);
        throw InputError(source + ": element " + std::to_string(tags[0]) + " is a " + name + " (and " +
                         std::to_string(tags.size() - 1) + " more): unilag takes linear " +
                         (dim == 2 ? "triangles" : "tetrahedra") + " only");
    }
}

//! The boundary physical groups: their names into m.boundaryNames, and each face's group by the face's key.
std::map<FaceKey, int> readBoundaryGroups(GlobalMesh& m, const std::unordered_map<std::size_t, int>& index)
{
    // faces are lines in 2D, triangles in 3D
    std::map<FaceKey, int> boundaryFace;
    gmsh::vectorpair bgroups;
    gmsh::model::getPhysicalGroups(bgroups, m.dim - 1);
    const int faceType = gmsh::model::mesh::getElementType(m.dim == 2 ? "Line" : "Triangle", 1);
    for (const auto& [dim, tag] : bgroups)
    {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        if (name.empty())
            name = std::to_string(tag);
        const int g = int(m.boundaryNames.size());
        m.boundaryNames.push_back(name);
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
        for (int e : entities)
        {
            std::vector<std::size_t> tags, nodes;
            gmsh::model::mesh::getElementsByType(faceType, tags, nodes, e);
            for (std::size_t f = 0; f < tags.size(); ++f)
            {
                int idx[3] = {-1, -1, -1};
                for (int k = 0; k < m.dim; ++k)
                    idx[k] = index.at(nodes[m.dim * f + k]);
                boundaryFace[faceKey(idx, m.dim)] = g;
            }
        }
    }
    return boundaryFace;
}

//! Each face of one cell is a boundary face: its group from boundaryFace, where it must be.
void assignFaceGroups(const std::string& source, GlobalMesh& m, const std::vector<std::size_t>& nodeTags,
                      const std::map<FaceKey, int>& boundaryFace)
{
    const int nv = m.nv();
    m.cellFaceGroup.assign(m.nCells() * nv, -1);
    auto onBoundary = [&](const FaceRef& f) {
        auto it = boundaryFace.find(f.key);
        if (it == boundaryFace.end())
        {
            std::string nodes;
            for (int k = 0; k < m.dim; ++k)
                nodes += " " + std::to_string(nodeTags[f.key[k]]);
            throw InputError(source + ": boundary face (nodes" + nodes + ") of element " +
                             std::to_string(m.cellTag[f.cell]) +
                             " is in no boundary physical group; name every boundary in the geometry");
        }
        m.cellFaceGroup[nv * f.cell + f.k] = it->second;
    };
    const auto overShared = matchFaces(m.cells.data(), m.nCells(), nv, [](const FaceRef&, const FaceRef&) {},
                                       onBoundary);
    if (overShared)
        throw InputError(source + ": a face is shared by more than two elements (element " +
                         std::to_string(m.cellTag[overShared->cell]) + ")");
}

//! All nodes at one z (a 2D mesh): a tetrahedron in it was said to be degenerate, in a region named by its tag.
bool flat(const std::vector<double>& xyz)
{
    if (xyz.size() < 12) // fewer nodes than one tetrahedron: gmsh's own checks speak
        return false;
    for (std::size_t i = 5; i < xyz.size(); i += 3)
        if (xyz[i] != xyz[2])
            return false;
    return true;
}

void extract(const std::string& source, GlobalMesh& m)
{
    m.dim = gmsh::model::getDimension();
    if (m.dim != 2 && m.dim != 3)
        throw InputError(source + ": the mesh must be 2D (triangles) or 3D (tetrahedra); gmsh model dimension is " +
                         std::to_string(m.dim));
    const int nv = m.nv();

    std::vector<std::size_t> nodeTags;
    std::vector<double> xyz, uvw;
    gmsh::model::mesh::getNodes(nodeTags, xyz, uvw, -1, -1, false, false);
    std::unordered_map<std::size_t, int> index;
    index.reserve(nodeTags.size());
    for (std::size_t i = 0; i < nodeTags.size(); ++i)
        index[nodeTags[i]] = int(i);
    m.coords = xyz;
    if (m.dim == 2)
        for (std::size_t i = 0; i < nodeTags.size(); ++i)
            if (std::abs(xyz[3 * i + 2]) > 0.0)
                throw InputError(source + ": node " + std::to_string(nodeTags[i]) +
                                 " has z != 0; a 2D mesh must lie in the plane z = 0");
    if (m.dim == 3 && flat(xyz))
        throw InputError(source + ": the mesh has 3D elements (tetrahedra) but every node at the same z: a 2D mesh "
                         "takes triangles only");

    const int cellType = gmsh::model::mesh::getElementType(m.dim == 2 ? "Triangle" : "Tetrahedron", 1);
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, m.dim);
    if (groups.empty())
        throw InputError(source + ": no physical group of " + (m.dim == 2 ? "surfaces" : "volumes") +
                         " (the scene's regions name them)");
    std::unordered_map<std::size_t, int> cellOfTag;
    for (const auto& [dim, tag] : groups)
    {
        std::string name;
        gmsh::model::getPhysicalName(dim, tag, name);
        if (name.empty())
            name = std::to_string(tag);
        const int region = int(m.regionNames.size());
        m.regionNames.push_back(name);
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
        for (int e : entities)
        {
            rejectOtherElements(source, m.dim, e, cellType);
            std::vector<std::size_t> tags, nodes;
            gmsh::model::mesh::getElementsByType(cellType, tags, nodes, e);
            // Orientation: gmsh orients each entity consistently, possibly clockwise. A cell whose sign differs
            // from the rest of its entity is folded over (inverted); a whole entity of negative sign is flipped.
            const std::size_t first = m.nCells();
            int nNeg = 0, nPos = 0;
            double meanAbs = 0.0;
            std::vector<double> vol(tags.size());
            for (std::size_t c = 0; c < tags.size(); ++c)
            {
                if (cellOfTag.count(tags[c]))
                    throw InputError(source + ": element " + std::to_string(tags[c]) + " is in two regions");
                cellOfTag[tags[c]] = int(first + c);
                int idx[4] = {0, 0, 0, 0};
                for (int k = 0; k < nv; ++k)
                    idx[k] = index.at(nodes[nv * c + k]);
                vol[c] = signedMeasure(m.dim, &xyz[3 * idx[0]], &xyz[3 * idx[1]], &xyz[3 * idx[2]],
                                       &xyz[3 * idx[3]]);
                (vol[c] < 0.0 ? nNeg : nPos)++;
                meanAbs += std::abs(vol[c]);
                m.cells.insert(m.cells.end(), idx, idx + nv);
                m.cellTag.push_back(tags[c]);
                m.cellRegion.push_back(region);
            }
            if (tags.empty())
                continue;
            meanAbs /= double(tags.size());
            const bool flip = nNeg > nPos;
            for (std::size_t c = 0; c < tags.size(); ++c)
            {
                if (std::abs(vol[c]) <= 1e-12 * meanAbs)
                    throw InputError(source + ": element " + std::to_string(tags[c]) + " of region '" + name +
                                     "' is degenerate (measure " + std::to_string(vol[c]) + ")");
                if ((vol[c] < 0.0) != flip)
                    throw InputError(source + ": element " + std::to_string(tags[c]) + " of region '" + name +
                                     "' is inverted (signed measure " + std::to_string(vol[c]) +
                                     " against the orientation of its neighbours)");
                if (flip)
                    std::swap(m.cells[nv * (first + c)], m.cells[nv * (first + c) + 1]);
            }
        }
    }
    if (m.nCells() == 0)
        throw InputError(source + ": the mesh has no " + std::string(m.dim == 2 ? "triangles" : "tetrahedra"));

    const std::map<FaceKey, int> boundaryFace = readBoundaryGroups(m, index);
    assignFaceGroups(source, m, nodeTags, boundaryFace);
}

//! Interleave the low 21 bits of three integers (Morton / Z-order key).
std::uint64_t morton(std::uint64_t x, std::uint64_t y, std::uint64_t z)
{
    auto spread = [](std::uint64_t v) {
        v &= 0x1fffff;
        v = (v | v << 32) & 0x1f00000000ffffULL;
        v = (v | v << 16) & 0x1f0000ff0000ffULL;
        v = (v | v << 8) & 0x100f00f00f00f00fULL;
        v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
        v = (v | v << 2) & 0x1249249249249249ULL;
        return v;
    };
    return spread(x) | spread(y) << 1 | spread(z) << 2;
}

/*! Renumber cells along a Morton curve of their centroids, and nodes in the order cells first touch them, so
 *  that global ids (and hence the local numbering, sorted by global id) are spatially coherent: the gathers
 *  of the kernels then walk memory nearly in order. gmsh's own numbering is not coherent. */
void renumber(GlobalMesh& m)
{
    const int nv = m.nv();
    const std::size_t nc = m.nCells();
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::size_t n = 0; n < m.nNodes(); ++n)
        for (int d = 0; d < 3; ++d)
        {
            lo[d] = std::min(lo[d], m.coords[3 * n + d]);
            hi[d] = std::max(hi[d], m.coords[3 * n + d]);
        }
    std::vector<std::pair<std::uint64_t, std::size_t>> key(nc);
    for (std::size_t c = 0; c < nc; ++c)
    {
        std::uint64_t q[3] = {0, 0, 0};
        for (int d = 0; d < 3; ++d)
        {
            double x = 0.0;
            for (int k = 0; k < nv; ++k)
                x += m.coords[3 * m.cells[nv * c + k] + d] / nv;
            const double w = hi[d] - lo[d];
            q[d] = w > 0.0 ? std::uint64_t((x - lo[d]) / w * 2097151.0) : 0;
        }
        key[c] = {morton(q[0], q[1], q[2]), c};
    }
    std::sort(key.begin(), key.end());
    GlobalMesh r;
    r.dim = m.dim;
    r.regionNames = m.regionNames;
    r.boundaryNames = m.boundaryNames;
    std::vector<int> newNode(m.nNodes(), -1);
    int next = 0;
    for (const auto& [k, c] : key)
    {
        for (int j = 0; j < nv; ++j)
        {
            int& id = newNode[m.cells[nv * c + j]];
            if (id < 0)
                id = next++;
            r.cells.push_back(id);
            r.cellFaceGroup.push_back(m.cellFaceGroup[nv * c + j]);
        }
        r.cellTag.push_back(m.cellTag[c]);
        r.cellRegion.push_back(m.cellRegion[c]);
    }
    // nodes that belong to no cell (e.g. geometry points) are dropped
    r.coords.resize(3 * std::size_t(next));
    for (std::size_t n = 0; n < m.nNodes(); ++n)
        if (newNode[n] >= 0)
            for (int d = 0; d < 3; ++d)
                r.coords[3 * newNode[n] + d] = m.coords[3 * n + d];
    m = std::move(r);
}

} // namespace

double signedMeasure(int dim, const double* a, const double* b, const double* c, const double* d)
{
    if (dim == 2)
        return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double e3[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return (e1[0] * (e2[1] * e3[2] - e2[2] * e3[1]) - e1[1] * (e2[0] * e3[2] - e2[2] * e3[0]) +
            e1[2] * (e2[0] * e3[1] - e2[1] * e3[0])) /
           6.0;
}

double signedMeasure(const GlobalMesh& m, std::size_t cell)
{
    const int* n = &m.cells[std::size_t(m.nv()) * cell];
    const double* x = m.coords.data();
    return signedMeasure(m.dim, x + 3 * n[0], x + 3 * n[1], x + 3 * n[2], m.dim == 3 ? x + 3 * n[3] : nullptr);
}

/*! gmsh's quality (gamma) below which free tetrahedra are optimised. 0.6 against gmsh's 0.3, on the Sedov octant at
 *  order 2: 1.5-1.8x fewer steps, L1 5-10% lower (docs/sedov.md, session 29). No effect on triangles, extruded or
 *  transfinite volumes. */
constexpr double tetOptimizeThreshold = 0.6;

/*! About how many cells mesh.size asks for: the model's bounding box over a regular simplex of that edge (an upper
 *  estimate). mesh.size = 1e-9 meshed for ever without a word. */
double estimatedCells(double size)
{
    const int dim = gmsh::model::getDimension();
    double lo[3], hi[3];
    gmsh::model::getBoundingBox(-1, -1, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    double measure = 1.0;
    for (int d = 0; d < dim; ++d)
        measure *= std::max(hi[d] - lo[d], 0.0);
    const double simplex = dim == 2 ? std::sqrt(3.0) / 4.0 : 1.0 / (6.0 * std::sqrt(2.0));
    return measure / (simplex * std::pow(size, dim));
}
constexpr double maxEstimatedCells = 1e9;

GlobalMesh loadMesh(const Scene& scene)
{
    const std::string source = scene.geometry.empty() ? scene.meshFile : scene.geometry;
    if (scene.geometry.empty())
        checkMshFile(source); // before gmsh, which crashes on some malformed files
    GlobalMesh m;
    double cells = 0.0; // estimated from mesh.size (a .geo only)
    gmsh::initialize(0, nullptr, false);
    try
    {
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.NumThreads", 1);
        try
        {
            // A .geo can read the scene's size as Mesh.MeshSizeMax (structured meshes compute their counts from it).
            if (!scene.geometry.empty())
            {
                gmsh::option::setNumber("Mesh.MeshSizeMin", scene.meshSize);
                gmsh::option::setNumber("Mesh.MeshSizeMax", scene.meshSize);
                // before the .geo is read, so that a .geo may choose its own threshold
                gmsh::option::setNumber("Mesh.OptimizeThreshold", tetOptimizeThreshold);
            }
            const GmshCrashGuard guard(source);
            gmsh::open(source);
            if (!scene.geometry.empty())
            {
                // Uniform size from the scene: the .geo's own point sizes are ignored.
                gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
                gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
                gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
                gmsh::option::setNumber("Mesh.MeshSizeMin", scene.meshSize);
                gmsh::option::setNumber("Mesh.MeshSizeMax", scene.meshSize);
                cells = estimatedCells(scene.meshSize);
                if (cells <= maxEstimatedCells)
                {
                    if (scene.meshLattice)
                        meshAsLattice(source, scene.meshSize);
                    else
                        gmsh::model::mesh::generate(gmsh::model::getDimension());
                }
            }
        }
        catch (const InputError&)
        {
            throw; // the lattice's own message
        }
        catch (...)
        {
            throw InputError(source + ": " + gmshError());
        }
        if (!(cells <= maxEstimatedCells))
            throw InputError(scene.file + ": key 'mesh.size': " + jsonNumber(scene.meshSize) + " asks for about " +
                             jsonNumber(cells) + " cells of " + source + ": at most 1e9");
        extract(source, m);
        renumber(m);
    }
    catch (...)
    {
        gmsh::finalize();
        throw;
    }
    gmsh::finalize();
    return m;
}

namespace
{

std::string joined(const std::vector<std::string>& names)
{
    std::string s;
    for (const auto& n : names)
        s += (s.empty() ? "" : ", ") + n;
    return s.empty() ? "none" : s;
}

//! One kind of group: the scene's keys (section.name) against the mesh's groups of that kind.
template <class Map>
void matchGroups(const Scene& scene, const std::string& source, const char* section, const char* kind,
                 const char* missing, const Map& keys, const std::vector<std::string>& groups)
{
    for (const auto& [name, spec] : keys)
        if (std::find(groups.begin(), groups.end(), name) == groups.end())
            throw InputError(scene.file + ": key '" + section + "." + name + "': no " + kind + " physical group '" +
                             name + "' in mesh " + source + " (it has: " + joined(groups) + ")");
    for (const auto& g : groups)
        if (!keys.count(g))
            throw InputError(scene.file + ": key '" + section + "': mesh " + source + " has a " + kind +
                             " physical group '" + g + "' with no " + missing + " (add " + section + "." + g + ")");
}

} // namespace

void matchScene(const Scene& scene, const GlobalMesh& mesh)
{
    const std::string source = scene.geometry.empty() ? scene.meshFile : scene.geometry;
    matchGroups(scene, source, "regions", "region", "initial state", scene.regions, mesh.regionNames);
    matchGroups(scene, source, "boundaries", "boundary", "condition", scene.boundaries, mesh.boundaryNames);
}

} // namespace unilag
