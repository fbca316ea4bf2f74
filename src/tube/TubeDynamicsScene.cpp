#include "tube/TubeDynamicsScene.hpp"

#include "config/Walker.hpp"

namespace unilag::tube
{
namespace
{

using config::ConfigNode;
using config::num;

std::array<double, 3> threeNumbers(ConfigNode& node, const std::string& key, std::array<double, 3> def)
{
    if (!node.has(key))
        return def;
    const std::vector<double> v = node.vector(key);
    std::array<double, 3> out{0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < v.size(); ++i)
        out[i] = v[i];
    for (double x : out)
        if (!std::isfinite(x))
            node.fail(key, "must be finite numbers");
    return out;
}

//! flow: speed (m/s) or critical_fraction (of the linear U_cf), not both; none means no flow.
void readFlow(ConfigNode& d, DynamicsSettings& s)
{
    ConfigNode f = d.sub("flow");
    if (f.has("speed") && f.has("critical_fraction"))
        f.fail("critical_fraction", "give speed or critical_fraction, not both");
    s.flowSpeed = f.nonNegative("speed", 0.0);
    if (f.has("critical_fraction"))
        s.criticalFraction = f.nonNegative("critical_fraction", 1.0);
    f.rejectUnknown();
}

} // namespace

DynamicsSettings readDynamics(ConfigNode& d)
{
    DynamicsSettings s;
    s.segments = int(d.integer("segments", s.segments, 4, 100000));
    s.endTime = d.positive("end_time", s.endTime, true);
    s.stepFactor = d.positive("step_factor", s.stepFactor);
    if (s.stepFactor > 1.0)
        d.fail("step_factor", "must be at most 1 (a fraction of the stable step), found " + num(s.stepFactor));
    readFlow(d, s);
    ConfigNode p = d.sub("perturbation");
    s.tipVelocity = threeNumbers(p, "tip_velocity", s.tipVelocity);
    p.rejectUnknown();
    s.gravity = threeNumbers(d, "gravity", s.gravity);
    s.outputInterval = d.nonNegative("output_interval", s.outputInterval);
    config::refuseTooManyDumps(d, "output_interval", s.outputInterval, s.endTime);
    s.tipRows = int(d.integer("tip_rows", s.tipRows, 2, 100000000));
    s.fitFrom = d.nonNegative("fit_from", s.fitFrom);
    if (s.fitFrom >= 1.0)
        d.fail("fit_from", "must be a fraction of the run in [0, 1), found " + num(s.fitFrom));
    s.fitBelow = d.positive("fit_below", s.fitBelow);
    d.rejectUnknown();
    return s;
}

} // namespace unilag::tube
