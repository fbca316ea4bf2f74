/*! \file GasRodCoupling.hpp
 *  \brief A free tube (the Cosserat rod of TubeDynamics) filled with compressible gas (TubeGas) that moves it:
 *  the gas sees the rod's stretch and velocity, the rod takes the gas's pressure and inertia, and total momentum
 *  is exchanged exactly. Strang splitting: rod (gas's xi, m, entropy held) dt/2, gas transport (rod frozen) dt,
 *  rod dt/2. Kernels in kernels/unilag/TubeGasRod.hpp; docs/tube-gas-rod.md.
 *
 *  The gas fills the rod's segments (cells = segments, closed ends: the end caps move with the rod). The wall
 *  radius is rigid (cross-section `area`), or with `wall` expandable (R per cell, tube.md 1.3; A = pi R^2, no
 *  axial tension a_s): then rod dt/2, wall exchange dt/2, gas dt, wall exchange dt/2, rod dt/2. The rod's
 *  RodConstants::fluidMass must be 0 (the gas is the fluid) and it has no plug flow.
 */
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "tube/TubeDynamics.hpp"
#include "tube/TubeGas.hpp"
#include "tube/TubeWall.hpp"
#include "unilag/TubeRod.hpp"

namespace unilag::tube
{

struct GasRodSetup
{
    RodConstants rod;
    RodSetup rodSetup;
    GasSetup gas;                 //!< cells and length are the rod's; both ends must be walls
    double area = 1.0;            //!< A, the gas's cross-section (rigid wall)
    double outsidePressure = 0.0; //!< p_ext
    //! An expandable wall (its a, b, c, R0; as must be 0 and pExt equal outsidePressure); A = pi R^2 then.
    std::optional<WallCoefficients> wall;
    double wallResolution = 0.3; //!< the step is at most this / the wall's frequency (as GasWallCoupling)
    //! The rod is sub-cycled at most at rodStepFactor x its stable step (TubeDynamics::stableStep) inside each
    //! coupled step, whose length the gas's CFL sets: scale both to refine the whole integrator in time.
    double rodStepFactor = 1.0;
};

//! Conserved totals of the coupled state: gas mass, total linear momentum (wall + gas), and the energy parts.
struct GasRodTotals
{
    double mass = 0;
    std::array<double, 3> momentum{0, 0, 0};
    double rodEnergy = 0;   //!< wall kinetic (translation, rotation) + elastic
    double gasKinetic = 0;  //!< the gas's kinetic energy in the lab frame
    double gasInternal = 0; //!< sum h xi e
    double outside = 0;     //!< p_ext sum h Q
    double wallKinetic = 0, wallElastic = 0, wallDissipated = 0; //!< the expandable wall's (0 without)
    double energy() const { return rodEnergy + gasKinetic + gasInternal + outside + wallKinetic + wallElastic; }
    double conserved() const { return energy() + wallDissipated; } //!< what the integrator keeps
};

class GasRodCoupling
{
  public:
    explicit GasRodCoupling(const GasRodSetup& setup);
    ~GasRodCoupling();

    //! The expandable wall's radius and speed at the cell centres (before setGas; default: at rest, R0).
    void setWall(const std::function<double(double s)>& radius, const std::function<double(double s)>& speed);
    /*! The gas's primitive state (u relative to the tube) at the cell centres, on the rod as it is now (set its
     *  velocities and displacements first through rod()). */
    void setGas(const std::function<GasPrimitive(double s)>& state);
    //! The gas's CFL step on the current metric (the rod is sub-cycled at its own stable step inside).
    double stableStep() const;
    void step(double dt);
    int advanceTo(double tEnd); //!< steps of stableStep(), the last shortened; returns their number
    double time() const;

    GasRodTotals totals() const;
    TubeDynamics& rod();
    const TubeDynamics& rod() const;
    const TubeGas& gas() const;
    /*! The metric (|Gamma|^2, Gamma.gamma, |gamma|^2) per cell as the gas sees it now (for the
     *  Rankine-Hugoniot relations of tube.md 1.8 evaluated on the solution). */
    std::vector<std::array<double, 3>> cellMetric() const;

  private:
    void rodPart(double tau);
    void gasPart(double tau);
    void wallPart(double tau);
    void kickFrom(const rod::Vec3View& start, double tau, bool spins);
    void updateMetric();
    void metricFrom(const rod::Vec3View& velocity); //!< the gas's metric with these node velocities
    void velocities();
    struct State;
    std::unique_ptr<State> s_;
};

} // namespace unilag::tube
