/*! \file TubeDynamicsState.hpp
 *  \brief Private to TubeDynamics*.cpp: the solver's state and host helpers. */
#pragma once

#include <cmath>

#include "tube/SmallLaunch.hpp"
#include "tube/TubeDynamics.hpp"
#include "unilag/TubeRod.hpp"

namespace unilag::tube
{

using namespace unilag::rod;

namespace dynamics_detail
{

using launch::forEach; // rods under RodSetup::serialBelow nodes run on Kokkos::Serial
using launch::scan;

inline int endFlags(EndCondition e)
{
    switch (e)
    {
    case EndCondition::Clamped:
        return 3;
    case EndCondition::Pinned:
        return 1;
    case EndCondition::Free:
        return 0;
    }
    return 0;
}

inline RodParams rodParams(const RodConstants& c, double h)
{
    RodParams p;
    p.h = h;
    const double j[3] = {c.torsion, c.bending, c.bending}, l[3] = {c.extension, c.shear, c.shear};
    for (int a = 0; a < 3; ++a)
    {
        p.J[a] = j[a];
        p.L[a] = l[a];
        p.rest[a] = c.restCurvature[a];
    }
    return p;
}

inline M3 identity()
{
    M3 m;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            m.a[a][b] = a == b ? 1.0 : 0.0;
    return m;
}

//! The minimal rotation taking unit vector u to unit vector w (exactly orthogonal in exact arithmetic).
inline M3 alignRotation(const V3& u, const V3& w)
{
    const V3 k = cross(u, w);
    const double c = dot(u, w);
    const double f = 1.0 / (1.0 + c);
    M3 q;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            q.a[a][b] = (a == b ? c : 0.0) + f * k[a] * k[b];
    q.a[0][1] -= k[2];
    q.a[1][0] += k[2];
    q.a[0][2] += k[1];
    q.a[2][0] -= k[1];
    q.a[1][2] -= k[0];
    q.a[2][1] += k[0];
    return q;
}

inline V3 toV3(const std::array<double, 3>& a) { return v3(a[0], a[1], a[2]); }
inline std::array<double, 3> toArray(const V3& v) { return {v[0], v[1], v[2]}; }

} // namespace dynamics_detail

struct TubeDynamics::State
{
    RodConstants c;
    RodSetup setup;
    RodParams p;
    int n = 0; // segments
    double t = 0.0;
    int leftFlags = 0, rightFlags = 0;
    bool serial = false; // kernels on Kokkos::Serial (RodSetup::serialBelow)
    Vec3View r, v, spin, force, torque;
    Mat3View lam;
    ScalarView mass, rotary;
    Vec3View segForce, segTorqueLeft, segTorqueRight, tangent, vA, vB; // vA, vB: Coriolis sweeps
    ScalarView pressureStep, pressure;

    bool screw = false;               // RodSetup::screwPeriodic
    M3 screwRotation = dynamics_detail::identity(); // R_g
    V3 screwShift = v3(0, 0, 0);      // d_g
    int dynamicNodes() const { return screw ? n : n + 1; } // node N of a screw-periodic rod is an image

    int flags(int j) const { return j == 0 ? leftFlags : (j == n ? rightFlags : 0); }
    bool flowing() const { return c.fluidMass > 0.0 && setup.flowSpeed != 0.0; }
};

} // namespace unilag::tube
