/*! \file GprSystem.hpp
 *  \brief The GPR solver as the time loop sees it (TimeSystem): model, operator and integrator, the retry
 *  bookkeeping of a step, output, and the conservation bookkeeping (boundary impulse and work, the force balance at
 *  the nodes, GCL defect).
 */
#pragma once

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/Format.hpp"
#include "mesh/Repartition.hpp"
#include "solver/GprCheckpoint.hpp"
#include "solver/GprDiagnostics.hpp"
#include "solver/GprOutput.hpp"
#include "solver/GprPeak.hpp"
#include "solver/Integrators.hpp"
#include "solver/TimeLoop.hpp"

namespace unilag
{

template <int D, class P> class GprSystem : public TimeSystem
{
  public:
    /*! checkEveryNode: evaluate the force balance at every owned node (--check asserts it), not only at the
     *  boundary nodes whose impulse and work the conservation needs. */
    explicit GprSystem(GprModel<D, P>& model, bool checkEveryNode = false)
        : md_(model), op_(model), euler_(op_), midpoint_(op_), ars_(op_),
          ars222_(md_.order2 && md_.scene.integrator == Integrator::Ars222), checkEveryNode_(checkEveryNode)
    {
        op_.selectBalanceNodes(checkEveryNode);
    }

    //! dumps: the dumps a restarted run's series already holds (0 for a new run).
    void openOutput(const std::string& dir, int dumps = 0)
    {
        writer_ = makeWriter(md_, dir);
        writer_->continueSeries(dumps);
    }
    const io::XdmfWriter* writer() const { return writer_.get(); }

    //! Geometry and EOS of the initial state. Collective.
    void start()
    {
        op_.refreshGeometry();
        op_.initialNodeVelocities();
        op_.computeAux();
        notePeakDensity(md_, 0.0, peak_);
    }

    double prepareStep(double t, long step) override
    {
        // The nodal solve on the configuration at t^n (geometry and EOS are current for all local cells).
        op_.setBoundaryTime(t);
        if constexpr (P::strain)
            op_.startPicard(step);
        if (md_.order2)
        {
            op_.clearFallback();
            op_.reconstructStart();
        }
        op_.solveNodes();
        if constexpr (P::heat)
            op_.heatFluxes();
        return op_.stableTimeStep();
    }

    void beginAttempts() override
    {
        stage_ = StageResult{};
        if (md_.fields.has("v_node0"))
            md_.fields.copy("v_node", "v_node0"); // v^0 and sigma^n do not depend on dt
    }

    /*! One attempt at [t, t + dt]. Order 2: where the update leaves cells inadmissible (a negative internal energy,
     *  an inverted cell), those cells fall back to first order for the rest of the step, the rates at t^n are
     *  recomputed and the step is tried again at the same dt, up to maxFallbackRounds times, then once with every
     *  cell at first order, before the time loop halves dt (docs/gpr-model.md 2.5, "A posteriori fallback"). */
    bool attemptStep(double t, double dt, int attempt, int& iterations) override
    {
        midpointStep_ = false;
        bool ok = integrate(t, dt, attempt > 0);
        for (int round = 0; !ok && md_.order2 && stage_.failure.empty() && round <= maxFallbackRounds; ++round)
        {
            // A cold gas fails cell by cell where each fallback changes its neighbours' node velocities (Noh with
            // vertex_based, t = 0): after maxFallbackRounds the whole step goes to first order.
            const long marked = round < maxFallbackRounds ? op_.markFallback() : op_.markAllFallback();
            if (marked == 0)
                break;
            fallbackCells_ += marked;
            op_.setBoundaryTime(t);
            if constexpr (P::strain)
                md_.fields.copy("sigma0", "sigma");
            op_.reconstructStart();
            op_.solveNodes();
            md_.fields.copy("v_node", "v_node0");
            ok = integrate(t, dt, false);
        }
        if (!ok && ars222_ && stage_.failure.empty())
        {
            // ARS(2,2,2)'s final row weighs the t^n rates by beta - 1 < 0: a cold cell the shock reaches within the
            // step (its rates 0 at t^n, O(1) at stage 1 or the reverse) is left a negative energy at any dt
            // (docs/ars222.md). The step is taken again by the midpoint scheme, which is conservative as well.
            midpointStep_ = true;
            ok = integrate(t, dt, true);
        }
        iterations = stage_.iterations;
        return ok;
    }

    std::string failure(double t, double dt, int attempts) override
    {
        if (!stage_.failure.empty())
            return "at t = " + jsonNumber(t) + " after " + std::to_string(attempts) +
                   " halvings of dt: " + stage_.failure;
        return diagnose(md_, stage_.check, t, dt, attempts);
    }

    void acceptStep(double t, double dt, int iterations) override
    {
        if constexpr (P::strain)
            if (md_.order2)
                op_.notePredictorStress();
        picardTotal_ += iterations;
        picardMax_ = std::max(picardMax_, iterations);
        ++stepsSincePartition_;
        maxGcl_ = std::max(maxGcl_, stage_.check.maxGclDefect);
        balance_.accumulate(op_.lastBalance(), t, dt);
        if (midpointStep_)
        {
            ++midpointSteps_;
            md_.fields.copy("v_node", "ars_v1"); // the midpoint step's lagged velocities (lagged()) for the next one
        }
        // ARS(2,2,2): the next step's impedances lag stage 1's node velocities (a nodal solution), not the combined
        // ones: their extrapolation (weight beta - 1 < 0 on v0) made z at t^n differ from stage 1's at any dt by the
        // 3D Sedov deposit (R0 = 1300 R1), and the final row, weighing R0 by beta - 1, left a negative energy.
        op_.advance(lagged());
        op_.filterEntropy(dt);
        notePeakDensity(md_, t + dt, peak_);
    }

    /*! New owners by the scene's partitioner (balancedOwners: Zoltan2 on the cells' current centroids, or the
     *  curve), weighted by the forecast predictedTimes(); the mesh rebuilt on them, the fields migrated (with the
     *  lagged node velocities and the cells' last plastic work rates), the operator's node lists and the writer's
     *  topology renewed, geometry and EOS recomputed: the next step is bitwise what it would have been. Collective. */
    long repartition() override
    {
        const auto& old = *md_.mesh;
        const std::vector<int> owner =
            balancedOwners(old, md_.fields["x"], predictedTimes(true), md_.scene.partitioner);
        double moved[1] = {0.0};
        for (LO i = 0; i < old.nOwnedCells; ++i)
            moved[0] += owner[i] != md_.rank ? 1.0 : 0.0;
        mpi::allSum(md_.comm, moved);
        auto mesh = DistributedMesh::rebuild(old, owner, positions3());
        std::vector<std::string> carry;
        if (md_.fields.has(lagged()))
            carry.push_back(lagged());
        if constexpr (P::plastic)
            carry.push_back("plastic_rate");
        md_.remesh(mesh, carry);
        op_.selectBalanceNodes(checkEveryNode_);
        op_.onNewMesh();
        if (writer_)
            setTopology(md_, *writer_);
        op_.refreshGeometry();
        op_.computeAux(lagged());
        stepsSincePartition_ = 0;
        stepsAtLastCall_ = intervalSteps_ = 0; // plastic_work starts again from zero on the new mesh
        workAtLastCall_.clear();
        intervalWork_.clear();
        return long(moved[0]);
    }

    //! The model's imbalance of the window just measured (what the check compares with the clock).
    double modelImbalance() override { return costImbalance(*md_.mesh, predictedTimes(false)); }
    double forecastImbalance() override { return costImbalance(*md_.mesh, predictedTimes(true)); }
    void setRankSpeed(double relative) override { rankSpeed_ = relative; }

    /*! Each owned cell's busy time per step: its cost over this rank's relative speed (1 unless the scene's
     *  parallel.rank_speeds measures them). Zoltan2's multijagged takes no part sizes, so a slow rank's cells weigh
     *  more instead: exact for the cells a repartition leaves on their rank, which are nearly all of them (the parts
     *  keep their places and ids). forecast: the next window's (a plastic zone that forms or moves changes the
     *  cells' costs within a window, so a partition by the last window's is behind): each cell's plastic work rate
     *  extrapolated linearly from its last two windows, 2 r_last - r_before (at least 0). */
    std::vector<double> predictedTimes(bool forecast) const
    {
        std::vector<double> t = cellCosts();
        const bool trend = forecast && intervalSteps_ > 0 && intervalWork_.size() == t.size() &&
                           previousRate_.size() == t.size();
        for (std::size_t i = 0; i < t.size(); ++i)
        {
            if (trend) // cellCosts holds r_last once: add r_last - r_before
                t[i] += plasticWorkCost_ *
                        std::max(-intervalWork_[i] / double(intervalSteps_),
                                 intervalWork_[i] / double(intervalSteps_) - previousRate_[i]);
            t[i] /= rankSpeed_;
        }
        return t;
    }

    /*! Each owned cell's cost per step, in units of a cell-step without plastic flow: 1 + plasticWorkCost_ times its
     *  units of plastic work per step (GprModel::plasticWork) over the last load-balance interval (costTerms), or
     *  since the last partition where no interval has ended since: the plastic zone moves, and a longer average
     *  would place it where it was. */
    std::vector<double> cellCosts() const
    {
        std::vector<double> cost(md_.mesh->nOwnedCells, 1.0);
        if constexpr (P::plastic)
        {
            const bool interval = intervalSteps_ > 0 && intervalWork_.size() == cost.size();
            const double perStep =
                plasticWorkCost_ / double(std::max(interval ? intervalSteps_ : stepsSincePartition_, 1L));
            if (interval) // costTerms has copied the work to the host already
                for (std::size_t i = 0; i < cost.size(); ++i)
                    cost[i] += perStep * intervalWork_[i];
            else
            {
                auto work = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md_.plasticWork());
                for (std::size_t i = 0; i < cost.size(); ++i)
                    cost[i] += perStep * work(i);
            }
        }
        return cost;
    }

    //! The cost terms: cell-steps, and with plasticity units of plastic work (weight plasticWorkCost_, fitted).
    std::vector<double> costWeights() const override
    {
        return P::plastic ? std::vector<double>{1.0, plasticWorkCost_} : std::vector<double>{1.0};
    }
    void setCostWeights(const std::vector<double>& w) override
    {
        if (w.size() > 1)
            plasticWorkCost_ = w[1];
    }
    //! Also keeps each cell's plastic work over the interval, for cellCosts.
    std::vector<double> costTerms() override
    {
        const LO n = md_.mesh->nOwnedCells;
        const double cellSteps = double(n) * double(stepsSincePartition_ - stepsAtLastCall_);
        intervalSteps_ = stepsSincePartition_ - stepsAtLastCall_;
        stepsAtLastCall_ = stepsSincePartition_;
        if constexpr (!P::plastic)
            return {cellSteps};
        auto work = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), md_.plasticWork());
        workAtLastCall_.resize(std::size_t(n), 0.0);
        // the window before's rates (carried through repartitions; 0 at the start of a run or restart) out, this
        // window's in
        auto rate = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), column(md_.fields["plastic_rate"]));
        previousRate_.assign(rate.data(), rate.data() + n);
        intervalWork_.resize(std::size_t(n));
        double total = 0.0;
        for (LO i = 0; i < n; ++i)
        {
            intervalWork_[i] = work(i) - workAtLastCall_[i];
            workAtLastCall_[i] = work(i);
            total += intervalWork_[i];
            rate(i) = intervalSteps_ > 0 ? intervalWork_[i] / double(intervalSteps_) : 0.0;
        }
        Kokkos::deep_copy(column(md_.fields["plastic_rate"]), rate);
        return {cellSteps, total};
    }

    std::string collapse(double t, double dt, long step) override { return unilag::collapse(md_, t, dt, step); }
    std::string stepLimit() override { return unilag::stepLimit(md_); }

    void write(int index, double t) override
    {
        if (writer_)
            dump(md_, *writer_, index, t);
    }

    //! Mass, momentum, total energy, sum m|v|, and the angular momentum's sums (GprDiagnostics.hpp TotalsLayout).
    std::vector<double> totals() override
    {
        double t[TotalsLayout<D>::size];
        unilag::totals(md_, t);
        return std::vector<double>(t, t + TotalsLayout<D>::size);
    }

    //! <output>/checkpoint.h5 (written to a temporary name, then renamed). Collective.
    void checkpoint(const LoopState& loop) override
    {
        io::CheckpointWriter out(md_.comm, checkpointPath());
        for (const auto& [key, value] : checkpointIdentity(md_))
            out.text(key, value);
        for (const char* section : kRestartSections)
            out.text(std::string("scene.") + section, sceneSection(md_.scene.resolved, section));
        const auto& dm = *md_.mesh;
        for (const auto& [name, node] : checkpointFields(md_, lagged()))
            out.table((node ? "node." : "cell.") + name, node ? dm.nGlobalNodes : dm.nGlobalCells,
                      ownedRows(md_, name, node));
        const double loopNumbers[] = {loop.t,     loop.dtPrev, loop.nextOutput, double(loop.steps), double(loop.dumps),
                                      double(loop.retries), loop.nextCheckpoint, loop.largestStable};
        out.numbers("loop", std::vector<double>(std::begin(loopNumbers), std::end(loopNumbers)));
        out.numbers("initial_totals", loop.initialTotals);
        out.numbers("initial_quality", {initialQuality_});
        out.numbers("largest_density", combinedPeak(md_.comm, peak_).numbers());
        std::vector<double> run = {double(picardTotal_), double(picardMax_), maxGcl_, double(fallbackCells_),
                                   balance_.work,        balance_.passiveWork, balance_.heat, balance_.maxImbalance,
                                   double(balance_.worstNode), balance_.worstTime};
        run.insert(run.end(), balance_.impulse, balance_.impulse + D);
        run.push_back(double(midpointSteps_));
        out.numbers("run", run);
        out.commit();
    }

    /*! Continues from a checkpoint: the persistent fields and lagged node velocities (owned rows by global id,
     *  then their ghosts), the geometry and EOS they give, the running totals; returns the time loop's state.
     *  InputError (exit 2) if the file is not a checkpoint of this scene, mesh and scheme. Collective. */
    LoopState restore(const std::string& path)
    {
        io::CheckpointReader in(md_.comm, path);
        for (const auto& [key, value] : checkpointIdentity(md_))
            if (in.text(key) != value)
                throw InputError("--restart '" + path + "': a checkpoint of another run (" + key + " '" +
                                 printable(in.text(key)) + "', this scene '" + value + "')");
        for (const char* section : kRestartSections)
        {
            const std::string change =
                sectionChange(in.text(std::string("scene.") + section), sceneSection(md_.scene.resolved, section));
            if (!change.empty())
                throw InputError("--restart '" + path + "': a checkpoint of another scene (" + printable(change, 160) +
                                 "); a restart keeps the materials, boundaries and scheme");
        }
        if (!md_.fields.has(lagged())) // ars_v1 is made by the first step's stage 1
            md_.fields.add(lagged(), Entity::Node, D, Lifetime::Scratch);
        for (const auto& [name, node] : checkpointFields(md_, lagged()))
            restoreRows(md_, in, name, node);
        op_.refreshGeometry();
        op_.computeAux(lagged());
        const std::vector<double>& l = in.numbers("loop");
        const std::vector<double>& run = in.numbers("run");
        // 7 loop numbers and 10 + D run numbers: written before largestStable and midpointSteps_ were kept
        if ((l.size() != 7 && l.size() != 8) || (run.size() != 10 + D && run.size() != 11 + D))
            throw InputError("--restart '" + path + "': the loop's state has the wrong length");
        // a checksum guards the bytes, not the values: a NaN dump index stopped the writer with an internal error
        const char* names[] = {"time", "last step", "next output time", "step count", "dump count", "retries",
                               "next checkpoint time", "largest stable step"};
        enum Kind { Any, NonNegative, Count }; // the last step and next times are -1 before their first
        const Kind kinds[] = {NonNegative, Any, Any, Count, Count, Count, Any, NonNegative};
        for (std::size_t k = 0; k < l.size(); ++k)
            if (!std::isfinite(l[k]) || (kinds[k] != Any && l[k] < 0.0) ||
                (kinds[k] == Count && !(l[k] < 2e9 && l[k] == std::floor(l[k])))) // whole, int-sized
                throw InputError("--restart '" + path + "': the loop's " + names[k] + " is " +
                                 (std::isfinite(l[k]) ? jsonNumber(l[k]) : std::string("not a finite number")));
        LoopState s;
        s.t = l[0];
        s.dtPrev = l[1];
        s.nextOutput = l[2];
        s.steps = long(l[3]);
        s.dumps = int(l[4]);
        s.retries = int(l[5]);
        s.nextCheckpoint = l[6];
        s.largestStable = l.size() > 7 ? l[7] : 0.0; // the collapse floor's scale, as the run had it
        s.initialTotals = in.numbers("initial_totals");
        initialQuality_ = in.numbers("initial_quality").at(0);
        if (in.hasNumbers("largest_density")) // every rank takes the run's record (absent: written before it was kept)
            peak_ = DensityPeak::from(in.numbers("largest_density"));
        if (s.initialTotals.size() != std::size_t(TotalsLayout<D>::size))
            throw InputError("--restart '" + path + "': the initial totals have the wrong length");
        picardTotal_ = long(run[0]);
        picardMax_ = int(run[1]);
        maxGcl_ = run[2];
        fallbackCells_ = long(run[3]);
        balance_.work = run[4];
        balance_.passiveWork = run[5];
        balance_.heat = run[6];
        balance_.maxImbalance = run[7];
        balance_.worstNode = GO(run[8]);
        balance_.worstTime = run[9];
        for (int d = 0; d < D; ++d)
            balance_.impulse[d] = run[10 + d];
        midpointSteps_ = run.size() > 10 + D ? long(run[10 + D]) : 0;
        return s;
    }

    std::string checkpointPath() const
    {
        return (std::filesystem::path(md_.scene.outputDirectory) / "checkpoint.h5").string();
    }

    long picardTotal() const { return picardTotal_; }
    //! Cells marked by the a posteriori first-order fallback, summed over the steps (order 2).
    long fallbackCells() const { return fallbackCells_; }
    //! ars222: the steps that the midpoint scheme took where ARS(2,2,2) left a cell inadmissible.
    long midpointSteps() const { return midpointSteps_; }
    bool usesArs222() const { return ars222_; }
    int picardMax() const { return picardMax_; }
    //! The smallest cell shape quality at t = 0: set by a new run, read from the checkpoint by a restart.
    double initialQuality() const { return initialQuality_; }
    //! The run's largest cell density, where and when (GprPeak.hpp). Collective.
    DensityPeak largestDensity() const { return combinedPeak(md_.comm, peak_); }
    void setInitialQuality(double q) { initialQuality_ = q; }
    double maxGclDefect() const { return maxGcl_; }
    //! Boundary impulse and work, wall work, boundary heat and the worst node imbalance of the accepted steps.
    const BoundaryBalance<D>& balance() const { return balance_; }
    const double (&impulse() const)[D] { return balance_.impulse; }
    double work() const { return balance_.work; }

  private:
    //! The node positions with 3 columns (z = 0 in 2D), on the overlap map: what DistributedMesh::rebuild takes.
    MV positions3() const
    {
        const MV& x = md_.fields["x"];
        MV x3(x.getMap(), 3);
        auto from = x.getLocalViewHost(Tpetra::Access::ReadOnly);
        auto to = x3.getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (std::size_t r = 0; r < from.extent(0); ++r)
            for (int d = 0; d < 3; ++d)
                to(r, d) = d < D ? from(r, d) : 0.0;
        return x3;
    }

    //! The node velocities the next step's impedance lags (GprSystem::acceptStep).
    const char* lagged() const { return ars222_ ? "ars_v1" : "v_node"; }

    //! The integrator's step from the rates at t^n; restore: a retry, which starts from v^0 and the first stress.
    bool integrate(double t, double dt, bool restore)
    {
        stage_.failure.clear();
        if (restore && md_.fields.has("v_node0"))
        {
            md_.fields.copy("v_node0", "v_node");
            op_.setBoundaryTime(t);
        }
        if constexpr (P::strain)
            if (restore)
                md_.fields.copy("sigma0", "sigma");
        if (ars222_ && !midpointStep_)
            return ars_.step(t, dt, stage_);
        return md_.order2 ? midpoint_.step(t, dt, stage_) : euler_.step(t, dt, stage_);
    }

    GprModel<D, P>& md_;
    GprOperator<D, P> op_;
    ForwardEuler<D, P> euler_;
    Midpoint<D, P> midpoint_;
    Ars222<D, P> ars_;
    bool ars222_; //!< scheme.integrator: ars222 (order 2)
    bool checkEveryNode_;
    long stepsSincePartition_ = 0;
    /*! The time of one unit of plastic work (relaxPlasticStrain's count: an eigen-decomposition, a Phi evaluation
     *  or a quadrature panel) over that of a cell-step without plastic flow: the start of the fit. Fitted on one
     *  rank through the impact scene (4.7k cells, one thread, a check every 25 steps): 0.08-0.12; docs/parallel.md. */
    static constexpr double plasticWorkCost = 0.1;
    double plasticWorkCost_ = plasticWorkCost; //!< refitted at each load-balance check (CostFit)
    double rankSpeed_ = 1.0;                   //!< setRankSpeed
    std::vector<double> previousRate_;         //!< costTerms: plastic_rate of the window before the last
    long stepsAtLastCall_ = 0, intervalSteps_ = 0; //!< costTerms: stepsSincePartition_ at its last call, and since
    std::vector<double> workAtLastCall_, intervalWork_; //!< costTerms: plastic_work at its last call, and since
    std::unique_ptr<io::XdmfWriter> writer_;
    StageResult stage_;
    static constexpr int maxFallbackRounds = 4;
    long picardTotal_ = 0;
    long fallbackCells_ = 0;
    bool midpointStep_ = false; //!< ars222: this attempt is the midpoint scheme's (attemptStep)
    long midpointSteps_ = 0;    //!< ars222: steps the midpoint scheme took, summed
    int picardMax_ = 0;
    double maxGcl_ = 0.0;
    double initialQuality_ = 0.0; //!< the mesh's smallest shape quality at t = 0 (kept through a restart)
    DensityPeak peak_;            //!< this rank's largest cell density so far (the run's, after a restart)
    BoundaryBalance<D> balance_;
};

} // namespace unilag
