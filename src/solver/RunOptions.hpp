/*! \file RunOptions.hpp
 *  \brief Options of a run that come from the command line, not the scene, and the time control a scene gives.
 */
#pragma once

#include <algorithm>
#include <filesystem>

#include "config/Scene.hpp"
#include "solver/TimeLoop.hpp"

namespace unilag
{

struct RunOptions
{
    bool check = false; //!< assert conservation and the scene's error bounds
    int threads = 1;    //!< Kokkos threads (reported)
    bool progress = true;
    std::string restart; //!< checkpoint to continue from ("" for a new run)
};

//! The time loop's settings from a continuum scene.
inline TimeControl timeControl(const Scene& scene, const RunOptions& options)
{
    TimeControl c;
    c.endTime = scene.endTime;
    c.outputInterval = scene.writeOutput ? scene.outputInterval : 0.0; // no output: no step cut to its times
    c.initialTimeStep = scene.initialTimeStep;
    c.maxGrowth = scene.maxGrowth;
    c.maxSteps = scene.maxSteps;
    c.stopStalled = !scene.maxStepsGiven;
    c.maxRetries = scene.maxRetries;
    c.progress = options.progress;
    c.stepsCsv = (std::filesystem::path(scene.outputDirectory) / "steps.csv").string();
    c.checkpointInterval = scene.checkpointInterval;
    c.checkpointOnSignal = true;
    c.balanceInterval = scene.balanceInterval;
    c.earlyBalanceInterval = scene.earlyChecks();
    c.imbalanceThreshold = scene.imbalanceThreshold;
    c.repartition = scene.repartition;
    c.rankSpeeds = scene.rankSpeeds;
    c.balanceCsv = (std::filesystem::path(scene.outputDirectory) / "balance.csv").string();
    return c;
}

} // namespace unilag
