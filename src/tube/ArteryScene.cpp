#include "tube/ArteryScene.hpp"

#include <cmath>
#include <string>

#include "config/Walker.hpp"

namespace unilag::tube
{
namespace
{

using config::ConfigNode;
using config::num;
constexpr double kPi = 3.14159265358979323846;

//! A unit Gaussian bump of the given centre and width, repeated with the period (images at -T, 0, T: smooth).
double bump(double t, double period, double centre, double width)
{
    const double tau = std::fmod(t, period);
    double sum = 0;
    for (int m = -1; m <= 1; ++m)
        sum += std::exp(-0.5 * std::pow((tau - centre - m * period) / width, 2));
    return sum;
}

/*! The stand-in carotid pulse of apps/tube_artery_study (docs/tube-artery.md: the benchmark's inlet file is not
 *  available): a systolic bump at 0.15 s (14 ml/s, width 0.06 s) and a dicrotic one at 0.42 s (3 ml/s, 0.04 s)
 *  on a diastolic level set for a mean of 6 ml/s, period 1.1 s; scaled here by mean / 6 ml/s. */
double standInFlow(double t, double mean, double period)
{
    constexpr double kMean = 6e-6, kSystole = 14e-6, kNotch = 3e-6;
    const double root2pi = std::sqrt(2 * kPi);
    const double diastole = kMean - (kSystole * 0.06 + kNotch * 0.04) * root2pi / period;
    const double q = diastole + kSystole * bump(t, period, 0.15, 0.06) + kNotch * bump(t, period, 0.42, 0.04);
    return q * mean / kMean;
}

//! inlet: {waveform: stand_in | harmonics, period, mean, cosine: [...], sine: [...]} (the flux inlet).
InletWaveform readInlet(ConfigNode& a)
{
    ConfigNode in = a.sub("inlet");
    InletWaveform w;
    w.standIn = in.choice("waveform", "stand_in", {"stand_in", "harmonics"}) == "stand_in";
    w.period = in.positive("period", w.period);
    w.mean = in.nonNegative("mean", w.mean);
    for (const char* key : {"cosine", "sine"})
        if (w.standIn && in.has(key))
            in.fail(key, "the stand_in waveform has no harmonics; set waveform: harmonics");
    if (!w.standIn)
    {
        w.cosine = in.has("cosine") ? in.numbers("cosine") : std::vector<double>();
        w.sine = in.has("sine") ? in.numbers("sine") : std::vector<double>();
    }
    in.rejectUnknown();
    return w;
}

//! outlet: {type: rcr, R1, R2, C} or {type: reflection, coefficient} (R_t in [-1, 1]; 0 absorbs).
void readOutlet(ConfigNode& a, ArteryConfig& c)
{
    ConfigNode out = a.sub("outlet");
    const bool rcr = out.choice("type", "rcr", {"rcr", "reflection"}) == "rcr";
    for (const char* key : {"R1", "R2", "C"})
        if (!rcr && out.has(key))
            out.fail(key, "a reflection outlet takes only `coefficient`");
    if (rcr && out.has("coefficient"))
        out.fail("coefficient", "an rcr outlet takes R1, R2 and C");
    if (rcr)
    {
        c.outlet = artery::OutletKind::Windkessel;
        c.R1 = out.nonNegative("R1", 2.4875e8);
        c.R2 = out.positive("R2", 1.8697e9);
        c.C = out.positive("C", 1.7529e-10);
    }
    else
    {
        c.outlet = artery::OutletKind::Reflection;
        c.reflection = out.number("coefficient", 0.0);
        if (!(std::abs(c.reflection) <= 1.0))
            out.fail("coefficient", "must be in [-1, 1], found " + num(c.reflection));
    }
    out.rejectUnknown();
}

} // namespace

double InletWaveform::operator()(double t) const
{
    if (standIn)
        return standInFlow(t, mean, period);
    double q = mean;
    for (std::size_t k = 0; k < cosine.size(); ++k)
        q += cosine[k] * std::cos(2 * kPi * double(k + 1) * t / period);
    for (std::size_t k = 0; k < sine.size(); ++k)
        q += sine[k] * std::sin(2 * kPi * double(k + 1) * t / period);
    return q;
}

ArterySettings readArtery(ConfigNode& a)
{
    ArterySettings s;
    ArteryConfig& c = s.config;
    c.length = a.positive("length", c.length);
    c.radius = a.positive("radius", c.radius);
    c.wall = a.positive("wall_thickness", c.wall);
    if (c.wall >= c.radius) // the thin-wall law beta = sqrt(pi) h E / ((1 - nu^2) A0) needs h well below R
        a.fail("wall_thickness", "must be less than the radius (" + num(c.radius) + " m) for the thin-wall law, "
                                 "found " + num(c.wall));
    c.young = a.positive("youngs_modulus", c.young);
    c.poisson = a.number("poisson_ratio", c.poisson);
    if (!(c.poisson > -1.0 && c.poisson < 1.0))
        a.fail("poisson_ratio", "must be in (-1, 1), found " + num(c.poisson));
    c.density = a.positive("density", c.density);
    c.viscosity = a.nonNegative("viscosity", c.viscosity);
    c.gammaProfile = a.positive("gamma_profile", c.gammaProfile);
    c.tension = a.nonNegative("tension", c.tension); // F_z (N); the law's T = F_z / (4 pi A0)
    c.cells = int(a.integer("cells", c.cells, 4, 1000000));
    c.cfl = a.positive("cfl", c.cfl);
    if (c.cfl > 1.0)
        a.fail("cfl", "must be at most 1, found " + num(c.cfl));
    s.inlet = readInlet(a);
    c.inlet = artery::InletKind::Flux;
    readOutlet(a, c);
    s.cycles = int(a.integer("cycles", s.cycles, 1, 1000));
    s.samplesPerCycle = int(a.integer("samples_per_cycle", s.samplesPerCycle, 4, 100000));
    s.dumpsPerCycle = int(a.integer("dumps_per_cycle", s.dumpsPerCycle, 0, s.samplesPerCycle));
    if (s.dumpsPerCycle > 0 && s.samplesPerCycle % s.dumpsPerCycle != 0)
        a.fail("dumps_per_cycle", "must divide samples_per_cycle (" + std::to_string(s.samplesPerCycle) + ")");
    s.periodicTolerance = a.positive("periodic_tolerance", s.periodicTolerance);
    a.rejectUnknown();
    return s;
}

} // namespace unilag::tube
