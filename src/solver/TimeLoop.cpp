#include "solver/TimeLoop.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <memory>
#include <csignal>
#include <unistd.h>

#include "core/Format.hpp"

namespace unilag
{
namespace
{

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t stopSignal = 0;
extern "C" void requestStop(int signal) { stopSignal = signal; }

/*! While alive, SIGTERM and SIGINT ask the loop to stop at the end of the current step (with a checkpoint) instead
 *  of killing the process; the previous handlers come back after. */
class StopOnSignal
{
  public:
    explicit StopOnSignal(bool enabled) : enabled_(enabled)
    {
        if (!enabled_)
            return;
        stopSignal = 0;
        term_ = std::signal(SIGTERM, requestStop);
        int_ = std::signal(SIGINT, requestStop);
    }
    ~StopOnSignal()
    {
        if (!enabled_)
            return;
        std::signal(SIGTERM, term_);
        std::signal(SIGINT, int_);
    }
    //! The signal any rank has received (0: none). Collective.
    static int received(MPI_Comm comm)
    {
        int s = int(stopSignal);
        MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_INT, MPI_MAX, comm);
        return s;
    }

  private:
    bool enabled_;
    void (*term_)(int) = SIG_DFL;
    void (*int_)(int) = SIG_DFL;
};

//! The progress line: on a terminal one updating line, otherwise a line every 5 seconds (rank 0).
class Progress
{
  public:
    Progress(bool enabled, double endTime) : enabled_(enabled), endTime_(endTime), tty_(isatty(fileno(stdout))) {}
    void report(long step, double t, double dt)
    {
        if (!enabled_)
            return;
        const auto now = Clock::now();
        const double since = std::chrono::duration<double>(now - last_).count();
        if ((tty_ && since > 0.2) || since > 5.0)
        {
            const double el = std::chrono::duration<double>(now - start_).count();
            const double eta = el * (endTime_ - t) / std::max(t, 1e-300);
            std::printf("%sstep %ld  t %.6g  dt %.3g  %5.1f%%  ETA %.0fs%s", tty_ ? "\r" : "", step, t, dt,
                        100.0 * t / endTime_, eta, tty_ ? "   " : "\n");
            std::fflush(stdout);
            last_ = now;
        }
    }
    ~Progress()
    {
        if (enabled_ && tty_)
            std::printf("\n");
    }

  private:
    bool enabled_;
    double endTime_;
    bool tty_;
    Clock::time_point start_ = Clock::now(), last_ = start_;
};

/*! The step size before any halving: the stable step, a tenth of it first, at most maxGrowth times the last one,
 *  and clipped to the next output time. Sets failure if it is not positive or has collapsed. */
double chooseStep(TimeSystem& system, const TimeControl& c, double t, double dtPrev, long step, double nextOutput,
                  std::string& failure)
{
    double dt = system.prepareStep(t, step);
    if (!(dt > 0.0) || !std::isfinite(dt))
    {
        failure = "the stable time step is " + jsonNumber(dt) + " at t = " + jsonNumber(t);
        return 0.0;
    }
    dt = dtPrev > 0.0 ? std::min(dt, c.maxGrowth * dtPrev) : 0.1 * dt;
    if (dt < 1e-12 * c.endTime)
    {
        failure = system.collapse(t, dt, step);
        return 0.0;
    }
    const double target = std::min(nextOutput, c.endTime);
    if (t + dt > target * (1.0 - 1e-12))
        dt = target - t;
    if (!(dt > 0.0))
        failure = "internal: zero time step at t = " + jsonNumber(t) + " (output time " + jsonNumber(target) + ")";
    return dt;
}

} // namespace

LoopResult runTimeLoop(TimeSystem& system, const TimeControl& c, MPI_Comm comm, LoopState from)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    LoopResult r;
    LoopState& s = r.state;
    s = from;
    if (s.dtPrev < 0.0)
        s.dtPrev = c.initialTimeStep;
    if (s.nextOutput < 0.0)
        s.nextOutput = c.outputInterval > 0 ? c.outputInterval : c.endTime;
    if (s.initialTotals.empty())
        s.initialTotals = system.totals();
    r.initialTotals = s.initialTotals;
    if (s.nextCheckpoint < 0.0)
        s.nextCheckpoint = c.checkpointInterval;
    if (s.dumps == 0)
        system.write(s.dumps++, s.t);
    std::unique_ptr<std::ofstream> steps;
    if (rank == 0 && !c.stepsCsv.empty())
    {
        // a restarted run goes on with the rows of the run it continues, up to its checkpoint's step
        std::vector<std::string> kept = {"step,t,dt,picard_iterations,dt_halvings"};
        std::ifstream old(s.steps > 0 ? c.stepsCsv : std::string());
        for (std::string line; std::getline(old, line) && long(kept.size()) <= s.steps;)
            if (line.rfind("step,", 0) != 0)
                kept.push_back(line);
        steps = std::make_unique<std::ofstream>(c.stepsCsv);
        for (const std::string& line : kept)
            *steps << line << '\n';
    }
    const auto wall0 = Clock::now();
    {
        Progress progress(c.progress && rank == 0, c.endTime);
        StopOnSignal stop(c.checkpointOnSignal);
        while (s.t < c.endTime * (1.0 - 1e-14) && s.steps < c.maxSteps)
        {
            if (c.checkpointOnSignal && (r.signal = StopOnSignal::received(comm)) != 0)
            {
                if (steps)
                    steps->flush();
                system.checkpoint(s);
                break;
            }
            double dt = chooseStep(system, c, s.t, s.dtPrev, s.steps, s.nextOutput, r.failure);
            if (!r.failure.empty())
                break;
            // Rejected steps (an inverted cell, an inadmissible state, an unconverged implicit solve) are retried
            // with half the step; the rates at t do not depend on dt.
            system.beginAttempts();
            int attempt = 0, iterations = 0;
            bool ok = false;
            for (;; ++attempt)
            {
                ok = system.attemptStep(s.t, dt, attempt, iterations);
                if (ok || attempt >= c.maxRetries)
                    break;
                dt *= 0.5;
                ++s.retries;
            }
            if (!ok)
            {
                r.failure = system.failure(s.t, dt, attempt);
                break;
            }
            system.acceptStep(s.t, dt, iterations);
            if (steps)
                *steps << s.steps + 1 << ',' << std::setprecision(12) << s.t + dt << ',' << dt << ',' << iterations
                       << ',' << attempt << '\n';
            s.t += dt;
            s.dtPrev = dt;
            ++s.steps;
            if (s.t >= s.nextOutput * (1.0 - 1e-12) && s.t < c.endTime * (1.0 - 1e-14))
            {
                system.write(s.dumps++, s.t);
                s.nextOutput = c.outputInterval > 0 ? s.nextOutput + c.outputInterval : c.endTime;
            }
            if (c.checkpointInterval > 0.0 && s.t >= s.nextCheckpoint * (1.0 - 1e-12) &&
                s.t < c.endTime * (1.0 - 1e-14))
            {
                while (s.nextCheckpoint <= s.t * (1.0 + 1e-12)) // one checkpoint even if a step spans several
                    s.nextCheckpoint += c.checkpointInterval;
                if (steps)
                    steps->flush(); // the checkpoint's steps.csv is complete up to its step
                system.checkpoint(s);
            }
            progress.report(s.steps, s.t, dt);
        }
    }
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - wall0).count();
    r.stepCapped = r.failure.empty() && r.signal == 0 && s.t < c.endTime * (1.0 - 1e-14);
    if (r.failure.empty())
        system.write(s.dumps++, s.t);
    r.finalTotals = system.totals();
    return r;
}

} // namespace unilag
