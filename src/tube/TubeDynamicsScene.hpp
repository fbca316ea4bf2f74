/*! \file TubeDynamicsScene.hpp
 *  \brief The `dynamics:` section of a tube scene: a nonlinear time run of the physical tube (src/tube/TubeDynamics)
 *  instead of the linear stability study. SI units; the flow speed is given in m/s or as a fraction of the linear
 *  critical speed of the same tube (tube.md 2.1), so that a flutter run reads "1.02 u_cf".
 */
#pragma once

#include <array>
#include <cmath>

namespace unilag::config
{
class ConfigNode;
}

namespace unilag::tube
{

struct DynamicsSettings
{
    int segments = 100;              //!< rod segments along the tube
    double endTime = 1.0;            //!< s
    double stepFactor = 0.9;         //!< the time step as a fraction of the explicit stable step
    double flowSpeed = 0.0;          //!< U, m/s (resolved from criticalFraction when that is given)
    double criticalFraction = NAN;   //!< U / U_cf when the scene gives the speed so (NaN: flow.speed in m/s)
    std::array<double, 3> tipVelocity{0.0, 1e-3, 0.0}; //!< initial perturbation: node velocity = this x shape(s)
    std::array<double, 3> gravity{0.0, 0.0, 0.0};      //!< m/s^2
    double outputInterval = 0.0;     //!< s between XDMF dumps (0: the first and last state only)
    int tipRows = 20000;             //!< at most this many rows in tip.csv (every step is kept for the fit)
    double fitFrom = 0.3;            //!< the growth rate is fitted on the tip's peaks after this fraction of the run
    double fitBelow = 0.01;          //!< ... and below this tip amplitude / length (the linear phase)
};

/*! Reads `dynamics:` of a scene whose physical tube is known (the caller checks that); every key is validated.
 *  Throws InputError naming the file and key. */
DynamicsSettings readDynamics(config::ConfigNode& dynamics);

} // namespace unilag::tube
