#include "tube/RiemannExact.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unilag::tube
{

RiemannExact::RiemannExact(const GasPrimitive& left, const GasPrimitive& right, double gamma)
    : l_(left), r_(right), g_(gamma)
{
    const double al = std::sqrt(gamma * left.p / left.rho), ar = std::sqrt(gamma * right.p / right.rho);
    const double du = right.u - left.u;
    if (2.0 * (al + ar) / (gamma - 1.0) <= du)
        throw std::runtime_error("RiemannExact: the data create a vacuum");
    // start from the two-rarefaction guess (exact for two rarefactions), then Newton on f_L + f_R + du = 0
    const double z = (gamma - 1.0) / (2.0 * gamma);
    double p = std::pow((al + ar - 0.5 * (gamma - 1.0) * du) / (al / std::pow(left.p, z) + ar / std::pow(right.p, z)),
                        1.0 / z);
    for (int it = 0; it < 100; ++it)
    {
        double fl, dfl, fr, dfr;
        side(p, left, fl, dfl);
        side(p, right, fr, dfr);
        const double next = std::max(1e-14 * (left.p + right.p), p - (fl + fr + du) / (dfl + dfr));
        const bool done = std::abs(next - p) <= 1e-15 * (next + p);
        p = next;
        if (done)
            break;
    }
    double fl, dfl, fr, dfr;
    side(p, left, fl, dfl);
    side(p, right, fr, dfr);
    pStar_ = p;
    uStar_ = 0.5 * (left.u + right.u) + 0.5 * (fr - fl);
}

void RiemannExact::side(double p, const GasPrimitive& w, double& f, double& df) const
{
    const double a = std::sqrt(g_ * w.p / w.rho);
    if (p > w.p)
    {
        const double A = 2.0 / ((g_ + 1.0) * w.rho), B = (g_ - 1.0) / (g_ + 1.0) * w.p;
        const double q = std::sqrt(A / (p + B));
        f = (p - w.p) * q;
        df = q * (1.0 - 0.5 * (p - w.p) / (p + B));
    }
    else
    {
        const double z = (g_ - 1.0) / (2.0 * g_);
        f = 2.0 * a / (g_ - 1.0) * (std::pow(p / w.p, z) - 1.0);
        df = std::pow(p / w.p, -(g_ + 1.0) / (2.0 * g_)) / (w.rho * a);
    }
}

//! One side of the solution, written for the left side; the right side is its mirror (sign = -1: x -> -x,
//! u -> -u), which halves the case analysis.
GasPrimitive RiemannExact::sampleSide(double x, const GasPrimitive& w0, double sign) const
{
    const GasPrimitive w{w0.rho, sign * w0.u, w0.p};
    const double us = sign * uStar_, ps = pStar_, g = g_;
    const double a = std::sqrt(g * w.p / w.rho);
    GasPrimitive out;
    if (ps > w.p) // shock
    {
        const double ratio = ps / w.p, k = (g - 1.0) / (g + 1.0);
        const double speed = w.u - a * std::sqrt((g + 1.0) / (2.0 * g) * ratio + (g - 1.0) / (2.0 * g));
        out = x < speed ? w : GasPrimitive{w.rho * (ratio + k) / (k * ratio + 1.0), us, ps};
    }
    else // rarefaction
    {
        const double as = a * std::pow(ps / w.p, (g - 1.0) / (2.0 * g));
        if (x < w.u - a)
            out = w;
        else if (x > us - as)
            out = GasPrimitive{w.rho * std::pow(ps / w.p, 1.0 / g), us, ps};
        else // inside the fan
        {
            const double c = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * a) * (w.u - x);
            out = GasPrimitive{w.rho * std::pow(c, 2.0 / (g - 1.0)), 2.0 / (g + 1.0) * (a + 0.5 * (g - 1.0) * w.u + x),
                               w.p * std::pow(c, 2.0 * g / (g - 1.0))};
        }
    }
    out.u *= sign;
    return out;
}

GasPrimitive RiemannExact::sample(double xOverT) const
{
    return xOverT < uStar_ ? sampleSide(xOverT, l_, 1.0) : sampleSide(-xOverT, r_, -1.0);
}

double shockMachFromPressureRatio(double pressureRatio, double gamma)
{
    return std::sqrt(1.0 + (gamma + 1.0) / (2.0 * gamma) * (pressureRatio - 1.0));
}

GasPrimitive postShockState(const GasPrimitive& ahead, double machNumber, double gamma)
{
    const double m2 = machNumber * machNumber, a1 = std::sqrt(gamma * ahead.p / ahead.rho);
    GasPrimitive behind;
    behind.p = ahead.p * (1.0 + 2.0 * gamma / (gamma + 1.0) * (m2 - 1.0));
    behind.rho = ahead.rho * (gamma + 1.0) * m2 / ((gamma - 1.0) * m2 + 2.0);
    behind.u = ahead.u + a1 * 2.0 * (m2 - 1.0) / ((gamma + 1.0) * machNumber);
    return behind;
}

} // namespace unilag::tube
