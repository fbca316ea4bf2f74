#include "tube/RankineHugoniot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unilag::tube
{

double ShockSide::entropy(double gamma) const
{
    return std::log(p / std::pow(rho, gamma));
}

namespace
{
//! The least-squares line through (x_i, y_i), evaluated at `at`.
double lineAt(const std::vector<double>& x, const std::vector<double>& y, double at)
{
    const double n = static_cast<double>(x.size());
    double mx = 0, my = 0, sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i)
        mx += x[i] / n, my += y[i] / n;
    for (size_t i = 0; i < x.size(); ++i)
        sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return x.size() < 2 ? my : my + sxy / sxx * (at - mx);
}
} // namespace

ShockSide shockSide(const GasFields& f, const std::vector<std::array<double, 3>>& metric, double from, double to,
                    double at, double gamma)
{
    std::vector<double> s, q[6]; // rho, u, p, metric
    for (size_t j = 0; j < f.s.size(); ++j)
    {
        if (f.s[j] < from || f.s[j] > to)
            continue;
        s.push_back(f.s[j]);
        const double values[6] = {f.rho[j],    f.u[j] / std::sqrt(metric[j][0]), f.p[j], metric[j][0], metric[j][1],
                                  metric[j][2]};
        for (int k = 0; k < 6; ++k)
            q[k].push_back(values[k]);
    }
    if (s.empty())
        throw std::invalid_argument("shockSide: no cell in the window");
    ShockSide out;
    out.rho = lineAt(s, q[0], at), out.u = lineAt(s, q[1], at), out.p = lineAt(s, q[2], at);
    for (int a = 0; a < 3; ++a)
        out.metric[a] = lineAt(s, q[3 + a], at);
    out.e = out.p / ((gamma - 1.0) * out.rho);
    return out;
}

std::array<double, 3> rankineHugoniotDefects(const ShockSide& b, const ShockSide& a, double cs,
                                             const std::array<double, 3>& m)
{
    const double c = m[0], g = m[1], k = m[2];
    const auto jump = [&](auto q) { return q(b) - q(a); };
    const auto speed2 = [&](const ShockSide& s) { return k + 2.0 * s.u * g + s.u * s.u * c; }; // |g + G u|^2
    const double dRho = jump([](const ShockSide& s) { return s.rho; });
    const double dFlux = jump([](const ShockSide& s) { return s.rho * s.u; });
    const std::array<std::array<double, 4>, 3> terms = {{
        {cs * dRho, -dFlux, 0, 0},
        {cs * dRho * g + cs * dFlux * c, -dFlux * g, -jump([](const ShockSide& s) { return s.rho * s.u * s.u; }) * c,
         -jump([](const ShockSide& s) { return s.p; })},
        {cs * jump([&](const ShockSide& s) { return s.rho * (s.e + 0.5 * speed2(s)); }),
         -jump([&](const ShockSide& s) { return 0.5 * s.rho * s.u * speed2(s); }),
         -jump([&](const ShockSide& s) { return s.p / c * (g + s.u * c); }),
         -jump([](const ShockSide& s) { return s.rho * s.u * s.e; })},
    }};
    std::array<double, 3> defect{};
    for (int r = 0; r < 3; ++r)
    {
        double sum = 0, largest = 0;
        for (double t : terms[r])
            sum += t, largest = std::max(largest, std::abs(t));
        defect[r] = std::abs(sum) / largest;
    }
    return defect;
}

double fittedShockSpeed(const std::function<double(double)>& positionAt, double t0, double halfWidth, int samples)
{
    if (samples < 2 || !(halfWidth > 0.0))
        throw std::invalid_argument("fittedShockSpeed: need samples >= 2 and halfWidth > 0");
    std::vector<double> t(samples), x(samples);
    double mt = 0, mx = 0;
    for (int i = 0; i < samples; ++i)
    {
        t[i] = t0 - halfWidth + 2.0 * halfWidth * i / (samples - 1);
        x[i] = positionAt(t[i]);
        mt += t[i] / samples, mx += x[i] / samples;
    }
    double stx = 0, stt = 0;
    for (int i = 0; i < samples; ++i)
        stx += (t[i] - mt) * (x[i] - mx), stt += (t[i] - mt) * (t[i] - mt);
    return stx / stt;
}

ShockJump measureShockJump(const std::function<void(double)>& advance, const std::function<double()>& position,
                           const std::function<std::pair<GasFields, CellMetric>()>& snapshot, double t0, double gamma,
                           const ShockWindows& w)
{
    ShockJump j;
    std::pair<GasFields, CellMetric> state;
    j.speed = fittedShockSpeed(
        [&](double t)
        {
            advance(t);
            const double s = position();
            if (std::abs(t - t0) < 1e-12 * std::max(1.0, std::abs(t0)))
                state = snapshot(), j.position = s;
            return s;
        },
        t0, w.halfWidth, w.samples);
    const double s0 = j.position;
    j.behind = shockSide(state.first, state.second, s0 - w.far, s0 - w.near, s0, gamma);
    j.ahead = shockSide(state.first, state.second, s0 + w.near, s0 + w.far, s0, gamma);
    for (int k = 0; k < 3; ++k)
        j.metric[k] = 0.5 * (j.behind.metric[k] + j.ahead.metric[k]);
    j.defects = rankineHugoniotDefects(j.behind, j.ahead, j.speed, j.metric);
    j.entropyJump = j.behind.entropy(gamma) - j.ahead.entropy(gamma);
    return j;
}

} // namespace unilag::tube
