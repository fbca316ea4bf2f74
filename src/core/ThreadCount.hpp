/*! \file ThreadCount.hpp
 *  \brief How many OpenMP threads each rank runs when the user does not say: the cores it may run on, shared with
 *  the other ranks of its node that may run on them. OpenMP threads that outnumber the cores spin at barriers: 4
 *  ranks of 2 threads on this 2-core machine ran the impact scene in 260 s, 4 ranks of 1 thread in about 4 s.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1 // C API only
#endif
#include <mpi.h>

#include <string>

namespace unilag
{

struct ThreadCount
{
    int threads = 1;     //!< threads for this rank
    std::string warning; //!< on world rank 0: its node runs more threads than CPUs, some rank more than one
};

/*! Threads for this rank: `requested` (from --threads) when positive, else OMP_NUM_THREADS when set, else the CPUs
 *  of this process' affinity mask divided among the ranks of the node whose masks overlap it (at least 1). Every
 *  rank must call it (collective on `world`). */
ThreadCount threadsPerRank(int requested, MPI_Comm world);

} // namespace unilag
