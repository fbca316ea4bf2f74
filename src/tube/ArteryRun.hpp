/*! \file ArteryRun.hpp
 *  \brief A tube scene with an `artery:` section: one 1D artery (Artery) driven by the shared time loop for a number
 *  of inlet periods; waveforms.csv with pressure and flow at inlet, middle and outlet, the vessel as an XDMF polyline
 *  with per-cell area, flow, pressure and velocity, and summary.json (cycles to periodicity, mean pressures). Rank 0
 *  runs it; the other ranks wait.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include "tube/TubeScene.hpp"

namespace unilag
{

/*! Runs the scene's artery. check: the volume balance (V - V0 = inflow - outflow) to 1e-10 relative, the run
 *  periodic within artery.periodic_tolerance by its last cycle, state finite. Returns the exit code. */
int runTubeArtery(const tube::TubeScene& scene, bool check, MPI_Comm comm);

} // namespace unilag
