#include "tube/GasRodCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tube/SmallLaunch.hpp"
#include "unilag/TubeGasRod.hpp"

namespace unilag::tube
{

using namespace unilag::gasrod;
using launch::forEach;
using launch::reduce;

namespace
{

constexpr int kMidpointPasses = 3; // the gas step on v0, then twice on the midpoint velocity
constexpr int kImplicitPasses = 3; // the rod part's implicit kick and drift

void validate(const GasRodSetup& s)
{
    const auto fail = [](const char* why) { throw std::invalid_argument(std::string("GasRodCoupling: ") + why); };
    if (s.rod.fluidMass != 0.0 || s.rodSetup.flowSpeed != 0.0 || s.rodSetup.screwPeriodic)
        fail("the gas is the fluid: the rod must have no plug flow (fluidMass 0, flowSpeed 0) and no screw ends");
    if (s.rod.gravity[0] != 0.0 || s.rod.gravity[1] != 0.0 || s.rod.gravity[2] != 0.0)
        fail("gravity is not coupled to the gas's weight");
    if (s.gas.left.type != GasEndType::Wall || s.gas.right.type != GasEndType::Wall)
        fail("both gas ends must be walls (the end caps move with the rod)");
    if (!(s.area > 0.0) || !(s.outsidePressure >= 0.0) || !(s.rodStepFactor > 0.0 && s.rodStepFactor <= 1.0))
        fail("need area > 0, outside pressure >= 0 and 0 < rodStepFactor <= 1");
    if (s.wall && (s.wall->as != 0.0 || s.wall->pExt != s.outsidePressure || !(s.wallResolution > 0.0)))
        fail("an expandable wall on the free rod needs as = 0 (no axial tension), its pExt equal to the outside "
             "pressure, and wallResolution > 0");
}

wall::WallParams wallParams(const WallCoefficients& c)
{
    return wall::WallParams{c.a, c.b, c.c, c.restRadius, c.pExt, c.as};
}

GasSetup gasOnRod(const GasRodSetup& s)
{
    GasSetup g = s.gas;
    g.cells = s.rodSetup.segments;
    g.length = s.rod.length;
    return g;
}

} // namespace

struct GasRodCoupling::State
{
    GasRodSetup setup;
    TubeDynamics rod;
    TubeGas gas;
    int n;
    bool serial;
    Vec3View momentum, load;               // P_k per node, the gas's load n_j per segment
    Vec3View startVelocity, midVelocity;   // the gas part's iteration on the tube's velocity
    Vec3View startMomentum, startPosition; // the rod part's implicit kick and drift
    StateView startGas;                    // the gas's state at the start of the gas part
    gasrod::ScalarView entropy;
    gasrod::ScalarView radius, speed, wallMomentum, dissipated; // the expandable wall (sized 0 without)
    State(const GasRodSetup& s)
        : setup(s), rod(s.rod, s.rodSetup), gas(gasOnRod(s)), n(s.rodSetup.segments), serial(n < s.gas.serialBelow),
          momentum("gas rod momentum", n + 1), load("gas rod load", n), startVelocity("gas rod v0", n + 1),
          midVelocity("gas rod v mid", n + 1), startMomentum("gas rod P0", n + 1), startPosition("gas rod r0", n + 1),
          startGas("gas rod q0", n), entropy("gas rod entropy", n), radius("gas rod R", s.wall ? n : 0),
          speed("gas rod R_t", s.wall ? n : 0), wallMomentum("gas rod pi_R", s.wall ? n : 0),
          dissipated("gas rod wall loss", s.wall ? n : 0)
    {
    }
    gasrod::ScalarView area() const { return gas.deviceViews().areaCell; } // A = pi R^2 with a wall
    RodViews rodViews() const { return rod.deviceViews(); }
    gas::GasViews gasViews() const { return gas.deviceViews(); }
};

GasRodCoupling::GasRodCoupling(const GasRodSetup& setup)
{
    validate(setup);
    s_ = std::make_unique<State>(setup);
    const double a = setup.area;
    s_->gas.setArea([a](double) { return a; });
    if (setup.wall)
    {
        const double r0 = setup.wall->restRadius;
        setWall([r0](double) { return r0; }, [](double) { return 0.0; });
    }
    setGas([](double) { return GasPrimitive{}; });
}

GasRodCoupling::~GasRodCoupling() = default;

TubeDynamics& GasRodCoupling::rod()
{
    return s_->rod;
}
const TubeDynamics& GasRodCoupling::rod() const
{
    return s_->rod;
}
const TubeGas& GasRodCoupling::gas() const
{
    return s_->gas;
}
double GasRodCoupling::time() const
{
    return s_->gas.time();
}

void GasRodCoupling::updateMetric()
{
    metricFrom(s_->rodViews().velocity);
}

void GasRodCoupling::metricFrom(const Vec3View& velocity)
{
    State& s = *s_;
    const gas::GasViews g = s.gasViews();
    RodViews rod = s.rodViews();
    rod.velocity = velocity;
    forEach("gas rod metric", s.n, s.serial, SegmentMetric{rod, g.metricCell});
    forEach("gas rod face metric", s.n + 1, s.serial, FaceMetric{g.metricCell, g.metricFace, s.n});
    forEach("gas rod restate", s.n, s.serial, RestateEnergy{g.q, s.area(), s.entropy, g.metricCell, s.setup.gas.gamma});
}

void GasRodCoupling::velocities()
{
    State& s = *s_;
    forEach("gas rod velocities", s.n + 1, s.serial, VelocityFromMomentum{s.rodViews(), s.gasViews().q, s.momentum});
}

void GasRodCoupling::setWall(const std::function<double(double)>& radius, const std::function<double(double)>& speed)
{
    State& s = *s_;
    if (!s.setup.wall)
        throw std::logic_error("GasRodCoupling::setWall: the setup has no expandable wall");
    auto r = Kokkos::create_mirror_view(s.radius);
    auto v = Kokkos::create_mirror_view(s.speed);
    const double h = s.rod.spacing();
    for (int j = 0; j < s.n; ++j)
        r(j) = radius((j + 0.5) * h), v(j) = speed((j + 0.5) * h);
    Kokkos::deep_copy(s.radius, r);
    Kokkos::deep_copy(s.speed, v);
    Kokkos::deep_copy(s.dissipated, 0.0);
    const gas::GasViews g = s.gasViews();
    forEach("gas rod wall areas", s.n, s.serial, wall::CellAreasFromRadius{g.areaCell, s.radius});
    forEach("gas rod wall face areas", s.n + 1, s.serial, wall::FaceAreasFromCells{g.areaFace, g.areaCell, s.n});
}

void GasRodCoupling::setGas(const std::function<GasPrimitive(double)>& state)
{
    State& s = *s_;
    const gas::GasViews g = s.gasViews();
    forEach("gas rod metric", s.n, s.serial, SegmentMetric{s.rodViews(), g.metricCell});
    forEach("gas rod face metric", s.n + 1, s.serial, FaceMetric{g.metricCell, g.metricFace, s.n});
    s.gas.setState(state);
    forEach("gas rod entropy", s.n, s.serial, SaveEntropy{g.q, s.area(), s.entropy, g.metricCell, s.setup.gas.gamma});
    forEach("gas rod momentum", s.n + 1, s.serial, TotalMomentum{s.rodViews(), g.q, s.momentum});
}

double GasRodCoupling::stableStep() const
{
    const State& s = *s_;
    const double gasStep = s.gas.stableStep();
    if (!s.setup.wall)
        return gasStep;
    double omega = 0.0;
    reduce("gas rod wall frequency", s.n, s.serial,
           WallFrequencyOnRod{s.gasViews().q, s.radius, s.gasViews().metricCell, wallParams(*s.setup.wall),
                              s.setup.gas.gamma},
           Kokkos::Max<double>(omega));
    return std::min(gasStep, s.setup.wallResolution / omega);
}

/*! P = P0 + tau (elastic load + the gas's load at the current velocities), velocities from P; the elastic load
 *  is the one stored last. `spins`: kick the spins too (once per kick). */
void GasRodCoupling::kickFrom(const Vec3View& start, double tau, bool spins)
{
    State& s = *s_;
    const RodViews rod = s.rodViews();
    GasSegmentForce load;
    load.rod = rod, load.q = s.gasViews().q, load.area = s.area(), load.entropy = s.entropy, load.load = s.load;
    load.gamma = s.setup.gas.gamma, load.pExt = s.setup.outsidePressure;
    if (s.setup.wall)
    {
        load.wall = true;
        load.radius = s.radius;
        load.wallMomentum = s.wallMomentum;
        load.w = wallParams(*s.setup.wall);
    }
    forEach("gas rod load", s.n, s.serial, load);
    if (start.data() != s.momentum.data())
        Kokkos::deep_copy(s.momentum, start);
    forEach("gas rod kick", s.n + 1, s.serial, CoupledKick{rod, s.load, s.momentum, tau, spins});
    velocities();
}

/*! The rod with the gas carried, sub-cycled at its own stable step by the generalised leapfrog (Stoermer-Verlet
 *  for a Hamiltonian that is not separable, Hairer-Lubich-Wanner VI.3): the gas's load depends on the
 *  velocities and the mass on the tangents, so the first half kick and the drift are implicit (fixed-point
 *  passes, contraction ~ xi / alpha), the second half kick explicit. (The explicit kick-drift-kick's energy
 *  error did not fall when only the gas's step was refined.) An expandable wall's momentum pi_R = a sqrt(c) R_t is
 *  held through the part, its speed follows the stretch. */
void GasRodCoupling::rodPart(double tau)
{
    State& s = *s_;
    if (s.setup.wall)
        forEach("gas rod wall momentum", s.n, s.serial,
                WallMomentum{s.rodViews(), s.speed, s.wallMomentum, s.setup.wall->a, false});
    const double limit = s.setup.rodStepFactor * s.rod.stableStep();
    const int substeps = std::max(1, static_cast<int>(std::ceil(tau / limit)));
    const double h = tau / substeps;
    for (int i = 0; i < substeps; ++i)
    {
        s.rod.storeElasticLoads();
        Kokkos::deep_copy(s.startMomentum, s.momentum);
        for (int pass = 0; pass < kImplicitPasses; ++pass)
            kickFrom(s.startMomentum, 0.5 * h, pass + 1 == kImplicitPasses);
        Kokkos::deep_copy(s.startPosition, s.rodViews().position);
        Kokkos::deep_copy(s.startVelocity, s.rodViews().velocity);
        s.rod.driftBy(h); // frames: exact; positions: the predictor r0 + h v0
        for (int pass = 0; pass < kImplicitPasses; ++pass)
        {
            velocities();
            forEach("gas rod trapezoidal drift", s.n + 1, s.serial,
                    TrapezoidalPositions{s.rodViews(), s.startPosition, s.startVelocity, h});
        }
        velocities();
        s.rod.storeElasticLoads();
        kickFrom(s.momentum, 0.5 * h, true);
    }
    if (s.setup.wall)
        forEach("gas rod wall speed", s.n, s.serial,
                WallMomentum{s.rodViews(), s.speed, s.wallMomentum, s.setup.wall->a, true});
}

//! The expandable wall's exchange with the gas on the frozen rod and frozen gas transport (energy-exact per cell).
void GasRodCoupling::wallPart(double tau)
{
    State& s = *s_;
    if (!s.setup.wall)
        return;
    updateMetric();
    const gas::GasViews g = s.gasViews();
    forEach("gas rod wall exchange", s.n, s.serial,
            WallExchangeOnRod{g.q, g.areaCell, s.radius, s.speed, s.dissipated, g.metricCell, wallParams(*s.setup.wall),
                              s.setup.gas.gamma, tau});
    forEach("gas rod wall face areas", s.n + 1, s.serial, wall::FaceAreasFromCells{g.areaFace, g.areaCell, s.n});
}

/*! Gas transport on the frozen rod; the wall's velocities then follow the gas's new momentum (P held). The gas
 *  sees the tube at the midpoint velocity (v0 + v1)/2 of the part, found by fixed-point iteration (contraction
 *  ~ xi / alpha times the gas's sensitivity to the tube's speed): with the start velocity alone, the wall's velocity
 *  jump after the part gains the energy dP^2 / (2 alpha) every step, a first-order drift (docs/tube-gas-rod.md). */
void GasRodCoupling::gasPart(double tau)
{
    State& s = *s_;
    const gas::GasViews g = s.gasViews();
    const double t0 = s.gas.time();
    Kokkos::deep_copy(s.startVelocity, s.rodViews().velocity);
    Kokkos::deep_copy(s.startGas, g.q);
    Kokkos::deep_copy(s.midVelocity, s.startVelocity);
    for (int pass = 0; pass < kMidpointPasses; ++pass)
    {
        if (pass > 0)
        {
            Kokkos::deep_copy(g.q, s.startGas);
            s.gas.setTime(t0);
            forEach("gas rod midpoint velocity", s.n + 1, s.serial,
                    MidpointVelocity{s.startVelocity, s.rodViews().velocity, s.midVelocity});
        }
        metricFrom(s.midVelocity);
        s.gas.step(tau);
        velocities();
    }
    forEach("gas rod entropy", s.n, s.serial, SaveEntropy{g.q, s.area(), s.entropy, g.metricCell, s.setup.gas.gamma});
}

void GasRodCoupling::step(double dt)
{
    rodPart(0.5 * dt);
    wallPart(0.5 * dt);
    gasPart(dt);
    wallPart(0.5 * dt);
    rodPart(0.5 * dt);
    updateMetric(); // the gas's state as the rod now is (fields, stableStep)
}

int GasRodCoupling::advanceTo(double tEnd)
{
    int steps = 0;
    while (time() < tEnd * (1.0 - 1e-14))
    {
        step(std::min(stableStep(), tEnd - time()));
        ++steps;
    }
    return steps;
}

GasRodTotals GasRodCoupling::totals() const
{
    const State& s = *s_;
    const RodViews rod = s.rodViews();
    const StateView q = s.gasViews().q;
    GasRodTotals t;
    t.mass = s.gas.mass();
    t.rodEnergy = s.rod.energy();
    double parts[3] = {0, 0, 0}, transverse = 0;
    for (int part = 0; part < 3; ++part)
        reduce("gas rod energy", s.n, s.serial,
               CellGasEnergy{rod, q, s.area(), s.entropy, s.setup.gas.gamma, s.setup.outsidePressure, part},
               parts[part]);
    reduce("gas rod transverse", s.n + 1, s.serial, NodeGasKinetic{rod, q}, transverse);
    t.gasKinetic = parts[0] + transverse;
    t.gasInternal = parts[1];
    t.outside = parts[2];
    if (s.setup.wall)
    {
        double w[3] = {0, 0, 0};
        for (int part = 0; part < 3; ++part)
            reduce("gas rod wall energy", s.n, s.serial,
                   CellWallEnergy{rod, s.radius, s.speed, s.dissipated, wallParams(*s.setup.wall), part}, w[part]);
        t.wallKinetic = w[0], t.wallElastic = w[1], t.wallDissipated = w[2];
    }
    const auto p = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.momentum);
    for (int k = 0; k <= s.n; ++k)
        for (int a = 0; a < 3; ++a)
            t.momentum[a] += p(k, a);
    return t;
}

std::vector<std::array<double, 3>> GasRodCoupling::cellMetric() const
{
    const auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s_->gasViews().metricCell);
    std::vector<std::array<double, 3>> out(s_->n);
    for (int j = 0; j < s_->n; ++j)
        out[j] = {m(j, 0), m(j, 1), m(j, 2)};
    return out;
}

} // namespace unilag::tube
