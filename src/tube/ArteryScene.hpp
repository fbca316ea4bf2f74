/*! \file ArteryScene.hpp
 *  \brief The `artery:` section of a tube scene: one 1D artery with stretchable walls (Artery, docs/tube-artery.md)
 *  driven by a periodic inlet flow and an RCR or reflecting outlet, run through the shared time loop. SI units.
 */
#pragma once

#include <vector>

#include "tube/Artery.hpp"

namespace unilag::config
{
class ConfigNode;
}

namespace unilag::tube
{

//! The inlet flow Q(t) (m^3/s), periodic with `period`.
struct InletWaveform
{
    bool standIn = true;       //!< the study's stand-in carotid pulse (docs/tube-artery.md), scaled to `mean`
    double period = 1.1;       //!< s
    double mean = 6e-6;        //!< m^3/s
    std::vector<double> cosine, sine; //!< harmonics: Q = mean + sum a_k cos(2 pi k t / T) + b_k sin(...)
    double operator()(double t) const;
};

struct ArterySettings
{
    ArteryConfig config; //!< vessel, wall tension, blood, cells, outlet (inletFlux set by the run from `inlet`)
    InletWaveform inlet;
    int cycles = 10;                 //!< the run's length, in periods
    int samplesPerCycle = 200;       //!< probe samples a period (waveforms.csv, periodicity)
    int dumpsPerCycle = 0;           //!< XDMF dumps a period (0: first and last state only); divides the samples
    double periodicTolerance = 1e-3; //!< cycle-to-cycle change below which the run is periodic
};

//! Reads `artery:`; every key is validated. Throws InputError naming the file and key.
ArterySettings readArtery(config::ConfigNode& artery);

} // namespace unilag::tube
