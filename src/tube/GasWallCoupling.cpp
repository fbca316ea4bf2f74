#include "tube/GasWallCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tube/SmallLaunch.hpp"
#include "unilag/TubeWall.hpp"

namespace unilag::tube
{

using namespace unilag::wall;
using launch::forEach; // small tubes run on Kokkos::Serial (GasSetup::serialBelow)
using launch::reduce;

namespace
{

WallParams params(const WallCoefficients& c)
{
    return WallParams{c.a, c.b, c.c, c.restRadius, c.pExt, c.as};
}

} // namespace

GasWallCoupling::GasWallCoupling(const GasSetup& gas, const WallCoefficients& wall, double wallResolution)
    : gas_(gas), wall_(wall, gas.cells, gas.length, gas.cells < gas.serialBelow), gamma_(gas.gamma),
      wallResolution_(wallResolution), serial_(gas.cells < gas.serialBelow)
{
    if (!(wallResolution > 0.0))
        throw std::invalid_argument("GasWallCoupling: wallResolution must be > 0");
}

void GasWallCoupling::setState(const std::function<double(double)>& radius,
                               const std::function<GasPrimitive(double)>& gas,
                               const std::function<double(double)>& wallSpeed)
{
    wall_.setState(radius, wallSpeed);
    const gas::GasViews g = gas_.deviceViews();
    const WallViews w = wall_.deviceViews();
    const int n = gas_.cells();
    forEach("wall cell areas", n, serial_, CellAreasFromRadius{g.areaCell, w.radius});
    forEach("wall face areas", n + 1, serial_, FaceAreasFromCells{g.areaFace, g.areaCell, n});
    gas_.setState(gas); // per unit length with the areas just set
}

//! The per-cell exchange over dt, then the face areas from the new cell areas.
void GasWallCoupling::exchange(double dt)
{
    const gas::GasViews g = gas_.deviceViews();
    const WallViews w = wall_.deviceViews();
    const int n = gas_.cells();
    const WallParams p = params(wall_.coefficients());
    if (p.as > 0.0) // one work item: a Thomas sweep along the tube (kernels/unilag/TubeWall.hpp)
        forEach("wall exchange tension", 1, serial_,
                WallExchangeTension{g.q, g.areaCell, w.radius, w.speed, w.dissipated, w.step, w.cPrime, w.rPrime, p,
                                    gamma_, dt, gas_.spacing(), n});
    else
        forEach("wall exchange", n, serial_,
                WallExchange{g.q, g.areaCell, w.radius, w.speed, w.dissipated, p, gamma_, dt});
    forEach("wall face areas", n + 1, serial_, FaceAreasFromCells{g.areaFace, g.areaCell, n});
}

/*! Strang splitting: each part conserves the total energy by itself (transport: fluxes telescope at frozen
 *  areas, the wall untouched; exchange: the discrete gradient), and the symmetric order makes it second order. */
void GasWallCoupling::step(double dt)
{
    exchange(0.5 * dt);
    gas_.step(dt);
    exchange(0.5 * dt);
}

double GasWallCoupling::stableStep() const
{
    const gas::GasViews g = gas_.deviceViews();
    const WallViews w = wall_.deviceViews();
    double omega = 0.0;
    reduce("wall max frequency", gas_.cells(), serial_,
           MaxWallFrequency{g.q, w.radius, params(wall_.coefficients()), gamma_, gas_.spacing()},
           Kokkos::Max<double>(omega));
    return std::min(gas_.stableStep(), wallResolution_ / omega);
}

int GasWallCoupling::advanceTo(double tEnd)
{
    int steps = 0;
    while (time() < tEnd * (1.0 - 1e-14))
    {
        const double dt = stableStep();
        if (!(dt > 0.0) || !std::isfinite(dt)) // a NaN state would otherwise loop here for ever
            throw std::runtime_error("GasWallCoupling::advanceTo: no valid step (NaN or non-positive state)");
        step(std::min(dt, tEnd - time()));
        ++steps;
    }
    return steps;
}

double GasWallCoupling::time() const
{
    return gas_.time();
}
double GasWallCoupling::mass() const
{
    return gas_.mass();
}

CoupledEnergy GasWallCoupling::energy() const
{
    CoupledEnergy e;
    e.gas = gas_.energy();
    e.wall = wall_.energy();
    return e;
}

const TubeGas& GasWallCoupling::gas() const
{
    return gas_;
}
const TubeWall& GasWallCoupling::wall() const
{
    return wall_;
}

} // namespace unilag::tube
