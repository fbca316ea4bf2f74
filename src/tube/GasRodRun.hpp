/*! \file GasRodRun.hpp
 *  \brief A tube scene with `gas.rod:`: the free tube (a Cosserat rod) filled with gas that moves it
 *  (GasRodCoupling, docs/tube-gas-rod.md), driven by the shared time loop. tube.xmf: the rod's centreline as a 3D
 *  polyline (cells = segments) with per cell density, pressure, velocity relative to the tube, Mach number, area
 *  and radius, per node the rod's velocity; summary.json: mass, total momentum and energy (rod + gas) with their
 *  changes, and the leading shock's position and speed until it reaches the right end cap. Rank 0 runs it.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include "tube/TubeScene.hpp"

namespace unilag
{

/*! Runs the scene's free tube. check: mass to 1e-12 relative, total momentum (both rod ends free) to 1e-12 of
 *  its scale sqrt(2 E0 (wall + gas mass)), max |E/E0 - 1| over the run within gas.check.energy. Returns the exit
 *  code. */
int runTubeGasRod(const tube::TubeScene& scene, bool check, MPI_Comm comm);

} // namespace unilag
