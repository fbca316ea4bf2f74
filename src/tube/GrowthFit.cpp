#include "tube/GrowthFit.hpp"

#include <cmath>
#include <cstddef>

namespace unilag::tube
{
namespace
{

constexpr double kPi = 3.14159265358979323846;

//! Least squares y = a + b x; returns b and the rms residual.
void lineFit(const std::vector<double>& x, const std::vector<double>& y, double& slope, double& residual)
{
    const double n = double(x.size());
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
        sx += x[i];
        sy += y[i];
        sxx += x[i] * x[i];
        sxy += x[i] * y[i];
    }
    const double det = n * sxx - sx * sx;
    slope = det > 0.0 ? (n * sxy - sx * sy) / det : 0.0;
    const double intercept = (sy - slope * sx) / n;
    double r2 = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i)
        r2 += std::pow(y[i] - intercept - slope * x[i], 2);
    residual = std::sqrt(r2 / n);
}

} // namespace

GrowthFit fitGrowth(const std::vector<double>& t, const std::vector<double>& a, double from)
{
    GrowthFit fit;
    std::vector<double> peakTime, logPeak;
    for (std::size_t i = 1; i + 1 < t.size(); ++i)
        if (t[i] >= from && a[i] > a[i - 1] && a[i] >= a[i + 1] && a[i] > 0.0)
        {
            peakTime.push_back(t[i]);
            logPeak.push_back(std::log(a[i]));
        }
    fit.peaks = int(peakTime.size());
    if (fit.peaks >= 4)
    {
        lineFit(peakTime, logPeak, fit.growthRate, fit.residual);
        fit.frequency = kPi * (fit.peaks - 1) / (peakTime.back() - peakTime.front());
        fit.lastPeak = std::exp(logPeak.back());
        fit.ok = true;
        return fit;
    }
    // a whirl: the distance from the axis has no oscillation to speak of; fit its logarithm directly
    std::vector<double> tw, lw;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= from && a[i] > 0.0)
        {
            tw.push_back(t[i]);
            lw.push_back(std::log(a[i]));
        }
    if (tw.size() >= 16)
    {
        lineFit(tw, lw, fit.growthRate, fit.residual);
        fit.lastPeak = a.back();
        fit.ok = true;
    }
    return fit;
}

} // namespace unilag::tube
