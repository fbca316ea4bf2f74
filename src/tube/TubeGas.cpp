#include "tube/TubeGas.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tube/SmallLaunch.hpp"
#include "unilag/TubeGas.hpp"

namespace unilag::tube
{

using namespace unilag::gas;

namespace
{

using launch::forEach; // small tubes run on Kokkos::Serial (GasSetup::serialBelow)
using launch::reduce;

EndParams endParams(const GasEnd& e)
{
    int type = End::Wall;
    switch (e.type)
    {
    case GasEndType::Wall:
        type = End::Wall;
        break;
    case GasEndType::Transmissive:
        type = End::Transmissive;
        break;
    case GasEndType::FixedState:
        type = End::FixedState;
        break;
    case GasEndType::PressureOutlet:
        type = End::PressureOutlet;
        break;
    case GasEndType::SubsonicInflow:
        type = End::SubsonicInflow;
        break;
    }
    return EndParams{type, e.state.rho, e.state.u, e.state.p};
}

} // namespace

struct TubeGas::State
{
    GasSetup setup;
    int n = 0;
    double h = 0, t = 0;
    EndParams left{}, right{};
    int limiter = Limiter::VanLeer;
    bool serial = false; // kernels on Kokkos::Serial (GasSetup::serialBelow)
    StateView q, scratch, w, flux; // conserved (n), stage (n), primitives with ghosts (n + 4), faces (n + 1)
    ScalarView areaFace, areaCell;
    MetricView metricFace, metricCell; // (c, g, k) of the centreline: (1, 0, 0) for a rigid tube at rest
};

TubeGas::TubeGas(TubeGas&&) noexcept = default;
TubeGas& TubeGas::operator=(TubeGas&&) noexcept = default;
TubeGas::~TubeGas() = default;

TubeGas::TubeGas(const GasSetup& setup) : s_(std::make_unique<State>())
{
    if (setup.cells < 2 || !(setup.length > 0.0) || !(setup.gamma > 1.0))
        throw std::invalid_argument("TubeGas: need cells >= 2, length > 0, gamma > 1");
    State& s = *s_;
    s.setup = setup;
    s.n = setup.cells;
    s.h = setup.length / s.n;
    s.left = endParams(setup.left);
    s.right = endParams(setup.right);
    s.serial = s.n < setup.serialBelow;
    s.limiter = setup.limiter == GasLimiter::MinMod ? Limiter::MinMod : Limiter::VanLeer;
    s.q = StateView("gas q", s.n);
    s.scratch = StateView("gas q stage", s.n);
    s.w = StateView("gas w", s.n + 2 * ghosts);
    s.flux = StateView("gas flux", s.n + 1);
    s.areaFace = ScalarView("gas area face", s.n + 1);
    s.areaCell = ScalarView("gas area cell", s.n);
    s.metricFace = MetricView("gas metric face", s.n + 1);
    s.metricCell = MetricView("gas metric cell", s.n);
    setMetric({1.0, 0.0, 0.0}, {});
    setArea([](double) { return 1.0; });
    setState([](double) { return GasPrimitive{}; });
}

int TubeGas::cells() const { return s_->n; }
double TubeGas::spacing() const { return s_->h; }
double TubeGas::time() const { return s_->t; }
void TubeGas::setTime(double t) { s_->t = t; }

void TubeGas::setArea(const std::function<double(double)>& area)
{
    State& s = *s_;
    auto af = Kokkos::create_mirror_view(s.areaFace);
    auto ac = Kokkos::create_mirror_view(s.areaCell);
    for (int f = 0; f <= s.n; ++f)
        af(f) = area(f * s.h);
    for (int j = 0; j < s.n; ++j)
        ac(j) = 0.5 * (af(j) + af(j + 1));
    Kokkos::deep_copy(s.areaFace, af);
    Kokkos::deep_copy(s.areaCell, ac);
}

namespace
{
//! Cell metrics: the mean of the two faces' (c, g, k), all three linear in the face values.
void cellMetricFromFaces(const MetricView::HostMirror& face, MetricView::HostMirror& cell, int n)
{
    for (int j = 0; j < n; ++j)
        for (int k = 0; k < 3; ++k)
            cell(j, k) = 0.5 * (face(j, k) + face(j + 1, k));
}
} // namespace

void TubeGas::setMetric(const std::array<double, 3>& uniform, const std::function<std::array<double, 3>(double)>& at)
{
    State& s = *s_;
    auto face = Kokkos::create_mirror_view(s.metricFace);
    auto cell = Kokkos::create_mirror_view(s.metricCell);
    for (int f = 0; f <= s.n; ++f)
    {
        const std::array<double, 3> m = at ? at(f * s.h) : uniform;
        if (!(m[0] > 0.0) || !(m[2] >= 0.0))
            throw std::invalid_argument("TubeGas::setMetric: need |r'|^2 > 0 and |r_t|^2 >= 0");
        for (int k = 0; k < 3; ++k)
            face(f, k) = m[k];
    }
    cellMetricFromFaces(face, cell, s.n);
    Kokkos::deep_copy(s.metricFace, face);
    Kokkos::deep_copy(s.metricCell, cell);
}

void TubeGas::setState(const std::function<GasPrimitive(double)>& state)
{
    State& s = *s_;
    auto q = Kokkos::create_mirror_view(s.q);
    auto ac = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.areaCell);
    auto mc = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.metricCell);
    const double g = s.setup.gamma;
    for (int j = 0; j < s.n; ++j)
    {
        const GasPrimitive w = state((j + 0.5) * s.h);
        const double c = mc(j, 0), root = std::sqrt(c), volume = ac(j) * root;
        const double xi = w.rho * volume, u = w.u / root; // u: the gas speed in s per time
        q(j, 0) = xi;
        q(j, 1) = xi * (mc(j, 1) + u * c);
        q(j, 2) = volume * w.p / (g - 1.0) + 0.5 * xi * (w.u * w.u - mc(j, 2));
    }
    Kokkos::deep_copy(s.q, q);
    s.t = 0.0;
}

/*! One stage: primitives and ghosts of the stage's input (q, or scratch after the first stage), face fluxes,
 *  then out = alpha q + beta (in + dt L(in)) into scratch (first stage) or q (second). */
void TubeGas::residualUpdate(double alpha, double beta, double dt, bool toScratch)
{
    State& s = *s_;
    const double g = s.setup.gamma;
    const StateView in = toScratch ? s.q : s.scratch;
    const StateView out = toScratch ? s.scratch : s.q;
    forEach("gas primitives", s.n, s.serial, ToPrimitive{in, s.w, s.areaCell, s.metricCell, g});
    forEach("gas ghosts", 4, s.serial, FillGhosts{s.w, s.left, s.right, s.n, g});
    forEach("gas fluxes", s.n + 1, s.serial,
            FaceFlux{s.w, s.flux, s.areaFace, s.metricFace, s.n, s.limiter, s.left.type == End::Wall, s.right.type == End::Wall, g});
    forEach("gas update", s.n, s.serial, CellUpdate{out, s.q, in, s.w, s.flux, s.areaFace, s.metricFace, s.metricCell, alpha, beta, dt, s.h});
}

void TubeGas::step(double dt)
{
    residualUpdate(0.0, 1.0, dt, true);
    residualUpdate(0.5, 0.5, dt, false);
    s_->t += dt;
}

double TubeGas::stableStep() const
{
    State& s = *s_;
    forEach("gas primitives", s.n, s.serial, ToPrimitive{s.q, s.w, s.areaCell, s.metricCell, s.setup.gamma});
    double speed = 0.0;
    reduce("gas max speed", s.n, s.serial, MaxSignalSpeed{s.w, s.metricCell, s.setup.gamma}, Kokkos::Max<double>(speed));
    return s.setup.cfl * s.h / speed;
}

int TubeGas::advanceTo(double tEnd)
{
    int steps = 0;
    while (s_->t < tEnd * (1.0 - 1e-14))
    {
        step(std::min(stableStep(), tEnd - s_->t));
        ++steps;
    }
    return steps;
}

double TubeGas::mass() const
{
    double m = 0.0;
    reduce("gas mass", s_->n, s_->serial, Integral{s_->q, 0, s_->h}, m);
    return m;
}

double TubeGas::energy() const
{
    double e = 0.0;
    reduce("gas energy", s_->n, s_->serial, Integral{s_->q, 2, s_->h}, e);
    return e;
}

bool TubeGas::finite() const
{
    int bad = 0;
    reduce("gas non-finite cells", s_->n, s_->serial, NonFiniteCells{s_->q}, bad);
    return bad == 0;
}

double TubeGas::shockPosition(double level) const
{
    const State& s = *s_;
    forEach("gas primitives", s.n, s.serial, ToPrimitive{s.q, s.w, s.areaCell, s.metricCell, s.setup.gamma});
    int face = -1;
    reduce("gas shock face", s.n - 1, s.serial, LastPressureCrossing{s.w, level}, Kokkos::Max<int>(face));
    if (face < 1)
        return -1.0;
    const auto p = Kokkos::create_mirror_view_and_copy(
        Kokkos::HostSpace(), Kokkos::subview(s.w, Kokkos::make_pair(face - 1 + ghosts, face + 1 + ghosts), 2));
    const double left = (face - 0.5) * s.h, right = (face + 0.5) * s.h; // the two cell centres
    return left + (right - left) * (p(0) - level) / (p(0) - p(1));
}

gas::GasViews TubeGas::deviceViews() const { return gas::GasViews{s_->q, s_->areaFace, s_->areaCell, s_->metricFace, s_->metricCell}; }

double leadingShockPosition(const GasFields& f, double level)
{
    for (size_t j = f.p.size() - 1; j > 0; --j)
        if (f.p[j - 1] >= level && f.p[j] < level)
            return f.s[j - 1] + (f.s[j] - f.s[j - 1]) * (f.p[j - 1] - level) / (f.p[j - 1] - f.p[j]);
    return -1.0;
}

GasFields TubeGas::fields() const
{
    const State& s = *s_;
    forEach("gas primitives", s.n, s.serial, ToPrimitive{s.q, s.w, s.areaCell, s.metricCell, s.setup.gamma});
    auto w = Kokkos::create_mirror_view(s.w);
    auto ac = Kokkos::create_mirror_view(s.areaCell);
    Kokkos::deep_copy(w, s.w);
    Kokkos::deep_copy(ac, s.areaCell);
    GasFields out;
    for (int j = 0; j < s.n; ++j)
    {
        out.s.push_back((j + 0.5) * s.h);
        out.rho.push_back(w(j + ghosts, 0));
        out.u.push_back(w(j + ghosts, 1));
        out.p.push_back(w(j + ghosts, 2));
        out.area.push_back(ac(j));
    }
    return out;
}

} // namespace unilag::tube
