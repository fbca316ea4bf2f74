/*! \file TimeLoop.hpp
 *  \brief The time loop every solver runs through (Laghos' driver): the step size (stable step, first-step
 *  fraction, growth limit, output times, end time), cut-and-retry of rejected steps, the output cadence, steps.csv
 *  and the progress line. It knows nothing of the physics or of how a step is integrated: a TimeSystem does.
 */
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

namespace unilag
{

/*! What the time loop drives. Every member function is collective over the system's ranks. */
class TimeSystem
{
  public:
    virtual ~TimeSystem() = default;
    //! Rates at t that do not depend on dt (step: the index of the step about to be taken); returns the largest
    //! stable step over all ranks.
    virtual double prepareStep(double t, long step) = 0;
    //! Called once before the attempts at a step: keep what a retry must start from.
    virtual void beginAttempts() = 0;
    //! One attempt at the step [t, t + dt] (attempt 0, 1, ... after halvings); true if the result is admissible.
    //! iterations: the implicit solver's count (0 if none).
    virtual bool attemptStep(double t, double dt, int attempt, int& iterations) = 0;
    //! The diagnosis of a step that every attempt failed.
    virtual std::string failure(double t, double dt, int attempts) = 0;
    //! The step's result becomes the state.
    virtual void acceptStep(double t, double dt, int iterations) = 0;
    //! The diagnosis of a time step that has collapsed (where the mesh tangles).
    virtual std::string collapse(double t, double dt, long step) = 0;
    //! What sets the stable step (where and why), for the diagnosis of a run that cannot end; "" if unknown.
    virtual std::string stepLimit() { return ""; }
    //! Writes dump number index of the state at t (nothing if the scene writes no output).
    virtual void write(int index, double t) = 0;
    //! The conserved totals of the state (and whatever their check needs), the same on every rank.
    virtual std::vector<double> totals() = 0;
    //! Writes a checkpoint of the persistent state with the loop's state (a system without checkpoints ignores it).
    virtual void checkpoint(const struct LoopState& /*loop*/) {}
    /*! Moves the state onto a new partition of the ranks, balanced by the cells' measured costs; returns the number
     *  of cells that changed rank (a system that cannot repartition returns -1). Must not change any result. */
    virtual long repartition() { return -1; }
    /*! The imbalance the system's cost model sees in the current partition (max / mean of the ranks' summed cell
     *  costs; 1 if it has none). Collective. */
    virtual double modelImbalance() { return 1.0; }
    /*! The imbalance the model forecasts for the next window on the current partition (a plastic zone that forms
     *  moves cost within a window); modelImbalance() where the model has no forecast. Collective. */
    virtual double forecastImbalance() { return modelImbalance(); }
    /*! This rank's speed (modelled cost per busy second) relative to the ranks' mean, as measured at the checks:
     *  the model predicts its busy time as its cost over that speed, and a repartition gives it cost in proportion. */
    virtual void setRankSpeed(double /*relative*/) {}
    /*! The cost model's weights: what one unit of each cost term costs in units of the first (1); empty if the
     *  system has no model to fit (CostFit). */
    virtual std::vector<double> costWeights() const { return {}; }
    virtual void setCostWeights(const std::vector<double>& /*weights*/) {}
    //! This rank's cost terms (one per weight) since the last call or repartition.
    virtual std::vector<double> costTerms() { return {}; }
};

struct TimeControl
{
    double endTime = 1.0;
    double outputInterval = 0.0;  //!< 0: first and last state only
    double initialTimeStep = 0.0; //!< 0: a tenth of the first stable step
    double maxGrowth = 1.1;       //!< of dt from one step to the next
    long maxSteps = 10000000;
    bool stopStalled = true; //!< stop a run whose end time is out of reach (else it runs to maxSteps)
    int maxRetries = 8; //!< halvings of a rejected step before the run stops
    bool progress = true;
    std::string stepsCsv; //!< per accepted step: t, dt, iterations, halvings (rank 0; "" for none)
    double checkpointInterval = 0.0; //!< simulated time between TimeSystem::checkpoint calls (0: none)
    bool checkpointOnSignal = false; //!< SIGTERM / SIGINT: checkpoint at the end of the step and stop
    long balanceInterval = 0;         //!< steps between load-balance checks (0: none)
    long earlyBalanceInterval = 0;    //!< steps between checks in the first balanceInterval of a run (0: none)
    double imbalanceThreshold = 1.15; //!< repartition when a check's imbalance exceeds it (and the model's too)
    bool repartition = false;         //!< repartition (TimeSystem::repartition) or only measure
    //! give the system each rank's measured speed (TimeSystem::setRankSpeed): a slower rank gets less modelled cost
    bool rankSpeeds = false;
    std::string balanceCsv;           //!< per check: step, t, imbalance, repartitioned (rank 0; "" for none)
};

/*! A load-balance check: the ranks' busy times (CPU time less the time spent waiting in collectives and halo
 *  exchanges, mpi::waitSeconds) over the steps since the last check, as max / mean. */
struct BalanceCheck
{
    long step = 0;
    double t = 0.0;
    double imbalance = 1.0;
    double modelImbalance = 1.0; //!< what the cost model predicts for the same partition
    double workCost = 0.0; //!< the model's second weight at this check (CostFit; 0 if it has none)
    double speedSpread = 0.0;    //!< max / min of the ranks' busy time per modelled cost (0: no model)
};

//! A repartition: when, the imbalance of the check that triggered it and of the next one, its cost.
struct RepartitionEvent
{
    long step = 0;
    double t = 0.0;
    double before = 0.0, after = -1.0; //!< after < 0: no check followed
    double seconds = 0.0;              //!< wall time of the repartition (the slowest rank)
    long cellsMoved = 0;
};

/*! Where the loop is: all it needs to go on from here (a checkpoint keeps it with the system's persistent fields).
 *  The default is the start of a run. */
struct LoopState
{
    double t = 0.0;
    double dtPrev = -1.0;     //!< the last accepted step, before an output time cut it (< 0: none yet)
    double nextOutput = -1.0; //!< the next output time (< 0: the first one after t = 0)
    long steps = 0;
    int dumps = 0;   //!< dumps written so far (the next dump's index)
    int retries = 0; //!< halvings of rejected steps so far
    double nextCheckpoint = -1.0;       //!< the next checkpoint time (< 0: the first one after t = 0)
    double largestStable = 0.0;         //!< the largest stable step of this run so far (the collapse floor's scale)
    std::vector<double> initialTotals; //!< TimeSystem::totals() at t = 0 (empty: not taken yet)
};

struct LoopResult
{
    LoopState state;          //!< where the loop stopped
    double wallSeconds = 0.0; //!< from the first step to the last (without the first and last dumps)
    std::vector<double> initialTotals, finalTotals; //!< TimeSystem::totals() before the first step, after the last
    std::string failure;                            //!< "" if the run completed
    bool stepCapped = false; //!< stopped by TimeControl::maxSteps before the end time
    int signal = 0;          //!< stopped (with a checkpoint) by this signal
    std::vector<BalanceCheck> balanceChecks;
    std::vector<RepartitionEvent> repartitions;
};

//! Runs the system from `from` to the end time or the step cap. Collective.
LoopResult runTimeLoop(TimeSystem& system, const TimeControl& control, MPI_Comm comm, LoopState from = LoopState());

} // namespace unilag
