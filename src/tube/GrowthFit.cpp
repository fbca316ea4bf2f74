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

//! The fit over given peaks (at least 4): log-linear growth, frequency from their spacing (half periods).
GrowthFit fitPeaks(const std::vector<double>& peakTime, const std::vector<double>& logPeak)
{
    GrowthFit fit;
    fit.peaks = int(peakTime.size());
    if (fit.peaks < 4)
        return fit;
    lineFit(peakTime, logPeak, fit.growthRate, fit.residual);
    fit.frequency = kPi * (fit.peaks - 1) / (peakTime.back() - peakTime.front());
    fit.lastPeak = std::exp(logPeak.back());
    fit.ok = true;
    return fit;
}

} // namespace

GrowthFit fitGrowthSigned(const std::vector<double>& t, const std::vector<double>& y, double from,
                          double maxAmplitude)
{
    std::vector<double> peakTime, logPeak;
    int sign = 0;
    double peak = 0.0, peakAt = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i)
    {
        if (t[i] < from || y[i] == 0.0)
            continue;
        const int s = y[i] > 0.0 ? 1 : -1;
        const double v = std::abs(y[i]);
        if (sign == 0 || (s != sign && v > 0.1 * peak)) // a half cycle ends (a ripple near zero does not)
        {
            if (sign != 0)
            {
                peakTime.push_back(peakAt);
                logPeak.push_back(std::log(peak));
            }
            sign = s;
            peak = 0.0;
        }
        if (s == sign && v > peak)
        {
            peak = v;
            peakAt = t[i];
        }
    }
    if (!peakTime.empty()) // the first half cycle began before `from`: its peak may not be one
    {
        peakTime.erase(peakTime.begin());
        logPeak.erase(logPeak.begin());
    }
    std::vector<double> keptTime, keptLog;
    for (std::size_t i = 0; i < peakTime.size(); ++i)
        if (logPeak[i] <= std::log(maxAmplitude))
        {
            keptTime.push_back(peakTime[i]);
            keptLog.push_back(logPeak[i]);
        }
    return fitPeaks(keptTime, keptLog);
}

GrowthFit fitGrowth(const std::vector<double>& t, const std::vector<double>& a, double from, double maxAmplitude)
{
    GrowthFit fit;
    std::vector<double> peakTime, logPeak;
    for (std::size_t i = 1; i + 1 < t.size(); ++i)
        if (t[i] >= from && a[i] > a[i - 1] && a[i] >= a[i + 1] && a[i] > 0.0 && a[i] <= maxAmplitude)
        {
            peakTime.push_back(t[i]);
            logPeak.push_back(std::log(a[i]));
        }
    fit = fitPeaks(peakTime, logPeak);
    if (fit.ok)
        return fit;
    // a whirl: the distance from the axis has no oscillation to speak of; fit its logarithm directly
    std::vector<double> tw, lw;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (t[i] >= from && a[i] > 0.0 && a[i] <= maxAmplitude)
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
