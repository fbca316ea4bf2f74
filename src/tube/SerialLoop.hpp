/*! \file SerialLoop.hpp
 *  \brief The time loop of a tube run, on rank 0 alone (RankZero.hpp), with what every tube run sets the same way.
 */
#pragma once

#include <chrono>

#include "solver/TimeLoop.hpp"

namespace unilag::tube
{

struct TimedLoop
{
    LoopResult loop;
    double wall = 0.0; //!< seconds, the first and last dumps included (LoopResult::wallSeconds leaves them out)
};

/*! Runs system from t = 0 to endTime on MPI_COMM_SELF with the tube runs' settings: no halvings (a tube step is
 *  stable by construction, or the run stops with its diagnosis) and the first step given (no ramp). control
 *  carries any other setting (steps CSV); progress: the progress line (TubeScene::progress). */
inline TimedLoop runTubeLoop(TimeSystem& system, double endTime, double outputInterval, double firstStep,
                             bool progress, TimeControl control = TimeControl())
{
    control.progress = progress;
    control.endTime = endTime;
    control.outputInterval = outputInterval;
    control.maxRetries = 0;
    control.initialTimeStep = firstStep;
    const auto start = std::chrono::steady_clock::now();
    TimedLoop r{runTimeLoop(system, control, MPI_COMM_SELF)};
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

} // namespace unilag::tube
