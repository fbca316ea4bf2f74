#include "mesh/BoundaryPlanes.hpp"

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

} // namespace

std::vector<std::array<double, 3>> flatBoundaryNormals(const DistributedMesh& dm, MPI_Comm comm)
{
    const int ng = int(dm.boundaryNames.size()), nv = dm.nv;
    // the group's normal: that of its face of lowest (global cell id, local face), whichever rank holds it, so that
    // it is the same on any partition, bit for bit
    std::vector<double> key(std::size_t(ng), 1e300);
    std::vector<std::array<double, 3>> first(std::size_t(ng), {0.0, 0.0, 0.0});
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        for (int j = 0; j < nv; ++j)
            if (const int g = dm.cellFaceGroupHost[std::size_t(nv) * i + j]; g >= 0)
            {
                const double k = double(dm.cellGid[i]) * nv + j;
                if (k < key[g])
                {
                    key[g] = k;
                    first[g] = faceArea(dm, i, j);
                }
            }
    std::vector<double> sum(3 * std::size_t(ng) + 1, 0.0), bent(std::size_t(ng) + 1, 0.0);
    for (int g = 0; g < ng; ++g)
        if (key[g] == mpi::allMin(comm, key[g]) && key[g] < 1e300)
            for (int d = 0; d < 3; ++d)
                sum[3 * g + d] = first[g][d] / length(first[g]);
    mpi::allSum(comm, sum.data(), int(sum.size())); // one rank adds its normal, the others 0
    std::vector<std::array<double, 3>> normal(ng, {0.0, 0.0, 0.0});
    for (int g = 0; g < ng; ++g)
        normal[g] = {sum[3 * g], sum[3 * g + 1], sum[3 * g + 2]};
    // flat: every face's unit normal is that one (to the round-off of the mesh's coordinates)
    for (LO i = 0; i < dm.nOwnedCells; ++i)
        for (int j = 0; j < nv; ++j)
            if (const int g = dm.cellFaceGroupHost[std::size_t(nv) * i + j]; g >= 0)
            {
                const auto a = faceArea(dm, i, j);
                const double len = length(a);
                double dev = 0.0;
                for (int d = 0; d < 3; ++d)
                    dev += std::pow(a[d] / len - normal[g][d], 2);
                if (!(std::sqrt(dev) <= 1e-9))
                    bent[g] = 1.0;
            }
    mpi::allSum(comm, bent.data(), int(bent.size()));
    for (int g = 0; g < ng; ++g)
        if (bent[g] > 0.0)
            normal[g] = {0.0, 0.0, 0.0};
    return normal;
}

} // namespace unilag
