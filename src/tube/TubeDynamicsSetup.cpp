// TubeDynamics: construction and initial state (the rest shape, screw-periodic closure, initial data).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tube/TubeDynamicsState.hpp"

namespace unilag::tube
{

using namespace dynamics_detail;

TubeDynamics::TubeDynamics(const RodConstants& constants, const RodSetup& setup) : s_(std::make_unique<State>())
{
    if (setup.segments < 2)
        throw std::invalid_argument("TubeDynamics: at least 2 segments");
    if (!(constants.wallRotary > 0.0) || !(constants.wallMass + constants.fluidMass > 0.0))
        throw std::invalid_argument("TubeDynamics: wallRotary and wallMass + fluidMass must be > 0 (explicit)");
    State& s = *s_;
    s.c = constants;
    s.setup = setup;
    s.n = setup.segments;
    const int nn = s.n + 1;
    const double h = constants.length / s.n;
    s.p = rodParams(constants, h);
    s.screw = setup.screwPeriodic;
    if (s.screw && constants.fluidMass > 0.0 && setup.flowSpeed != 0.0)
        throw std::invalid_argument("TubeDynamics: screw-periodic ends without flow only");
    s.leftFlags = s.screw ? 0 : endFlags(setup.left);
    s.rightFlags = s.screw ? 0 : endFlags(setup.right);
    s.serial = nn < setup.serialBelow;
    s.r = Vec3View("tube r", nn);
    s.v = Vec3View("tube v", nn);
    s.spin = Vec3View("tube pi", nn);
    s.force = Vec3View("tube F", nn);
    s.torque = Vec3View("tube T", nn);
    s.lam = Mat3View("tube Lambda", nn);
    s.mass = ScalarView("tube mass", nn);
    s.rotary = ScalarView("tube rotary", nn);
    s.segForce = Vec3View("tube segment force", s.n);
    s.segTorqueLeft = Vec3View("tube segment torque left", s.n);
    s.segTorqueRight = Vec3View("tube segment torque right", s.n);
    s.tangent = Vec3View("tube tangent", s.n);
    s.vA = Vec3View("tube v sweep A", nn);
    s.vB = Vec3View("tube v sweep B", nn);
    s.pressureStep = ScalarView("tube dpA", s.n);
    s.pressure = ScalarView("tube pA", nn);

    auto r = Kokkos::create_mirror_view(s.r);
    auto lam = Kokkos::create_mirror_view(s.lam);
    auto mass = Kokkos::create_mirror_view(s.mass);
    auto rotary = Kokkos::create_mirror_view(s.rotary);
    // The rest helix (both ends free): Lambda_{j+1} = Lambda_j cay(h Omega_rest) makes Omega_j = Omega_rest
    // exactly, and Gamma_j = e1 fixes the chord: Lambda_j^T (r_{j+1} - r_j) = 2 h (I + R^T)^{-1} e1.
    // Screw-periodic: the same helix; its node N, frame R_g and position d_g (node 0 at the identity), is g.
    const bool helix = s.screw || (setup.left == EndCondition::Free && setup.right == EndCondition::Free);
    const V3 restStep = helix ? h * toV3(constants.restCurvature) : v3(0, 0, 0);
    const M3 R = cayley(restStep);
    M3 S; // I + R^T
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            S.a[a][b] = (a == b ? 1.0 : 0.0) + R.a[b][a];
    const double det = S.a[0][0] * (S.a[1][1] * S.a[2][2] - S.a[1][2] * S.a[2][1]) -
                       S.a[0][1] * (S.a[1][0] * S.a[2][2] - S.a[1][2] * S.a[2][0]) +
                       S.a[0][2] * (S.a[1][0] * S.a[2][1] - S.a[1][1] * S.a[2][0]);
    // first column of S^{-1} (cofactors), times 2h
    const V3 bodyChord = (2.0 * h / det) * v3(S.a[1][1] * S.a[2][2] - S.a[1][2] * S.a[2][1],
                                              S.a[1][2] * S.a[2][0] - S.a[1][0] * S.a[2][2],
                                              S.a[1][0] * S.a[2][1] - S.a[1][1] * S.a[2][0]);
    M3 frame = identity();
    V3 pos = v3(0, 0, 0);
    for (int j = 0; j < nn; ++j)
    {
        const double w = (!s.screw && (j == 0 || j == s.n)) ? 0.5 : 1.0;
        mass(j) = (constants.wallMass + constants.fluidMass) * h * w;
        rotary(j) = constants.wallRotary * h * w;
        for (int a = 0; a < 3; ++a)
        {
            r(j, a) = pos[a];
            for (int b = 0; b < 3; ++b)
                lam(j, a, b) = frame.a[a][b];
        }
        pos = pos + mul(frame, bodyChord);
        frame = mul(frame, R);
    }
    if (s.screw)
    {
        for (int a = 0; a < 3; ++a)
        {
            s.screwShift[a] = r(s.n, a);
            for (int b = 0; b < 3; ++b)
                s.screwRotation.a[a][b] = lam(s.n, a, b);
        }
    }
    Kokkos::deep_copy(s.r, r);
    Kokkos::deep_copy(s.lam, lam);
    Kokkos::deep_copy(s.mass, mass);
    Kokkos::deep_copy(s.rotary, rotary);
}

void TubeDynamics::setVelocity(const std::function<std::array<double, 3>(double s)>& vel)
{
    State& s = *s_;
    auto v = Kokkos::create_mirror_view(s.v);
    for (int j = 0; j <= s.n; ++j)
    {
        const auto x = vel(j * s.p.h);
        for (int a = 0; a < 3; ++a)
            v(j, a) = positionFixed(s.flags(j)) ? 0.0 : x[a];
    }
    Kokkos::deep_copy(s.v, v);
    closeScrew();
}

void TubeDynamics::setSpin(const std::function<std::array<double, 3>(double s)>& omega)
{
    State& s = *s_;
    auto pi = Kokkos::create_mirror_view(s.spin);
    auto rotary = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.rotary);
    for (int j = 0; j <= s.n; ++j)
    {
        const auto w = omega(j * s.p.h);
        const double inertia[3] = {2.0 * rotary(j), rotary(j), rotary(j)};
        for (int a = 0; a < 3; ++a)
            pi(j, a) = rotationFixed(s.flags(j)) ? 0.0 : inertia[a] * w[a];
    }
    Kokkos::deep_copy(s.spin, pi);
    closeScrew();
}

void TubeDynamics::displace(const std::function<std::array<double, 3>(double s)>& dr)
{
    State& s = *s_;
    auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.r);
    auto lam = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.lam);
    for (int j = 0; j <= s.n; ++j)
    {
        if (positionFixed(s.flags(j)))
            continue;
        const auto d = dr(j * s.p.h);
        for (int a = 0; a < 3; ++a)
            r(j, a) += d[a];
    }
    if (s.screw) // the image of node 0, for node N-1's tangent
    {
        const V3 image = mul(s.screwRotation, v3(r(0, 0), r(0, 1), r(0, 2))) + s.screwShift;
        for (int a = 0; a < 3; ++a)
            r(s.n, a) = image[a];
    }
    for (int j = 0; j < s.dynamicNodes(); ++j)
    {
        if (rotationFixed(s.flags(j)))
            continue;
        const int lo = std::max(j - 1, 0), hi = std::min(j + 1, s.n);
        V3 t = v3(r(hi, 0) - r(lo, 0), r(hi, 1) - r(lo, 1), r(hi, 2) - r(lo, 2));
        t = (1.0 / std::sqrt(dot(t, t))) * t;
        M3 frame;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                frame.a[a][b] = lam(j, a, b);
        const M3 turned = mul(alignRotation(v3(frame.a[0][0], frame.a[1][0], frame.a[2][0]), t), frame);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                lam(j, a, b) = turned.a[a][b];
    }
    Kokkos::deep_copy(s.r, r);
    Kokkos::deep_copy(s.lam, lam);
    closeScrew();
}

void TubeDynamics::perturbBody(const std::function<std::array<double, 6>(double s)>& sigmaPsi)
{
    State& s = *s_;
    auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.r);
    auto lam = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.lam);
    for (int j = 0; j < s.dynamicNodes(); ++j)
    {
        const auto x = sigmaPsi(j * s.p.h);
        M3 frame;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                frame.a[a][b] = lam(j, a, b);
        if (!positionFixed(s.flags(j)))
        {
            const V3 d = mul(frame, v3(x[3], x[4], x[5]));
            for (int a = 0; a < 3; ++a)
                r(j, a) += d[a];
        }
        if (!rotationFixed(s.flags(j)))
        {
            const M3 inc = mul(frame, expSO3MinusI(v3(x[0], x[1], x[2])));
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    lam(j, a, b) = frame.a[a][b] + inc.a[a][b];
        }
    }
    Kokkos::deep_copy(s.r, r);
    Kokkos::deep_copy(s.lam, lam);
    closeScrew();
}

void TubeDynamics::closeScrew()
{
    State& s = *s_;
    if (!s.screw)
        return;
    forEach("tube screw image", 1, s.serial,
            ScrewImage{s.lam, s.r, s.v, s.spin, s.screwRotation, s.screwShift, s.n});
}

} // namespace unilag::tube
