/*! \file Mpi.hpp
 *  \brief The few MPI collectives the solvers need, in one place: the raw communicator of a Teuchos one,
 *  reductions over ranks, the exclusive prefix sum of global numbering, and the first error message of any rank.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1 // C API only
#endif
#include <mpi.h>

#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

namespace unilag::mpi
{

//! The MPI communicator behind a Teuchos one (MPI_COMM_SELF for a serial Teuchos comm).
MPI_Comm rawComm(const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

int rank(MPI_Comm comm);
int size(MPI_Comm comm);

/*! CPU seconds of this process, all its threads (CLOCK_PROCESS_CPUTIME_ID). The load balance measures work in CPU
 *  time, not wall time: ranks that share cores (more ranks than cores) would otherwise count the time the system
 *  ran another rank as their own work. */
double cpuSeconds();

/*! CPU seconds this process has spent in the collectives below and in the halo exchanges (FieldSet::halo), where a
 *  rank that finished its work early waits (Open MPI polls) for the others. A rank's busy time is its CPU time less
 *  this: the time loop's load balance compares the ranks' busy times (TimeLoop.cpp). */
double waitSeconds();

//! Adds the CPU time from construction to destruction to waitSeconds().
class WaitTimer
{
  public:
    WaitTimer() : t0_(cpuSeconds()) {}
    ~WaitTimer();
    WaitTimer(const WaitTimer&) = delete;
    WaitTimer& operator=(const WaitTimer&) = delete;

  private:
    double t0_;
};

double allMin(MPI_Comm comm, double v);
double allMax(MPI_Comm comm, double v);
//! The maximum of n values in place over the ranks.
void allMax(MPI_Comm comm, double* v, int n);
//! Sums n values in place over the ranks.
void allSum(MPI_Comm comm, double* v, int n);
//! Every rank's v (the same length on every rank), in rank order, on every rank.
std::vector<double> allGather(MPI_Comm comm, const std::vector<double>& v);
template <int N> void allSum(MPI_Comm comm, double (&v)[N])
{
    allSum(comm, v, N);
}

//! Exclusive prefix sum of n over the ranks (0 on rank 0): rank p's first global index. Collective.
long long exclusiveOffset(MPI_Comm comm, long long n);

//! The rank holding the smallest value (the lowest such rank on ties), the same on every rank. Collective.
int argMinRank(MPI_Comm comm, double v);

//! The first non-empty message over the ranks (by rank), the same on every rank. Collective.
std::string firstMessage(MPI_Comm comm, const std::string& local);

} // namespace unilag::mpi
