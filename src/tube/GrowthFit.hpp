/*! \file GrowthFit.hpp
 *  \brief The growth rate and frequency of an oscillation from its time series (the tip's distance from the
 *  straight axis in a flutter run): least squares of log(peak) against time over the local maxima of the
 *  amplitude after a start time. A planar oscillation y = a e^(sigma t) sin(omega t) has |y|'s peaks every half
 *  period, so omega = pi / (mean spacing); a whirling (3D) one has few peaks, and then log|y| itself is fitted.
 *  fitGrowthSigned does the same from the signed displacement with hysteresis, for planar runs.
 */
#pragma once

#include <cmath>
#include <vector>

namespace unilag::tube
{

struct GrowthFit
{
    bool ok = false;          //!< enough samples (at least 4 peaks, or a whirl over the window) to fit
    double growthRate = 0.0;  //!< sigma, per unit of t
    double frequency = 0.0;   //!< omega (rad per unit of t), 0 when the fit is not over peaks
    int peaks = 0;            //!< peaks in the window
    double lastPeak = 0.0;    //!< the last fitted peak's amplitude
    double residual = 0.0;    //!< rms of the log fit (small: one exponential)
};

/*! The fit of amplitude(t) over t >= from, on the peaks not above maxAmplitude (the linear phase of a run that
 *  saturates later into a limit cycle). t increasing; amplitude >= 0 (a distance). */
GrowthFit fitGrowth(const std::vector<double>& t, const std::vector<double>& amplitude, double from,
                    double maxAmplitude = INFINITY);

/*! The fit of a signed planar oscillation y(t) over t >= from: one peak per half cycle, the largest |y| between
 *  two changes of sign, where a change of sign counts only once |y| exceeds a tenth of the half cycle's peak (so
 *  that a small ripple of the higher modes riding on y near zero makes no extra half cycles). */
GrowthFit fitGrowthSigned(const std::vector<double>& t, const std::vector<double>& y, double from,
                          double maxAmplitude = INFINITY);

} // namespace unilag::tube
