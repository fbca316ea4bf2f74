/*! \file Repartition.hpp
 *  \brief The partition of a moving mesh, recomputed from where its cells are now and what they cost: Zoltan2's
 *  multijagged (or rcb) on the owned cells' current centroids, weighted by each cell's measured cost, or ranges of
 *  equal cost along the cells' space-filling curve. The mesh and fields then move with DistributedMesh::rebuild and
 *  FieldSet::migrate.
 */
#pragma once

#include <string>
#include <vector>

#include "core/Types.hpp"
#include "mesh/DistributedMesh.hpp"

namespace unilag
{

/*! \brief The rank to own each owned cell next. Collective.
 *  \param coords current node coordinates, D or 3 columns, on mesh.nodeMapOverlap (all local nodes)
 *  \param cost one positive weight per owned cell (the time it is expected to take per step, in any unit)
 *  \param algorithm Zoltan2's "multijagged" (as the start-up partition) or "rcb", or "sfc": ranges of global ids of
 *  equal cost (a space-filling-curve partition: the ids follow a Morton curve of the initial cells)
 *  The parts balance the summed cost to Zoltan2's imbalance tolerance (1.05). Deterministic: the same input on the
 *  same ranks gives the same owners. */
std::vector<int> balancedOwners(const DistributedMesh& mesh, const MV& coords, const std::vector<double>& cost,
                                const std::string& algorithm = "multijagged");

//! The largest part's share of a cost over its mean: max_p W_p / mean_p W_p, W_p the cost on rank p. Collective.
double costImbalance(const DistributedMesh& mesh, const std::vector<double>& cost);

} // namespace unilag
