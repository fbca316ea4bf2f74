/*! \file GasRun.hpp
 *  \brief A tube scene with a `gas:` section: the gas in a rigid tube (TubeGas), or with `gas.wall:` in an expandable
 *  tube (GasWallCoupling), driven by the shared time loop, the tube written as an XDMF polyline with per-cell
 *  density, pressure, velocity, Mach number, area, radius and wall speed, and summary.json with mass and energy (gas +
 *  wall), the leading shock measured from the run and, for a rigid Riemann problem, L1(density) against the exact
 *  solution. With `gas.rod:` the free tube that the gas moves runs instead (GasRodRun). Rank 0 runs it; the other
 *  ranks wait.
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include <vector>

#include "tube/TubeScene.hpp"

namespace unilag
{

namespace tube
{
//! A Riemann problem's exact right-running shock, where the runs locate and time theirs.
struct ExactReference
{
    bool exists = false, shock = false; //!< shock: the exact solution has a right-running shock
    double shockLevel = NAN;            //!< pressure halfway up the shock, where it is located in the run
    double shockSpeed = NAN;            //!< exact speed of that shock (into the right state)
};

//! The exact solution of (left, right) in a rigid tube: its right wave, a shock when p* > p_R (1 + 1e-3).
ExactReference riemannShock(const GasPrimitive& left, const GasPrimitive& right, double gamma);

//! Least-squares slope of x(t) over the samples with t >= endTime / 2 (the shock has formed and settled); NaN
//! with fewer than two.
double secondHalfSpeed(const std::vector<double>& t, const std::vector<double>& x, double endTime);
} // namespace tube

/*! Runs the scene's gas (the scene is read and its output folder checked). check: mass and energy (gas + wall +
 *  the wall's viscous loss) to 1e-10 relative with both ends walls, L1(density) within gas.check.l1_density when
 *  given, state finite. Returns the exit code. */
int runTubeGas(const tube::TubeScene& scene, bool check, MPI_Comm comm);

} // namespace unilag
