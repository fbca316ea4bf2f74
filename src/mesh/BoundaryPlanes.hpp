/*! \file BoundaryPlanes.hpp
 *  \brief Which boundary groups are made of planes: the fixed normals a slip wall or symmetry plane imposes
 *  (wallNormal in Physics.hpp), found once from the mesh as built.
 */
#pragma once

#include <array>
#include <vector>

#include "core/Mpi.hpp"
#include "mesh/DistributedMesh.hpp"

namespace unilag
{

/*! For each boundary group of dm, the outward unit normals of the planes its faces lie in, in the mesh as built
 *  (coords0): one for a flat wall, several for a box's walls in one group, none where the faces lie in more than
 *  maxPlanes planes (a curved boundary). Each plane's normal is that of its face of lowest (global cell id, local
 *  face), so the list is the same on any partition, bit for bit. Collective. */
std::vector<std::vector<std::array<double, 3>>> flatBoundaryPlanes(const DistributedMesh& dm, MPI_Comm comm,
                                                                   int maxPlanes);

} // namespace unilag
