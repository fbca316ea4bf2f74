// The time loop's load balance (src/solver/TimeLoop.cpp, LoadBalancer) on a toy system whose ranks take known times
// per step: the busy time is measured without the time spent waiting in collectives, its imbalance (max / mean over
// the ranks) triggers TimeSystem::repartition above the threshold and not below, and only when the system's cost
// model sees it too; the check after a repartition reports the imbalance it left, and parallel.repartition false
// only measures. `unit` runs these on one rank (where the imbalance is 1 by definition), unit_mesh_np2 and
// unit_mesh_np3 on more (tests/CMakeLists.txt).
#include <gtest/gtest.h>

#include <mpi.h>
#include <vector>

#include "core/Mpi.hpp"
#include "solver/TimeLoop.hpp"

namespace
{

/*! Each step computes for `work` milliseconds of CPU time on this rank, then waits for the others in a reduction
 *  (as the stable time step's allMin makes the real solver wait). repartition() sets every rank's work to the
 *  mean. CPU time, as the load balance measures it: the test holds when the ranks share cores. */
class Sleeper : public unilag::TimeSystem
{
  public:
    explicit Sleeper(double work) : work_(work) {}
    double prepareStep(double, long) override { return 0.01; }
    void beginAttempts() override {}
    bool attemptStep(double, double, int, int& iterations) override
    {
        iterations = 0;
        ++steps_;
        const double t0 = unilag::mpi::cpuSeconds();
        volatile double sink = 0.0;
        while (unilag::mpi::cpuSeconds() - t0 < 1e-3 * work_)
            sink = sink + 1.0;
        unilag::mpi::allMin(MPI_COMM_WORLD, 1.0); // the slower rank's time is the others' wait
        return true;
    }
    std::string failure(double, double, int) override { return "none"; }
    void acceptStep(double, double, int) override {}
    std::string collapse(double, double, long) override { return "none"; }
    void write(int, double) override {}
    std::vector<double> totals() override { return {0.0}; }
    //! The model: the works themselves (unless blind), as GprSystem's cell costs predict its ranks' times.
    double modelImbalance() override
    {
        double sum[1] = {work_};
        unilag::mpi::allSum(MPI_COMM_WORLD, sum);
        const double largest = unilag::mpi::allMax(MPI_COMM_WORLD, work_);
        return blind ? 1.0 : largest * unilag::mpi::size(MPI_COMM_WORLD) / sum[0];
    }
    double forecastImbalance() override { return forecast > 0.0 ? forecast : modelImbalance(); }
    //! Modelled: every rank's cost is its steps (weight 1), whatever its work: the ranks' speeds differ.
    std::vector<double> costWeights() const override
    {
        return modelled ? std::vector<double>{1.0} : std::vector<double>{};
    }
    std::vector<double> costTerms() override
    {
        const double steps = double(steps_ - stepsAtLastCall_);
        stepsAtLastCall_ = steps_;
        return modelled ? std::vector<double>{steps} : std::vector<double>{};
    }
    void setRankSpeed(double relative) override { speeds.push_back(relative); }
    long repartition() override
    {
        double sum[1] = {work_};
        unilag::mpi::allSum(MPI_COMM_WORLD, sum);
        work_ = sum[0] / unilag::mpi::size(MPI_COMM_WORLD);
        ++calls;
        return 7;
    }
    int calls = 0;
    bool blind = false; //!< a cost model that does not see the imbalance
    double forecast = 0.0; //!< > 0: what forecastImbalance says, whatever the works
    bool modelled = false; //!< cost terms: the steps
    std::vector<double> speeds; //!< what setRankSpeed was given, in order

  private:
    double work_;
    long steps_ = 0, stepsAtLastCall_ = 0;
};

unilag::TimeControl control(bool repartition)
{
    unilag::TimeControl c;
    c.endTime = 0.31; // 31 steps of 0.01: checks after steps 10, 20 and 30 (none after the last)
    c.initialTimeStep = 0.01;
    c.maxGrowth = 1.0;
    c.progress = false;
    c.balanceInterval = 10;
    c.imbalanceThreshold = 1.15;
    c.repartition = repartition;
    return c;
}

int ranks() { return unilag::mpi::size(MPI_COMM_WORLD); }
int rank() { return unilag::mpi::rank(MPI_COMM_WORLD); }

TEST(LoadBalance, ImbalanceTriggersARepartitionThatRemovesIt)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(rank() == 0 ? 6.0 : 2.0); // rank 0 takes 3x the others: imbalance 6 / mean
    const auto r = unilag::runTimeLoop(s, control(true), MPI_COMM_WORLD);
    const double expected = 6.0 * ranks() / (6.0 + 2.0 * (ranks() - 1));
    ASSERT_EQ(r.balanceChecks.size(), 3u);
    EXPECT_NEAR(r.balanceChecks[0].imbalance, expected, 0.15 * expected); // the wait is not counted as work
    ASSERT_EQ(r.repartitions.size(), 1u); // after the first check only: then the ranks are balanced
    EXPECT_EQ(s.calls, 1);
    EXPECT_EQ(r.repartitions[0].step, 10);
    EXPECT_EQ(r.repartitions[0].cellsMoved, 7);
    EXPECT_DOUBLE_EQ(r.repartitions[0].before, r.balanceChecks[0].imbalance);
    EXPECT_DOUBLE_EQ(r.repartitions[0].after, r.balanceChecks[1].imbalance);
    EXPECT_LT(r.repartitions[0].after, 1.15);
}

TEST(LoadBalance, EarlyChecksRepartitionWithinTheFirstInterval)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(rank() == 0 ? 6.0 : 2.0);
    unilag::TimeControl c = control(true);
    c.earlyBalanceInterval = 3; // parallel.early_check_interval: the start-up partition's cost shows early
    const auto r = unilag::runTimeLoop(s, c, MPI_COMM_WORLD);
    std::vector<long> steps;
    for (const auto& check : r.balanceChecks)
        steps.push_back(check.step);
    EXPECT_EQ(steps, (std::vector<long>{3, 6, 9, 10, 20, 30})); // early checks through the first interval only
    ASSERT_EQ(r.repartitions.size(), 1u);
    EXPECT_EQ(r.repartitions[0].step, 3);
    EXPECT_LT(r.balanceChecks[1].imbalance, 1.15); // steps 4-6 run balanced
}

TEST(LoadBalance, MeasureOnlyNeverRepartitions)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(rank() == 0 ? 6.0 : 2.0);
    const auto r = unilag::runTimeLoop(s, control(false), MPI_COMM_WORLD);
    ASSERT_EQ(r.balanceChecks.size(), 3u);
    for (const auto& c : r.balanceChecks)
        EXPECT_GT(c.imbalance, 1.15);
    EXPECT_TRUE(r.repartitions.empty());
    EXPECT_EQ(s.calls, 0);
}

TEST(LoadBalance, AnImbalanceTheModelDoesNotSeeIsLeftAlone)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(rank() == 0 ? 6.0 : 2.0);
    s.blind = true; // as a rank slowed by another process: no partition by the model would help
    const auto r = unilag::runTimeLoop(s, control(true), MPI_COMM_WORLD);
    ASSERT_EQ(r.balanceChecks.size(), 3u);
    EXPECT_GT(r.balanceChecks[0].imbalance, 1.15);
    EXPECT_DOUBLE_EQ(r.balanceChecks[0].modelImbalance, 1.0);
    EXPECT_EQ(s.calls, 0);
}

TEST(LoadBalance, BalancedRanksStayAsTheyAre)
{
    Sleeper s(4.0);
    const auto r = unilag::runTimeLoop(s, control(true), MPI_COMM_WORLD);
    EXPECT_EQ(r.balanceChecks.size(), ranks() > 1 ? 3u : 0u); // one rank: nothing to balance, no checks
    for (const auto& c : r.balanceChecks)
        EXPECT_LT(c.imbalance, 1.15);
    EXPECT_EQ(s.calls, 0);
}

TEST(LoadBalance, ThresholdBelowOneRepartitionsAtEveryCheck)
{
    Sleeper s(1.0);
    auto c = control(true);
    c.imbalanceThreshold = 0.0; // as the repartition tests force it, on any number of ranks
    const auto r = unilag::runTimeLoop(s, c, MPI_COMM_WORLD);
    EXPECT_EQ(s.calls, 3);
    EXPECT_EQ(r.repartitions.size(), 3u);
}

TEST(LoadBalance, AForecastImbalanceRepartitionsABalancedWindow)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(4.0);
    s.forecast = 1.3; // a plastic zone forming: the next window will not be balanced, though this one was
    const auto r = unilag::runTimeLoop(s, control(true), MPI_COMM_WORLD);
    ASSERT_EQ(r.balanceChecks.size(), 3u);
    EXPECT_LT(r.balanceChecks[0].imbalance, 1.15);
    EXPECT_EQ(s.calls, 3);
    Sleeper quiet(4.0);
    unilag::runTimeLoop(quiet, control(true), MPI_COMM_WORLD);
    EXPECT_EQ(quiet.calls, 0);
}

TEST(LoadBalance, ChecksComeEarlyWhileRepartitionsFollowTheCost)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(4.0);
    s.forecast = 1.3; // every check repartitions: the checks stay at the early interval all the run
    unilag::TimeControl c = control(true);
    c.earlyBalanceInterval = 3;
    const auto r = unilag::runTimeLoop(s, c, MPI_COMM_WORLD);
    std::vector<long> steps;
    for (const auto& check : r.balanceChecks)
        steps.push_back(check.step);
    EXPECT_EQ(steps, (std::vector<long>{3, 6, 9, 10, 12, 15, 18, 20, 21, 24, 27, 30}));
    EXPECT_EQ(s.calls, 12);
}

TEST(LoadBalance, ChecksComeEarlyWhileTheForecastDiffersFromTheLastWindow)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    Sleeper s(4.0);
    s.forecast = 1.08; // below the threshold, but the cost is moving: no repartition, early checks
    unilag::TimeControl c = control(true);
    c.earlyBalanceInterval = 3;
    const auto r = unilag::runTimeLoop(s, c, MPI_COMM_WORLD);
    EXPECT_EQ(r.balanceChecks.size(), 12u);
    EXPECT_EQ(s.calls, 0);
    Sleeper still(4.0);
    const auto q = unilag::runTimeLoop(still, c, MPI_COMM_WORLD);
    EXPECT_EQ(q.balanceChecks.size(), 6u); // 3, 6, 9, then every 10
}

TEST(LoadBalance, RankSpeedsReachTheSystemWhenAsked)
{
    if (ranks() < 2)
        GTEST_SKIP() << "needs two ranks";
    for (const bool asked : {false, true})
    {
        Sleeper s(rank() == 0 ? 6.0 : 2.0); // the same modelled cost, rank 0 three times slower per unit
        s.modelled = true;
        s.blind = true;
        unilag::TimeControl c = control(false);
        c.rankSpeeds = asked;
        unilag::runTimeLoop(s, c, MPI_COMM_WORLD);
        if (!asked)
        {
            EXPECT_TRUE(s.speeds.empty());
            continue;
        }
        ASSERT_EQ(s.speeds.size(), 3u);
        // relative speeds 1 / 3 of the others' on rank 0, averaged with the start (1) and halved in weight per check
        const double slow = 3.0 / (1.0 + 3.0 * (ranks() - 1)) * ranks() / 3.0;
        const double mine = rank() == 0 ? slow : 3.0 * slow;
        const double expected = 0.125 + 0.875 * mine;
        EXPECT_NEAR(s.speeds.back(), expected, 0.1 * expected);
        EXPECT_EQ(s.speeds.front() < 1.0, rank() == 0);
    }
}

} // namespace

