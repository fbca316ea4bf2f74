/*! \file PhysicalRod.hpp
 *  \brief The rod's constants per unit length from a physical tube (SI), shared by the tube's time run
 *  (TubeTimeRun) and the free tube filled with gas (GasRodRun), so that both scenes turn the same material keys
 *  into the same rod.
 */
#pragma once

#include <array>
#include <cmath>

#include "tube/TubeDynamics.hpp"

namespace unilag::tube
{

/*! tube.md 1.3: wall area A_w = pi (Ro^2 - Ri^2), I = pi (Ro^4 - Ri^4) / 4, J_p = 2 I, G = E / (2 (1 + nu)); the
 *  fluid's mass per length rho_f pi Ri^2 (0 for a tube whose fluid is coupled separately, as the gas). */
inline RodConstants rodConstants(const PhysicalTube& p, const std::array<double, 3>& gravity = {0.0, 0.0, 0.0})
{
    constexpr double pi = 3.14159265358979323846;
    const double areaWall = pi * (p.outerRadius * p.outerRadius - p.innerRadius * p.innerRadius);
    const double inertia = pi * (std::pow(p.outerRadius, 4) - std::pow(p.innerRadius, 4)) / 4.0;
    const double shearModulus = p.youngsModulus / (2.0 * (1.0 + p.poissonRatio));
    RodConstants c;
    c.length = p.length;
    c.extension = p.youngsModulus * areaWall;
    c.shear = p.shearCoefficient * shearModulus * areaWall;
    c.bending = p.youngsModulus * inertia;
    c.torsion = shearModulus * 2.0 * inertia;
    c.wallMass = p.wallDensity * areaWall;
    c.wallRotary = p.wallDensity * inertia;
    c.fluidMass = p.fluidMassPerLength();
    c.fluidArea = pi * p.innerRadius * p.innerRadius;
    c.gravity = gravity;
    return c;
}

} // namespace unilag::tube
