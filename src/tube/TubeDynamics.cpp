#include "tube/TubeDynamics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "tube/TubeDynamicsState.hpp"

namespace unilag::tube
{

using namespace dynamics_detail;

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

TubeDynamics::TubeDynamics(TubeDynamics&&) noexcept = default;
TubeDynamics& TubeDynamics::operator=(TubeDynamics&&) noexcept = default;
TubeDynamics::~TubeDynamics() = default;

int TubeDynamics::nodes() const { return s_->n + 1; }
double TubeDynamics::spacing() const { return s_->p.h; }
double TubeDynamics::time() const { return s_->t; }

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
    gather.screw = s.screw;
    gather.screwRotation = s.screwRotation;
    forEach("tube node gather", s.dynamicNodes(), s.serial, gather);
    if (!flow)
        return;
    // The pressure takes the accelerations of the elastic load just stored and the velocities at the kick's
    // start; the Coriolis force the midpoint velocity, by three Jacobi sweeps (predictor, two corrections).
    const double U = s.setup.flowSpeed, M = s.c.fluidMass;
    forEach("tube fluid segments", s.n, s.serial,
            FluidSegment{s.r, s.v, s.force, s.tangent, s.mass, s.pressureStep, M, U, s.leftFlags, s.rightFlags, s.n});
    scan("tube pressure", s.n, PressureScan{s.pressureStep, s.pressure, s.n});
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
    forEach("tube drift", s.dynamicNodes(), s.serial,
            Drift{s.r, s.v, s.spin, s.lam, s.rotary, s.leftFlags, s.rightFlags, s.n, tau});
    closeScrew();
    s.t += tau;
}

void TubeDynamics::step(double dt) { run(dt, 1); }

rod::RodViews TubeDynamics::deviceViews() const
{
    const State& s = *s_;
    return rod::RodViews{s.r, s.v, s.spin, s.force, s.torque, s.lam, s.mass, s.rotary,
                         s.leftFlags, s.rightFlags, s.n, s.p.h};
}

void TubeDynamics::storeElasticLoads()
{
    State& s = *s_;
    if (s.flowing() || s.screw)
        throw std::logic_error("TubeDynamics::storeElasticLoads: not for rods with plug flow or screw ends");
    forEach("tube segment stress", s.n, s.serial,
            SegmentStress{s.lam, s.r, s.segForce, s.segTorqueLeft, s.segTorqueRight, s.p});
    NodeGather gather{s.segForce, s.segTorqueLeft, s.segTorqueRight, s.force, s.torque, s.v, s.spin, s.mass,
                      {0, 0, 0}, s.leftFlags, s.rightFlags, s.n, 0.0, false};
    for (int a = 0; a < 3; ++a)
        gather.gravity[a] = s.c.gravity[a];
    forEach("tube node gather", s.n + 1, s.serial, gather);
}

void TubeDynamics::driftBy(double tau) { drift(tau); }

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
    for (int j = 0; j < s.dynamicNodes(); ++j)
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
    for (int j = 0; j < s.dynamicNodes(); ++j)
        p = p + h.mass(j) * vecAt(h.v, j);
    return toArray(p);
}

std::array<double, 3> TubeDynamics::angularMomentum() const
{
    const State& s = *s_;
    const HostState h = hostCopy(s.r, s.v, s.spin, s.lam, s.mass, s.rotary);
    V3 l = v3(0, 0, 0);
    for (int j = 0; j < s.dynamicNodes(); ++j)
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

std::array<double, 9> TubeDynamics::frame(int node) const
{
    auto m = Kokkos::subview(s_->lam, node, Kokkos::ALL(), Kokkos::ALL());
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m);
    std::array<double, 9> f;
    for (int i = 0; i < 9; ++i)
        f[i] = host(i / 3, i % 3);
    return f;
}

bool TubeDynamics::screwPeriodic() const { return s_->screw; }

std::array<double, 3> TubeDynamics::tip() const { return position(s_->n); }

bool TubeDynamics::finite() const
{
    const State& s = *s_;
    int bad = 0;
    launch::reduce("tube non-finite nodes", s.n + 1, s.serial, NonFiniteNodes{s.r, s.v, s.spin, s.lam}, bad);
    return bad == 0;
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
