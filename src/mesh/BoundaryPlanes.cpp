#include "mesh/BoundaryPlanes.hpp"

#include <algorithm>
#include <cmath>

namespace unilag
{
namespace
{

//! Outward area vector of face j (opposite local node j) of cell i, from coords0 (3 components, 0 in 2D).
std::array<double, 3> faceArea(const DistributedMesh& dm, LO i, int j)
{
    const int nv = dm.nv;
    const double* x[4];
    for (int k = 0; k < nv; ++k)
        x[k] = &dm.coords0[3 * std::size_t(dm.cellNodesHost[std::size_t(nv) * i + k])];
    const double* a = x[(j + 1) % nv];
    const double* b = x[(j + 2) % nv];
    std::array<double, 3> n{0.0, 0.0, 0.0};
    if (dm.dim == 2)
        n = {b[1] - a[1], a[0] - b[0], 0.0};
    else
    {
        const double* c = x[(j + 3) % nv];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        n = {0.5 * (u[1] * w[2] - u[2] * w[1]), 0.5 * (u[2] * w[0] - u[0] * w[2]), 0.5 * (u[0] * w[1] - u[1] * w[0])};
    }
    // outward: away from the opposite node
    double s = 0.0;
    for (int d = 0; d < 3; ++d)
        s += n[d] * (x[j][d] - a[d]);
    if (s > 0.0)
        for (double& v : n)
            v = -v;
    return n;
}

double length(const std::array<double, 3>& v)
{
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

//! One plane of a boundary group: the unit normal of its face of lowest key (global cell id x nv + local face).
struct Plane
{
    double key;
    std::array<double, 3> normal;
};

/*! Adds a face to the plane it lies in (unit normals equal to the round-off of the mesh's coordinates), keeping the
 *  lower key's normal; false where that would make more than maxPlanes planes (a curved or folded boundary). */
bool joinPlane(std::vector<Plane>& planes, const Plane& face, int maxPlanes)
{
    for (Plane& p : planes)
    {
        const std::array<double, 3> d{face.normal[0] - p.normal[0], face.normal[1] - p.normal[1],
                                      face.normal[2] - p.normal[2]};
        if (length(d) <= 1e-9)
        {
            if (face.key < p.key)
                p = face;
            return true;
        }
    }
    planes.push_back(face);
    return int(planes.size()) <= maxPlanes;
}

} // namespace

std::vector<std::vector<std::array<double, 3>>> flatBoundaryPlanes(const DistributedMesh& dm, MPI_Comm comm,
                                                                   int maxPlanes)
{
    const int ng = int(dm.boundaryNames.size()), nv = dm.nv;
    // this rank's planes of each group (a plane: the unit normal of its face of lowest global key), or overflow
    std::vector<std::vector<Plane>> local{std::size_t(ng)};
    std::vector<bool> curved(std::size_t(ng), false);
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        for (int j = 0; j < nv; ++j)
            if (const int g = dm.cellFaceGroupHost[std::size_t(nv) * i + j]; g >= 0 && !curved[g])
            {
                const auto a = faceArea(dm, i, j);
                const double len = length(a);
                const Plane face{double(dm.cellGid[i]) * nv + j, {a[0] / len, a[1] / len, a[2] / len}};
                curved[g] = !joinPlane(local[g], face, maxPlanes);
            }
    // gather them (key, normal; key -1 = none, -2 = curved) and merge in key order, the same on every rank
    const std::size_t row = 4 * std::size_t(maxPlanes), width = row * std::size_t(ng);
    std::vector<double> mine(width, -1.0);
    for (int g = 0; g < ng; ++g)
        if (curved[g])
            mine[row * g] = -2.0;
        else
            for (std::size_t p = 0; p < local[g].size(); ++p)
            {
                double* r = &mine[row * g + 4 * p];
                r[0] = local[g][p].key;
                std::copy(local[g][p].normal.begin(), local[g][p].normal.end(), r + 1);
            }
    const std::vector<double> all = mpi::allGather(comm, mine);
    std::vector<std::vector<std::array<double, 3>>> planes{std::size_t(ng)};
    for (int g = 0; g < ng; ++g)
    {
        std::vector<Plane> found;
        bool bent = false;
        for (std::size_t r = 0; r < all.size() / width; ++r)
            for (int p = 0; p < maxPlanes; ++p)
            {
                const double* e = &all[width * r + row * g + 4 * std::size_t(p)];
                bent = bent || e[0] == -2.0;
                if (e[0] >= 0.0)
                    found.push_back({e[0], {e[1], e[2], e[3]}});
            }
        std::sort(found.begin(), found.end(), [](const Plane& a, const Plane& b) { return a.key < b.key; });
        std::vector<Plane> merged;
        for (const Plane& p : found)
            bent = bent || !joinPlane(merged, p, maxPlanes);
        if (!bent)
            for (const Plane& p : merged)
                planes[g].push_back(p.normal);
    }
    return planes;
}

} // namespace unilag
