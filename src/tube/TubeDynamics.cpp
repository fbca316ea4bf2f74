#include "tube/TubeDynamics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "unilag/TubeRod.hpp"

namespace unilag::tube
{

using namespace unilag::rod;

namespace
{

int endFlags(EndCondition e)
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

//! parallel_for on the default execution space, or on Kokkos::Serial (small rods, host backends).
template <class Functor>
void forEach(const char* name, int n, bool serial, const Functor& f)
{
#if defined(KOKKOS_ENABLE_SERIAL)
    if constexpr (Kokkos::SpaceAccessibility<Kokkos::Serial, MemSpace>::accessible)
        if (serial)
        {
            Kokkos::parallel_for(name, Kokkos::RangePolicy<Kokkos::Serial>(0, n), f);
            return;
        }
#endif
    (void)serial;
    Kokkos::parallel_for(name, Kokkos::RangePolicy<ExecSpace>(0, n), f);
}

template <class Functor>
void scan(const char* name, int n, bool serial, const Functor& f)
{
#if defined(KOKKOS_ENABLE_SERIAL)
    if constexpr (Kokkos::SpaceAccessibility<Kokkos::Serial, MemSpace>::accessible)
        if (serial)
        {
            Kokkos::parallel_scan(name, Kokkos::RangePolicy<Kokkos::Serial>(0, n), f);
            return;
        }
#endif
    (void)serial;
    Kokkos::parallel_scan(name, Kokkos::RangePolicy<ExecSpace>(0, n), f);
}

RodParams rodParams(const RodConstants& c, double h)
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

M3 identity()
{
    M3 m;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            m.a[a][b] = a == b ? 1.0 : 0.0;
    return m;
}

//! The minimal rotation taking unit vector u to unit vector w (exactly orthogonal in exact arithmetic).
M3 alignRotation(const V3& u, const V3& w)
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

V3 toV3(const std::array<double, 3>& a) { return v3(a[0], a[1], a[2]); }
std::array<double, 3> toArray(const V3& v) { return {v[0], v[1], v[2]}; }

} // namespace

SegmentGradient segmentGradient(const RodConstants& c, double h, const std::array<double, 9>& A,
                                const std::array<double, 9>& B, const std::array<double, 3>& ra,
                                const std::array<double, 3>& rb)
{
    M3 a, b;
    for (int i = 0; i < 9; ++i)
    {
        a.a[i / 3][i % 3] = A[i];
        b.a[i / 3][i % 3] = B[i];
    }
    const SegmentLoad s = segmentLoad(a, b, toV3(ra), toV3(rb), rodParams(c, h));
    return {s.energy, toArray(s.force), toArray(s.torqueLeft), toArray(s.torqueRight)};
}

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

    int flags(int j) const { return j == 0 ? leftFlags : (j == n ? rightFlags : 0); }
    bool flowing() const { return c.fluidMass > 0.0 && setup.flowSpeed != 0.0; }
};

TubeDynamics::TubeDynamics(TubeDynamics&&) noexcept = default;
TubeDynamics& TubeDynamics::operator=(TubeDynamics&&) noexcept = default;
TubeDynamics::~TubeDynamics() = default;

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
    s.leftFlags = endFlags(setup.left);
    s.rightFlags = endFlags(setup.right);
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
    const bool helix = setup.left == EndCondition::Free && setup.right == EndCondition::Free;
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
        const double w = (j == 0 || j == s.n) ? 0.5 : 1.0;
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
    Kokkos::deep_copy(s.r, r);
    Kokkos::deep_copy(s.lam, lam);
    Kokkos::deep_copy(s.mass, mass);
    Kokkos::deep_copy(s.rotary, rotary);
}

int TubeDynamics::nodes() const { return s_->n + 1; }
double TubeDynamics::spacing() const { return s_->p.h; }
double TubeDynamics::time() const { return s_->t; }

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
    for (int j = 0; j <= s.n; ++j)
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
}

double TubeDynamics::stableStep() const
{
    const State& s = *s_;
    const RodConstants& c = s.c;
    const double h = s.p.h, mu = c.wallMass + c.fluidMass, rho = c.wallRotary;
    // Each energy term's element matrix, scaled by the lumped masses, bounds its share of omega^2; the sum
    // bounds the assembled one. 1.25: the half masses at the ends.
    const double w2 = 4.0 * (c.extension + c.shear) / (mu * h * h) + c.shear / rho +
                      4.0 * c.bending / (rho * h * h) + 2.0 * c.torsion / (rho * h * h) +
                      4.0 * c.fluidMass * s.setup.flowSpeed * s.setup.flowSpeed / (mu * h * h);
    return 0.9 * 2.0 / std::sqrt(1.25 * w2);
}

void TubeDynamics::kick(double tau)
{
    State& s = *s_;
    const bool flow = s.flowing();
    forEach("tube segment stress", s.n, s.serial,
            SegmentStress{s.lam, s.r, s.segForce, s.segTorqueLeft, s.segTorqueRight, s.p});
    NodeGather gather{s.segForce, s.segTorqueLeft, s.segTorqueRight, s.force, s.torque, s.v, s.spin, s.mass,
                      {0, 0, 0}, s.leftFlags, s.rightFlags, s.n, tau, !flow};
    for (int a = 0; a < 3; ++a)
        gather.gravity[a] = s.c.gravity[a];
    forEach("tube node gather", s.n + 1, s.serial, gather);
    if (!flow)
        return;
    // The pressure takes the accelerations of the elastic load just stored and the velocities at the kick's
    // start; the Coriolis force the midpoint velocity, by three Jacobi sweeps (predictor, two corrections).
    const double U = s.setup.flowSpeed, M = s.c.fluidMass;
    forEach("tube fluid segments", s.n, s.serial,
            FluidSegment{s.r, s.v, s.force, s.tangent, s.mass, s.pressureStep, M, U, s.leftFlags, s.rightFlags, s.n});
    scan("tube pressure", s.n, s.serial, PressureScan{s.pressureStep, s.pressure, s.n});
    CoriolisKick sweep{s.force, s.torque, s.tangent, s.v, s.vB, s.vA, s.spin, s.mass, s.pressure, M * U * U, M * U,
                       s.leftFlags, s.rightFlags, s.n, tau, true, false};
    forEach("tube coriolis predictor", s.n + 1, s.serial, sweep); // v -> vA
    sweep.predictor = false;
    sweep.vIn = s.vA;
    sweep.vOut = s.vB;
    forEach("tube coriolis sweep", s.n + 1, s.serial, sweep); // vA -> vB
    sweep.vIn = s.vB;
    sweep.vOut = s.vA;
    sweep.last = true;
    forEach("tube coriolis kick", s.n + 1, s.serial, sweep); // vB -> vA, spins kicked
    std::swap(s.v, s.vA);
}

void TubeDynamics::drift(double tau)
{
    State& s = *s_;
    forEach("tube drift", s.n + 1, s.serial,
            Drift{s.r, s.v, s.spin, s.lam, s.rotary, s.leftFlags, s.rightFlags, s.n, tau});
    s.t += tau;
}

void TubeDynamics::step(double dt) { run(dt, 1); }

void TubeDynamics::run(double dt, int steps)
{
    // kick(dt/2) [drift(dt) kick(dt)]... drift(dt) kick(dt/2): consecutive half kicks at the same positions
    // merged (identical without flow; with flow the merged kick's Coriolis force takes v^{n+1/2}).
    if (steps <= 0)
        return;
    kick(0.5 * dt);
    for (int k = 0; k < steps; ++k)
    {
        drift(dt);
        kick(k + 1 < steps ? dt : 0.5 * dt);
    }
    Kokkos::fence();
}

namespace
{
struct HostState
{
    Vec3View::HostMirror r, v, spin;
    Mat3View::HostMirror lam;
    ScalarView::HostMirror mass, rotary;
};
HostState hostCopy(const Vec3View& r, const Vec3View& v, const Vec3View& spin, const Mat3View& lam,
                   const ScalarView& mass, const ScalarView& rotary)
{
    return {Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r),
            Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v),
            Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), spin),
            Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), lam),
            Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mass),
            Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), rotary)};
}
M3 frameAt(const Mat3View::HostMirror& lam, int j)
{
    M3 m;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            m.a[a][b] = lam(j, a, b);
    return m;
}
V3 vecAt(const Vec3View::HostMirror& x, int j) { return v3(x(j, 0), x(j, 1), x(j, 2)); }
} // namespace

double TubeDynamics::energy() const
{
    const State& s = *s_;
    const HostState h = hostCopy(s.r, s.v, s.spin, s.lam, s.mass, s.rotary);
    double e = 0.0;
    for (int j = 0; j <= s.n; ++j)
    {
        const V3 v = vecAt(h.v, j), pi = vecAt(h.spin, j), r = vecAt(h.r, j);
        e += 0.5 * h.mass(j) * dot(v, v) - h.mass(j) * dot(toV3(s.c.gravity), r);
        e += 0.5 * (pi[0] * pi[0] / (2.0 * h.rotary(j)) + (pi[1] * pi[1] + pi[2] * pi[2]) / h.rotary(j));
    }
    for (int j = 0; j < s.n; ++j)
        e += segmentLoad(frameAt(h.lam, j), frameAt(h.lam, j + 1), vecAt(h.r, j), vecAt(h.r, j + 1), s.p).energy;
    return e;
}

std::array<double, 3> TubeDynamics::linearMomentum() const
{
    const State& s = *s_;
    const HostState h = hostCopy(s.r, s.v, s.spin, s.lam, s.mass, s.rotary);
    V3 p = v3(0, 0, 0);
    for (int j = 0; j <= s.n; ++j)
        p = p + h.mass(j) * vecAt(h.v, j);
    return toArray(p);
}

std::array<double, 3> TubeDynamics::angularMomentum() const
{
    const State& s = *s_;
    const HostState h = hostCopy(s.r, s.v, s.spin, s.lam, s.mass, s.rotary);
    V3 l = v3(0, 0, 0);
    for (int j = 0; j <= s.n; ++j)
        l = l + h.mass(j) * cross(vecAt(h.r, j), vecAt(h.v, j)) + mul(frameAt(h.lam, j), vecAt(h.spin, j));
    return toArray(l);
}

double TubeDynamics::orthogonalityDefect() const
{
    auto lam = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s_->lam);
    double worst = 0.0;
    for (int j = 0; j <= s_->n; ++j)
    {
        const M3 f = frameAt(lam, j);
        const M3 g = mulTN(f, f);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                worst = std::max(worst, std::abs(g.a[a][b] - (a == b ? 1.0 : 0.0)));
    }
    return worst;
}

std::array<double, 3> TubeDynamics::position(int node) const
{
    auto r = Kokkos::subview(s_->r, node, Kokkos::ALL());
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), r);
    return {host(0), host(1), host(2)};
}

std::array<double, 3> TubeDynamics::tip() const { return position(s_->n); }

bool TubeDynamics::finite() const
{
    const State& s = *s_;
    const HostState h = hostCopy(s.r, s.v, s.spin, s.lam, s.mass, s.rotary);
    for (int j = 0; j <= s.n; ++j)
        for (int a = 0; a < 3; ++a)
        {
            if (!std::isfinite(h.r(j, a)) || !std::isfinite(h.v(j, a)) || !std::isfinite(h.spin(j, a)))
                return false;
            for (int b = 0; b < 3; ++b)
                if (!std::isfinite(h.lam(j, a, b)))
                    return false;
        }
    return true;
}

RodFields TubeDynamics::fields() const
{
    const State& s = *s_;
    const HostState h = hostCopy(s.r, s.v, s.spin, s.lam, s.mass, s.rotary);
    auto pA = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.pressure);
    RodFields f;
    const int nn = s.n + 1;
    std::vector<double> segCurvature(s.n);
    for (int j = 0; j < s.n; ++j)
    {
        const V3 x = cayleyLog(mulTN(frameAt(h.lam, j), frameAt(h.lam, j + 1)));
        segCurvature[j] = std::sqrt(dot(x, x)) / s.p.h;
    }
    const double area = s.c.fluidArea;
    for (int j = 0; j < nn; ++j)
    {
        for (int a = 0; a < 3; ++a)
        {
            f.position.push_back(h.r(j, a));
            f.velocity.push_back(h.v(j, a));
        }
        const double k0 = j > 0 ? segCurvature[j - 1] : segCurvature[0];
        const double k1 = j < s.n ? segCurvature[j] : segCurvature[s.n - 1];
        f.curvature.push_back(0.5 * (k0 + k1));
        f.fluidVelocity.push_back(s.setup.flowSpeed);
        f.pressure.push_back(s.flowing() ? (area > 0.0 ? pA(j) / area : pA(j)) : 0.0);
        f.area.push_back(area);
    }
    return f;
}

} // namespace unilag::tube
