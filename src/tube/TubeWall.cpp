#include "tube/TubeWall.hpp"

#include <cmath>
#include <stdexcept>

#include "tube/SmallLaunch.hpp"
#include "unilag/TubeWall.hpp"

namespace unilag::tube
{

using namespace unilag::wall;
using launch::forEach; // small tubes run on Kokkos::Serial (GasSetup::serialBelow)
using launch::reduce;

WallCoefficients wallCoefficients(const WallMaterial& m, double pExt)
{
    if (!(m.thickness > 0.0) || !(m.restRadius > 0.0) || !(m.youngModulus > 0.0) || !(m.poisson < 1.0) ||
        !(m.axialTension >= 0.0))
        throw std::invalid_argument("wallCoefficients: need h, R0, E > 0, nu < 1 and N_x >= 0");
    WallCoefficients w;
    w.a = m.density * 2.0 * pi * m.restRadius * m.thickness;
    w.b = 2.0 * pi * m.youngModulus * m.thickness / (m.restRadius * (1.0 - m.poisson * m.poisson));
    w.c = m.viscosity;
    w.restRadius = m.restRadius;
    w.pExt = pExt;
    w.as = 2.0 * pi * m.restRadius * m.axialTension;
    return w;
}

double equilibriumRadius(const WallCoefficients& w, double p)
{
    const double load = 2.0 * pi * (p - w.pExt);
    if (load >= w.b)
        throw std::domain_error("equilibriumRadius: past the bulge limit p - p_ext = b / (2 pi)");
    return w.b * w.restRadius / (w.b - load);
}

double compliance(const WallCoefficients& w, double p)
{
    const double r = equilibriumRadius(w, p);
    return 4.0 * pi * pi * r * r * r / (w.b * w.restRadius);
}

double compliantSpeed(const WallCoefficients& w, double rho, double p, double gamma)
{
    const double r = equilibriumRadius(w, p);
    const double inverseSquare = rho / (gamma * p) + rho / (pi * r * r) * compliance(w, p);
    return 1.0 / std::sqrt(inverseSquare);
}

struct TubeWall::State
{
    WallCoefficients coefficients;
    int n = 0;
    double h = 0;
    bool serial = false;
    WallViews views;
};

TubeWall::TubeWall(TubeWall&&) noexcept = default;
TubeWall& TubeWall::operator=(TubeWall&&) noexcept = default;
TubeWall::~TubeWall() = default;

TubeWall::TubeWall(const WallCoefficients& coefficients, int cells, double length, bool serial)
    : s_(std::make_unique<State>())
{
    if (cells < 1 || !(length > 0.0) || !(coefficients.a > 0.0) || !(coefficients.b >= 0.0) ||
        !(coefficients.c >= 0.0) || !(coefficients.restRadius > 0.0) || !(coefficients.as >= 0.0))
        throw std::invalid_argument("TubeWall: need cells >= 1, length > 0, a > 0, b >= 0, c >= 0, R0 > 0, as >= 0");
    State& s = *s_;
    s.coefficients = coefficients;
    s.n = cells;
    s.h = length / cells;
    s.serial = serial;
    s.views.radius = ScalarView("wall R", cells);
    s.views.speed = ScalarView("wall dR/dt", cells);
    s.views.dissipated = ScalarView("wall dissipated", cells);
    if (coefficients.as > 0.0)
    {
        s.views.step = ScalarView("wall tension step", cells);
        s.views.cPrime = ScalarView("wall tension c'", cells);
        s.views.rPrime = ScalarView("wall tension r'", cells);
    }
    const double r0 = coefficients.restRadius;
    setState([r0](double) { return r0; }, [](double) { return 0.0; });
}

const WallCoefficients& TubeWall::coefficients() const
{
    return s_->coefficients;
}
int TubeWall::cells() const
{
    return s_->n;
}
WallViews TubeWall::deviceViews() const
{
    return s_->views;
}

void TubeWall::setState(const std::function<double(double)>& radius, const std::function<double(double)>& speed)
{
    State& s = *s_;
    auto r = Kokkos::create_mirror_view(s.views.radius);
    auto v = Kokkos::create_mirror_view(s.views.speed);
    for (int j = 0; j < s.n; ++j)
    {
        r(j) = radius((j + 0.5) * s.h);
        v(j) = speed((j + 0.5) * s.h);
        if (!(r(j) > 0.0))
            throw std::invalid_argument("TubeWall::setState: radius must be > 0");
    }
    Kokkos::deep_copy(s.views.radius, r);
    Kokkos::deep_copy(s.views.speed, v);
    Kokkos::deep_copy(s.views.dissipated, 0.0);
}

WallEnergy TubeWall::energy() const
{
    const State& s = *s_;
    const WallCoefficients& c = s.coefficients;
    const WallParams p{c.a, c.b, c.c, c.restRadius, c.pExt, c.as};
    double parts[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
        reduce("wall energy", s.n, s.serial, WallEnergyPart{s.views.radius, s.views.speed, p, s.h, k}, parts[k]);
    WallEnergy e;
    e.kinetic = parts[0];
    e.elastic = parts[1];
    e.outside = parts[2];
    reduce("wall tension energy", s.n - 1, s.serial, WallTensionEnergy{s.views.radius, c.as, s.h}, e.tension);
    reduce("wall dissipated", s.n, s.serial, SumTimesH{s.views.dissipated, s.h}, e.dissipated);
    return e;
}

WallFields TubeWall::fields() const
{
    const State& s = *s_;
    auto r = Kokkos::create_mirror_view(s.views.radius);
    auto v = Kokkos::create_mirror_view(s.views.speed);
    Kokkos::deep_copy(r, s.views.radius);
    Kokkos::deep_copy(v, s.views.speed);
    WallFields f;
    for (int j = 0; j < s.n; ++j)
    {
        f.radius.push_back(r(j));
        f.speed.push_back(v(j));
    }
    return f;
}

} // namespace unilag::tube
