/*! \file GasRun.hpp
 *  \brief A tube scene with a `gas:` section: the gas in a rigid tube (TubeGas), or with `gas.wall:` in an expandable
 *  tube (GasWallCoupling), driven by the shared time loop, the tube written as an XDMF polyline with per-cell
 *  density, pressure, velocity, Mach number, area, radius and wall speed, and summary.json with mass and energy (gas +
 *  wall), the leading shock measured from the run and, for a rigid Riemann problem, L1(density) against the exact
 *  solution. Rank 0 runs it; the other ranks wait.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include "tube/TubeScene.hpp"

namespace unilag
{

/*! Runs the scene's gas (the scene is read and its output folder checked). check: mass and energy (gas + wall +
 *  the wall's viscous loss) to 1e-10 relative with both ends walls, L1(density) within gas.check.l1_density when
 *  given, state finite. Returns the exit code. */
int runTubeGas(const tube::TubeScene& scene, bool check, MPI_Comm comm);

} // namespace unilag
