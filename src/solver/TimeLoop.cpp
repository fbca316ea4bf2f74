#include "solver/TimeLoop.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <csignal>
#include <unistd.h>

#include "core/Format.hpp"
#include "core/Mpi.hpp"
#include "io/OutputFolder.hpp"
#include "solver/CostFit.hpp"

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
        mpi::WaitTimer wait;
        int s = int(stopSignal);
        MPI_Allreduce(MPI_IN_PLACE, &s, 1, MPI_INT, MPI_MAX, comm);
        return s;
    }

  private:
    bool enabled_;
    void (*term_)(int) = SIG_DFL;
    void (*int_)(int) = SIG_DFL;
};

/*! The load balance: each rank's busy time in the steps (CPU time less mpi::waitSeconds, the time it waited for
 *  the others), compared over the ranks every balanceInterval steps, and every earlyBalanceInterval steps through
 *  the first balanceInterval of a run or restart (the start-up partition balances cells, not their cost, which
 *  shows as the first steps form a plastic zone, say). Above the threshold the system repartitions, if its cost
 *  model sees an imbalance too (above Zoltan2's tolerance, 1.05): an imbalance the model does not see, a new
 *  partition by that model cannot remove; or when the model forecasts one for the next window (a plastic zone
 *  forming). Checks come early after a repartition and while the forecast differs from the last window. With
 *  rankSpeeds the model knows each rank's measured speed (a rank slowed on a shared core, say). A threshold below 1
 *  repartitions at every check. A few reductions of a few numbers per check; docs/parallel.md 2. */
class LoadBalancer
{
  public:
    //! fromStep: the step a restarted run continues from (its balance.csv keeps the rows up to there)
    LoadBalancer(const TimeControl& c, MPI_Comm comm, long fromStep)
        : c_(c), comm_(comm), size_(mpi::size(comm)), fromStep_(fromStep),
          on_(c.balanceInterval > 0 && (size_ > 1 || (c.repartition && c.imbalanceThreshold < 1.0)))
    {
        // A restart without checks (on one rank) still cuts the rows of the abandoned run past its checkpoint.
        const bool restartedCsv = fromStep > 0 && std::filesystem::exists(c_.balanceCsv);
        if ((!on_ && !restartedCsv) || mpi::rank(comm) != 0 || c_.balanceCsv.empty())
            return;
        std::vector<std::string> kept = {
            "step,t,imbalance,model_imbalance,repartitioned,cells_moved,seconds,work_cost,speed_spread,forecast"};
        std::ifstream old(fromStep > 0 ? c_.balanceCsv : std::string());
        for (std::string line; std::getline(old, line);)
            if (line.rfind("step,", 0) != 0 && std::strtol(line.c_str(), nullptr, 10) <= fromStep)
                kept.push_back(line);
        csv_ = std::make_unique<std::ofstream>(c_.balanceCsv);
        for (const std::string& line : kept)
            *csv_ << line << '\n';
        if (!on_ || !*csv_) // nothing more to write, or a folder in its place (finish throws)
        {
            finish();
            csv_.reset();
        }
    }
    //! rank 0 closes balance.csv: OutputError if it could not be written
    void finish()
    {
        if (csv_)
            io::finishOutput(*csv_, c_.balanceCsv);
    }
    void startStep()
    {
        if (!on_)
            return;
        start_ = mpi::cpuSeconds();
        waited_ = mpi::waitSeconds();
    }
    void endStep()
    {
        if (on_)
            busy_ += mpi::cpuSeconds() - start_ - (mpi::waitSeconds() - waited_);
    }
    //! After accepted step number step (ending at t): the check, and the repartition it calls for. Collective.
    void check(TimeSystem& system, long step, double t, LoopResult& r)
    {
        const long since = step - fromStep_; // early checks: the start-up partition's cost (class comment)
        // early checks: through the first interval, and after a repartition until a check finds no need of one
        const bool early = c_.earlyBalanceInterval > 0 && (since < c_.balanceInterval || following_) &&
                           since % c_.earlyBalanceInterval == 0;
        if (!on_ || (step % c_.balanceInterval != 0 && !early))
            return;
        const std::vector<double> busy = refit(system);
        double sum = 0.0, largest = 0.0;
        for (double b : busy)
        {
            sum += b;
            largest = std::max(largest, b);
        }
        const double imbalance = sum > 0.0 ? largest * size_ / sum : 1.0;
        busy_ = 0.0;
        const double model = system.modelImbalance();
        const double forecast = system.forecastImbalance();
        const auto weights = system.costWeights();
        r.balanceChecks.push_back({step, t, imbalance, model, weights.size() > 1 ? weights[1] : 0.0, spread_});
        if (!r.repartitions.empty() && r.repartitions.back().after < 0.0)
            r.repartitions.back().after = imbalance;
        RepartitionEvent e{step, t, imbalance};
        const bool forced = c_.imbalanceThreshold < 1.0;
        // the measured window, confirmed by the model (class comment), or the model's forecast of the next one
        const bool move = c_.repartition && repartitionable_ &&
                          ((imbalance > c_.imbalanceThreshold && (forced || model > modelTolerance)) ||
                           forecast > c_.imbalanceThreshold);
        if (move)
        {
            const auto t0 = Clock::now();
            e.cellsMoved = system.repartition();
            e.seconds = mpi::allMax(comm_, std::chrono::duration<double>(Clock::now() - t0).count());
            repartitionable_ = e.cellsMoved >= 0;
            following_ = repartitionable_ && !forced; // forced: the checks stay where the scene puts them
            if (repartitionable_)
                r.repartitions.push_back(e);
        }
        else // the cost is still moving where the forecast and the last window differ
            following_ = std::abs(forecast - model) > movingCost;
        if (csv_)
            *csv_ << step << ',' << std::setprecision(12) << t << ',' << imbalance << ',' << model << ','
                  << (move ? 1 : 0) << ',' << e.cellsMoved << ',' << e.seconds << ',' << r.balanceChecks.back().workCost
                  << ',' << spread_ << ',' << forecast << '\n';
    }

  private:
    //! Every rank's busy time since the last check, in rank order; the system's cost weights refitted to them.
    std::vector<double> refit(TimeSystem& system)
    {
        std::vector<double> mine = system.costTerms();
        const std::size_t k = mine.size();
        mine.insert(mine.begin(), busy_);
        const std::vector<double> all = mpi::allGather(comm_, mine);
        const auto ranks = std::size_t(size_);
        std::vector<double> busy(ranks);
        std::vector<std::vector<double>> terms(ranks);
        for (std::size_t p = 0; p < busy.size(); ++p)
        {
            busy[p] = all[(k + 1) * p];
            terms[p].assign(all.begin() + long((k + 1) * p + 1), all.begin() + long((k + 1) * (p + 1)));
        }
        if (k > 1)
        {
            if (!fit_)
                fit_ = std::make_unique<CostFit>(system.costWeights());
            fit_->add(busy, terms);
            system.setCostWeights(fit_->weights());
        }
        const std::vector<double> speed = k > 0 ? speeds(busy, terms, system.costWeights()) : std::vector<double>();
        spread_ = speed.empty() ? 0.0 : *std::max_element(speed.begin(), speed.end()) /
                                             *std::min_element(speed.begin(), speed.end());
        if (c_.rankSpeeds && !speed.empty())
            system.setRankSpeed(relativeSpeed(speed));
        return busy;
    }

    /*! Each rank's busy time per unit of modelled cost, inverted: its speed. Equal where the model explains the
     *  ranks' times; apart where ranks ran at different speeds (a shared core) or the model misses a cost that sits
     *  on some ranks. Empty where a rank has no modelled cost or no busy time. */
    static std::vector<double> speeds(const std::vector<double>& busy, const std::vector<std::vector<double>>& terms,
                                      const std::vector<double>& weights)
    {
        std::vector<double> speed(busy.size());
        for (std::size_t p = 0; p < busy.size(); ++p)
        {
            double cost = 0.0;
            for (std::size_t i = 0; i < weights.size() && i < terms[p].size(); ++i)
                cost += weights[i] * terms[p][i];
            if (!(cost > 0.0) || !(busy[p] > 0.0))
                return {};
            speed[p] = cost / busy[p];
        }
        return speed;
    }

    /*! This rank's speed relative to the ranks' mean, averaged with the earlier checks' (halving their weight at
     *  each check: one window's speed is noisy, a shared core's lasts minutes) and kept within [1/2, 2]. */
    double relativeSpeed(const std::vector<double>& speed)
    {
        double mean = 0.0;
        for (double v : speed)
            mean += v / double(speed.size());
        relative_.resize(speed.size(), 1.0);
        for (std::size_t p = 0; p < speed.size(); ++p)
            relative_[p] = std::clamp(0.5 * (relative_[p] + speed[p] / mean), 0.5, 2.0);
        return relative_[std::size_t(mpi::rank(comm_))];
    }

    const TimeControl& c_;
    MPI_Comm comm_;
    int size_;
    long fromStep_; //!< the step the run (or restart) starts from: the early checks count from there
    bool on_; //!< one rank has no imbalance: checked only when a repartition is forced (threshold < 1)
    bool repartitionable_ = true;
    bool following_ = false; //!< the cost moves (the last check repartitioned or forecast a change): check early
    static constexpr double modelTolerance = 1.05; //!< the partitioner's (Repartition.cpp)
    static constexpr double movingCost = 0.02;     //!< |forecast - model| above which the checks come early
    double busy_ = 0.0, waited_ = 0.0, start_ = 0.0;
    std::unique_ptr<std::ofstream> csv_;
    std::unique_ptr<CostFit> fit_; //!< the cost model's weights, fitted to the checks (when it has several)
    double spread_ = 0.0;          //!< the last check's speed spread: max / min of speeds()
    std::vector<double> relative_; //!< the ranks' relative speeds (relativeSpeed)
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

//! The stalled-run check starts once the first step's tenth has grown back (1.1^25 > 10).
constexpr long stallCheckFrom = 25;

/*! The step size before any halving: the stable step, a tenth of it first, at most maxGrowth times the last one,
 *  and clipped to the next output time; unclipped is the step before that clip. Sets failure if it is not positive,
 *  has collapsed or leaves the end time out of reach. */
double chooseStep(TimeSystem& system, const TimeControl& c, double t, double dtPrev, long step, double nextOutput,
                  double& largestStable, double& unclipped, std::string& failure)
{
    double dt = system.prepareStep(t, step);
    if (!(dt > 0.0) || !std::isfinite(dt))
    {
        failure = "the stable time step is " + jsonNumber(dt) + " at t = " + jsonNumber(t);
        return 0.0;
    }
    largestStable = std::max(largestStable, dt);
    dt = dtPrev > 0.0 ? std::min(dt, c.maxGrowth * dtPrev) : 0.1 * dt;
    // collapsed: 1e-8 of the run's largest step (a cell crushed at a rate the steps only approach: the piston of
    // test collapse_diagnosis crept 880,000 steps to the earlier floor, 1e-12 of the end time). Relative to the run's
    // own steps, so an end time far beyond them (1e300) is no collapse.
    if (dt < 1e-8 * largestStable)
    {
        failure = system.collapse(t, dt, step);
        return 0.0;
    }
    // stalled: a step near the run's largest (not a collapse, above) that leaves the end time more than 1e10 steps
    // away. An unphysical value (gamma 1e20, cfl 1e-12) otherwise ran for hours, its ETA 1e20 s, to the default
    // max_steps; a scene that sets time.max_steps runs to it (an end time far beyond, a step count wanted).
    const double stepsLeft = (c.endTime - t) / dt;
    if (c.stopStalled && step >= stallCheckFrom && dt > 1e-3 * largestStable && stepsLeft > 1e10)
    {
        failure = "the time step " + jsonNumber(dt) + " at t = " + jsonNumber(t) + " (step " + std::to_string(step) +
                  ") leaves about " + jsonNumber(stepsLeft) + " steps to the end time " + jsonNumber(c.endTime) +
                  ": the run would not end (time.max_steps, if set, runs it to that step count)";
        const std::string where = system.stepLimit();
        if (!where.empty())
            failure += "; " + where;
        return 0.0;
    }
    unclipped = dt;
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
        if (!*steps) // a folder in its place: stop before the first step (rank 0 ends the job, see unilag.cpp)
            io::finishOutput(*steps, c.stepsCsv);
    }
    const auto wall0 = Clock::now();
    {
        Progress progress(c.progress && rank == 0, c.endTime);
        StopOnSignal stop(c.checkpointOnSignal);
        LoadBalancer balance(c, comm, s.steps);
        while (s.t < c.endTime * (1.0 - 1e-14) && s.steps < c.maxSteps)
        {
            if (c.checkpointOnSignal && (r.signal = StopOnSignal::received(comm)) != 0)
            {
                if (steps)
                    steps->flush();
                system.checkpoint(s);
                break;
            }
            balance.startStep();
            double unclipped = 0.0;
            double dt = chooseStep(system, c, s.t, s.dtPrev, s.steps, s.nextOutput, s.largestStable, unclipped,
                                   r.failure);
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
            balance.endStep();
            if (steps)
                *steps << s.steps + 1 << ',' << std::setprecision(12) << s.t + dt << ',' << dt << ',' << iterations
                       << ',' << attempt << '\n';
            s.t += dt;
            // A step cut short by an output time does not hold back the next: the growth limit starts from the
            // step it would have been (2D Sedov, 10 outputs, 4k cells, order 2: 703 steps against 579 without).
            s.dtPrev = attempt == 0 ? unclipped : dt;
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
            if (s.t < c.endTime * (1.0 - 1e-14)) // none after the last step: a repartition then would be wasted
                balance.check(system, s.steps, s.t, r);
            progress.report(s.steps, s.t, dt);
        }
        balance.finish();
    }
    if (steps)
        io::finishOutput(*steps, c.stepsCsv); // a full disk is said, not left to a short file
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - wall0).count();
    r.stepCapped = r.failure.empty() && r.signal == 0 && s.t < c.endTime * (1.0 - 1e-14);
    if (r.failure.empty())
        system.write(s.dumps++, s.t);
    r.finalTotals = system.totals();
    return r;
}

} // namespace unilag
