/*! \file GasWallCoupling.hpp
 *  \brief Gas in a straight tube with an expandable wall R(s, t) (rod rigid): Strang splitting of the gas
 *  transport at frozen areas (TubeGas, SSP-RK2) and a per-cell exchange step in which the wall and the gas's
 *  internal energy trade energy exactly (discrete gradient; with axial tension the cells are coupled and the
 *  step solves one tridiagonal Newton system per half step). Total energy gas + wall is conserved to the
 *  Newton tolerance and round-off with closed ends; docs/tube-wall.md.
 */
#pragma once

#include <functional>

#include "tube/TubeGas.hpp"
#include "tube/TubeWall.hpp"

namespace unilag::tube
{

//! Energy of the coupled system (times h, summed): gas E, wall parts; total = gas + kinetic + elastic + outside,
//! and total + dissipated is what the step conserves.
struct CoupledEnergy
{
    double gas = 0;
    WallEnergy wall;
    double total() const { return gas + wall.kinetic + wall.elastic + wall.outside + wall.tension; }
};

class GasWallCoupling
{
  public:
    /*! wallResolution: the step is at most wallResolution / omega_max, omega = ((W'' + 4 as/h^2)/a)^(1/2) the
     *  wall's own frequency bound (the exchange is stable for any step, but a wall oscillation needs steps to be
     *  resolved). */
    GasWallCoupling(const GasSetup& gas, const WallCoefficients& wall, double wallResolution = 0.3);

    //! Wall radius and speed, then the gas primitives (per volume) at the cell centres; the areas pi R^2.
    void setState(
        const std::function<double(double s)>& radius, const std::function<GasPrimitive(double s)>& gas,
        const std::function<double(double s)>& wallSpeed = [](double) { return 0.0; });
    double stableStep() const; //!< min(gas CFL step, wallResolution / omega_max)
    void step(double dt);      //!< exchange dt/2, gas transport dt, exchange dt/2
    int advanceTo(double tEnd);
    double time() const;

    double mass() const;
    CoupledEnergy energy() const;
    const TubeGas& gas() const;
    const TubeWall& wall() const;

  private:
    void exchange(double dt);
    TubeGas gas_;
    TubeWall wall_;
    double gamma_, wallResolution_;
    bool serial_; // GasSetup::serialBelow
};

} // namespace unilag::tube
