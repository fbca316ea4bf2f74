/*! \file GasScene.hpp
 *  \brief The `gas:` section of a tube scene: the compressible gas in a rigid tube (TubeGas, docs/tube-gas.md) run
 *  through the shared time loop instead of the rod. Dimensionless or SI, as the scene's numbers are.
 */
#pragma once

#include <cmath>

#include "tube/TubeGas.hpp"

namespace unilag::config
{
class ConfigNode;
}

namespace unilag::tube
{

struct GasSettings
{
    GasSetup setup;               //!< length, cells, gamma, cfl, limiter, ends
    bool riemann = false;         //!< initial: left and right states about `position` (else uniform)
    double position = 0.5;        //!< where the Riemann problem's discontinuity starts
    GasPrimitive left, right;     //!< the Riemann states (uniform: both the same)
    double endTime = 0.2;
    double outputInterval = 0.0;  //!< 0: first and last state only
    double l1Bound = NAN;         //!< check.l1_density: --check's bound on L1(rho) against RiemannExact (NaN: none)
    /*! A uniform gas with a fixed_state left end is the Riemann problem (that state, the gas) at s = 0 as long as
     *  no wave runs left out of it (a supersonic inflow, or the post-shock state of a shock into the gas). */
    bool inflowProblem() const { return !riemann && setup.left.type == GasEndType::FixedState; }
    //! There is an exact solution to compare with (L1, shock speed).
    bool hasReference() const { return riemann || inflowProblem(); }
    //! Both ends closed: mass and energy are conserved to round-off (--check).
    bool closed() const { return setup.left.type == GasEndType::Wall && setup.right.type == GasEndType::Wall; }
};

const char* gasEndName(GasEndType type);

//! Reads `gas:`; every key is validated. Throws InputError naming the file and key.
GasSettings readGas(config::ConfigNode& gas);

} // namespace unilag::tube
