/*! \file TubeTimeRun.hpp
 *  \brief A nonlinear time run of a tube scene with a `dynamics:` section: the rod on SE(3) conveying fluid
 *  (TubeDynamics) driven by the shared time loop (solver/TimeLoop.hpp), the tube written as an XDMF polyline with
 *  per-node fields (ParaView: Extract Surface, then Tube), the tip's time series in tip.csv, and summary.json with the
 *  fitted growth rate next to the linear one at the same flow speed. Rank 0 runs it (threads do the parallel
 *  work: a tube has a few hundred nodes); the other ranks wait.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include "tube/TubeScene.hpp"

namespace unilag
{

/*! Runs the scene's dynamics (the scene is read and its output folder checked). check: energy kept (no flow,
 *  no gravity), rotations orthogonal, state finite. Returns the exit code (ExitOk, ExitCheck, ExitUnstable). */
int runTubeDynamics(const tube::TubeScene& scene, bool check, MPI_Comm comm);

} // namespace unilag
