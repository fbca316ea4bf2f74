#include "tube/Artery.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tube/SmallLaunch.hpp"

namespace unilag::tube
{

using namespace unilag::artery;

namespace
{
constexpr double kPi = 3.14159265358979323846;
using launch::forEach; // a 64-cell artery runs on Kokkos::Serial (ArteryConfig::serialBelow)
using launch::reduce;
} // namespace

double arteryBeta(const ArteryConfig& cfg)
{
    const double A0 = kPi * cfg.radius * cfg.radius;
    return std::sqrt(kPi / A0) * cfg.wall * cfg.young / (1.0 - cfg.poisson * cfg.poisson);
}

double moensKortewegSpeed(const ArteryConfig& cfg)
{
    return std::sqrt(cfg.young * cfg.wall / (2.0 * cfg.density * cfg.radius * (1.0 - cfg.poisson * cfg.poisson)));
}

double frictionCoefficient(const ArteryConfig& cfg)
{
    return 2.0 * (cfg.gammaProfile + 2.0) * kPi * cfg.viscosity / cfg.density;
}

double tensionCoefficient(const ArteryConfig& cfg)
{
    return cfg.tension / (4.0 * kPi * kPi * cfg.radius * cfg.radius);
}

Artery::Artery(const ArteryConfig& cfg) : cfg_(cfg)
{
    if (cfg.cells < 2)
        throw std::invalid_argument("Artery: at least 2 cells");
    if (cfg.inlet == InletKind::Flux && !cfg.inletFlux)
        throw std::invalid_argument("Artery: InletKind::Flux needs inletFlux");
    if (cfg.outlet == OutletKind::Windkessel && !(cfg.R1 >= 0 && cfg.R2 > 0 && cfg.C > 0))
        throw std::invalid_argument("Artery: Windkessel needs R1 >= 0, R2 > 0, C > 0");
    if (!(cfg.tension >= 0))
        throw std::invalid_argument("Artery: tension must be >= 0");
    serial_ = cfg.cells < cfg.serialBelow;
    constants_.rho = cfg.density;
    constants_.A0 = kPi * cfg.radius * cfg.radius;
    constants_.beta = arteryBeta(cfg);
    constants_.alpha = (cfg.gammaProfile + 2.0) / (cfg.gammaProfile + 1.0);
    constants_.frictionK = frictionCoefficient(cfg);
    constants_.dx = cfg.length / cfg.cells;
    constants_.inlet = cfg.inlet;
    constants_.outlet = cfg.outlet;
    constants_.reflection = cfg.reflection;
    constants_.R1 = cfg.R1;
    constants_.R2 = cfg.R2;
    constants_.C = cfg.C;
    constants_.tension = tensionCoefficient(cfg);
    constants_.n = cfg.cells;
    constants_.setDerived();
    U_ = StateView("artery U", cfg.cells);
    U1_ = StateView("artery U1", cfg.cells);
    flux_ = StateView("artery face flux", cfg.cells + 1);
    bc_ = BoundaryView("artery bc");
    bc1_ = BoundaryView("artery bc1");
    if (cfg.tension > 0)
    {
        U2_ = StateView("artery U2", cfg.cells);
        bc2_ = BoundaryView("artery bc2");
    }
    setState(std::vector<double>(cfg.cells, constants_.A0), std::vector<double>(cfg.cells, 0.0));
}

void Artery::setState(const std::vector<double>& area, const std::vector<double>& flow, double windkesselPressure)
{
    const int n = cfg_.cells;
    if (static_cast<int>(area.size()) != n || static_cast<int>(flow.size()) != n)
        throw std::invalid_argument("Artery::setState: wrong size");
    auto h = Kokkos::create_mirror_view(U_);
    for (int i = 0; i < n; ++i)
    {
        h(i, 0) = area[i];
        h(i, 1) = flow[i];
    }
    Kokkos::deep_copy(U_, h);
    auto hb = Kokkos::create_mirror_view(bc_);
    for (int s = 0; s < 8; ++s)
        hb(s) = 0;
    hb(kWindkesselPressure) = windkesselPressure;
    Kokkos::deep_copy(bc_, hb);
    Kokkos::deep_copy(bc1_, hb);
}

void Artery::runStage(StateView in, StateView base, StateView out, BoundaryView bcIn, BoundaryView bcBase,
                      BoundaryView bcOut, double dt, double weight, double t, bool record)
{
    const double inletQ = cfg_.inlet == InletKind::Flux ? cfg_.inletFlux(t) : 0.0;
    const ArteryFaceFlux faces{constants_, in,           flux_,  bcIn,   bcBase,     bcOut,
                               dt,         1.0 - weight, weight, inletQ, cfg_.cells, record};
    forEach("artery faces", cfg_.cells + 1, serial_, faces);
    forEach("artery cells", cfg_.cells, serial_,
            ArteryCellUpdate{constants_, in, base, out, flux_, dt, 1.0 - weight, weight});
}

double Artery::maxSpeed() const
{
    double s = 0;
    reduce("artery max speed", cfg_.cells, serial_, ArteryMaxSpeed{constants_, U_}, Kokkos::Max<double>(s));
    return s;
}

//! Heun / SSP-RK2: U1 = U + dt L(U);  U = U/2 + (U1 + dt L(U1))/2. Q_in is sampled at each stage's time.
void Artery::stepHeun(double dt)
{
    runStage(U_, U_, U1_, bc_, bc_, bc1_, dt, 1.0, time_);
    runStage(U1_, U_, U_, bc1_, bc_, bc_, dt, 0.5, time_ + dt);
}

/*! SSP-RK3 (Shu-Osher): U1 = U + dt L(U); U2 = 3/4 U + 1/4 (U1 + dt L(U1)); U = 1/3 U + 2/3 (U2 + dt L(U2)), the
 *  stages at t, t + dt, t + dt/2. The boundary records take the same weights, so the volume still balances. The
 *  boundary states kept for output are those of the stage at t + dt, from U1, as Heun's last stage gives them: the
 *  last stage's, at t + dt/2, would lag the probes by dt/2 (9e-4 of the carotid's inlet flow). */
void Artery::stepRK3(double dt)
{
    runStage(U_, U_, U1_, bc_, bc_, bc1_, dt, 1.0, time_);
    runStage(U1_, U_, U2_, bc1_, bc_, bc2_, dt, 0.25, time_ + dt);
    runStage(U2_, U_, U_, bc2_, bc_, bc_, dt, 2.0 / 3.0, time_ + 0.5 * dt, false);
}

double Artery::step(double dtMax)
{
    const double dt = std::fmin(cfg_.cfl * constants_.dx / maxSpeed(), dtMax);
    if (constants_.tension > 0)
        stepRK3(dt); // the dispersive eigenvalues lie near the imaginary axis, outside Heun's region
    else
        stepHeun(dt);
    time_ += dt;
    cellSteps_ += cfg_.cells;
    return dt;
}

void Artery::advanceTo(double t)
{
    while (time_ < t)
    {
        const double left = t - time_;
        step(left);
        if (t - time_ < 1e-12 * left) // round-off of the shortened last step
            time_ = t;
    }
}

double Artery::volume() const
{
    double v = 0;
    reduce("artery volume", cfg_.cells, serial_, ArteryVolume{U_, constants_.dx}, Kokkos::Sum<double>(v));
    return v;
}

double Artery::boundarySlot(int s) const
{
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), bc_);
    return h(s);
}

double Artery::volumeIn() const
{
    return boundarySlot(kVolumeIn);
}
double Artery::volumeOut() const
{
    return boundarySlot(kVolumeOut);
}
double Artery::windkesselPressure() const
{
    return boundarySlot(kWindkesselPressure);
}

void Artery::boundaryStates(double& Ain, double& Qin, double& Aout, double& Qout) const
{
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), bc_);
    Ain = h(kInletArea);
    Qin = h(kInletFlow);
    Aout = h(kOutletArea);
    Qout = h(kOutletFlow);
}

double Artery::tensionPressure(const std::vector<double>& area, int i) const
{
    const int n = int(area.size());
    const double left = area[std::max(i - 1, 0)], right = area[std::min(i + 1, n - 1)]; // mirror: d_s A = 0
    return -constants_.tension * (left - 2.0 * area[i] + right) / (constants_.dx * constants_.dx);
}

std::vector<double> Artery::wallPressure(const std::vector<double>& area) const
{
    std::vector<double> p(area.size());
    for (std::size_t i = 0; i < area.size(); ++i)
        p[i] = pressure(area[i]) + tensionPressure(area, int(i));
    return p;
}

void Artery::hostState(std::vector<double>& area, std::vector<double>& flow) const
{
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), U_);
    const int n = cfg_.cells;
    area.resize(n);
    flow.resize(n);
    for (int i = 0; i < n; ++i)
    {
        area[i] = h(i, 0);
        flow[i] = h(i, 1);
    }
}

} // namespace unilag::tube
