/*! \file BoundaryPlanes.hpp
 *  \brief Which boundary groups are flat: the fixed normal a slip wall or symmetry plane imposes (wallNormal in
 *  Physics.hpp), found once from the mesh as built.
 */
#pragma once

#include <array>
#include <vector>

#include "core/Mpi.hpp"
#include "mesh/DistributedMesh.hpp"

namespace unilag
{

/*! For each boundary group of dm, the outward unit normal its faces share in the mesh as built (coords0), or zero
 *  where they do not share one (a curved or folded boundary); the same on any partition. Collective. */
std::vector<std::array<double, 3>> flatBoundaryNormals(const DistributedMesh& dm, MPI_Comm comm);

} // namespace unilag
