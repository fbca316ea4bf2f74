/*! \file GprPeak.hpp
 *  \brief The largest cell density of a run (summary.json `largest_density`; the --check bound exact.max_density).
 *  A strong shock compresses an ideal gas to at most (gamma + 1) / (gamma - 1) times its density, and a scheme that
 *  overshoots at a front shows it there first (docs/sedov-peak.md); dumps every 0.1 miss most of it. Each rank
 *  keeps its record after every accepted step (one reduction, with the cell and its centroid); the ranks' records
 *  combine at the end by the largest value, then the earliest time, then the lowest global id, so that the record is
 *  the same on any number of ranks and threads (owned cells are sorted by global id).
 */
#pragma once

#include <vector>

#include "core/Mpi.hpp"
#include "solver/GprModel.hpp"
#include "unilag/Reduce.hpp"

namespace unilag
{

struct DensityPeak
{
    double value = 0.0;                   //!< the largest cell density so far
    double t = 0.0;                       //!< the time it was reached (the end of its step)
    GO cell = -1;                         //!< the cell's global id
    double centroid[3] = {0.0, 0.0, 0.0}; //!< where the cell was then

    //! As the checkpoint stores it: value, t, cell, centroid (3).
    std::vector<double> numbers() const { return {value, t, double(cell), centroid[0], centroid[1], centroid[2]}; }
    static DensityPeak from(const std::vector<double>& n)
    {
        DensityPeak p;
        p.value = n.at(0);
        p.t = n.at(1);
        p.cell = GO(n.at(2));
        for (int d = 0; d < 3; ++d)
            p.centroid[d] = n.at(3 + d);
        return p;
    }
};

//! Raises this rank's record `peak` to the owned cells' largest density of the state at time t (one pass).
template <int D, class P> void notePeakDensity(const GprModel<D, P>& md, double t, DensityPeak& peak)
{
    const ConstField state = md.read("state");
    const auto centroid = md.geom.centroid;
    constexpr int omega = StateLayout<D, P>::omega;
    double r[2 + D]; // density, local index, centroid
    largestAt<D>("unilag::check::largest_density", md.m.nOwnedCells, KOKKOS_LAMBDA(const LO i, double(&c)[D]) {
        for (int d = 0; d < D; ++d)
            c[d] = centroid(i, d);
        return 1.0 / state(i, omega);
    }, r);
    if (!(r[0] > peak.value))
        return;
    peak.value = r[0];
    peak.t = t;
    peak.cell = md.mesh->cellGid[LO(r[1])];
    for (int d = 0; d < 3; ++d)
        peak.centroid[d] = d < D ? r[2 + d] : 0.0;
}

//! The run's record from every rank's: the largest value, then the earliest time, then the lowest id. Collective.
inline DensityPeak combinedPeak(MPI_Comm comm, const DensityPeak& mine)
{
    const double value = mpi::allMax(comm, mine.value);
    const bool has = mine.value == value && mine.cell >= 0;
    const double t = mpi::allMin(comm, has ? mine.t : 1e300);
    const bool first = has && mine.t == t;
    const int owner = mpi::argMinRank(comm, first ? double(mine.cell) : 1e300);
    std::vector<double> n = mine.numbers();
    if (mpi::rank(comm) != owner)
        n.assign(n.size(), 0.0);
    mpi::allSum(comm, n.data(), int(n.size()));
    return DensityPeak::from(n);
}

} // namespace unilag
