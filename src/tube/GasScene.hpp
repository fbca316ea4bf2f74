/*! \file GasScene.hpp
 *  \brief The `gas:` section of a tube scene: the compressible gas in a rigid tube (TubeGas, docs/tube-gas.md) run
 *  through the shared time loop instead of the rod; with a `gas.wall:` section, in an expandable tube
 *  (GasWallCoupling, docs/tube-wall.md 6); with a `gas.rod:` section, in a free tube that the gas moves
 *  (GasRodCoupling, docs/tube-gas-rod.md). Dimensionless or SI, as the scene's numbers are.
 */
#pragma once

#include <array>
#include <cmath>

#include "tube/TubeGas.hpp"
#include "tube/TubeWall.hpp"

namespace unilag::config
{
class ConfigNode;
}

namespace unilag::tube
{

//! `gas.wall:` the expandable wall (docs/tube-wall.md 6). Its rest radius is the gas's radius (area pi R0^2).
struct GasWallSettings
{
    bool enabled = false;
    WallMaterial material;        //!< E, nu, h, rho_w, R0, viscosity, axial tension N_x
    double outsidePressure = 0.0; //!< p_ext
    double ramp = 0.0;            //!< width of the tanh blend of the initial left/right states (0: a jump)
    WallCoefficients coefficients() const { return wallCoefficients(material, outsidePressure); }
};

enum class EndCondition; // TubeScene.hpp (which includes this header)

/*! `gas.rod:` the tube is a Cosserat rod (TubeDynamics) moved by its gas (GasRodCoupling). Its material keys are
 *  the tube scene's (`tube:`), its length is gas.length, its segments are the gas's cells and the gas's
 *  cross-section is pi Ri^2 (a rigid radius). */
struct GasRodSettings
{
    bool enabled = false;
    double outerRadius = 0.0, innerRadius = 0.0;
    double youngsModulus = 0.0, poissonRatio = 0.3, density = 0.0, shearCoefficient = 0.5;
    EndCondition left{}, right{};          //!< the rod's ends (readGas sets them; the gas's ends stay walls)
    double outsidePressure = 0.0;          //!< p_ext on the tube's outside
    std::array<double, 3> velocity{0, 0, 0}; //!< perturbation.velocity: the transverse velocity's amplitude
    double rodStepFactor = 1.0;            //!< of the rod's stable sub-step (GasRodSetup::rodStepFactor)
    double energyBound = 1e-4;             //!< check.energy: --check's bound on max |E/E0 - 1| over the run
    double area() const { return 3.14159265358979323846 * innerRadius * innerRadius; }
};

struct GasSettings
{
    GasSetup setup;           //!< length, cells, gamma, cfl, limiter, ends
    bool riemann = false;     //!< initial: left and right states about `position` (else uniform)
    double position = 0.5;    //!< where the Riemann problem's discontinuity starts
    GasPrimitive left, right; //!< the Riemann states (uniform: both the same)
    double endTime = 0.2;
    double outputInterval = 0.0; //!< 0: first and last state only
    double l1Bound = NAN;        //!< check.l1_density: --check's bound on L1(rho) against RiemannExact (NaN: none)
    GasWallSettings wall;        //!< `wall:` given: the tube is expandable, the wall on the quasi-static law at t = 0
    GasRodSettings rod;          //!< `rod:` given: the tube is a free rod that the gas moves
    /*! A uniform gas with a fixed_state left end is the Riemann problem (that state, the gas) at s = 0 as long as
     *  no wave runs left out of it (a supersonic inflow, or the post-shock state of a shock into the gas). */
    bool inflowProblem() const { return !riemann && setup.left.type == GasEndType::FixedState; }
    //! There is an exact solution to compare with (L1, shock speed): a rigid tube only.
    bool hasReference() const { return !wall.enabled && !rod.enabled && (riemann || inflowProblem()); }
    //! The initial gas state at s: the uniform state, or the Riemann states (a tanh blend of width wall.ramp).
    GasPrimitive initialState(double s) const;
    //! Both ends closed: mass and energy are conserved to round-off (--check).
    bool closed() const { return setup.left.type == GasEndType::Wall && setup.right.type == GasEndType::Wall; }
};

const char* gasEndName(GasEndType type);

//! Reads `gas:`; every key is validated. Throws InputError naming the file and key.
GasSettings readGas(config::ConfigNode& gas);

} // namespace unilag::tube
