// The generic time loop (src/solver/TimeLoop.cpp) on a toy system, y' = -y, that knows nothing of meshes: the step
// size rules (a tenth of the stable step first, growth by at most 10% from the last step an output time did not
// cut, output and end times hit exactly), cut and retry of rejected steps, the step cap, the failure after the
// retries, and the totals before and after.
#include <gtest/gtest.h>

#include <cmath>
#include <mpi.h>
#include <vector>

#include "solver/TimeLoop.hpp"

namespace
{

//! y' = -y by forward Euler; steps longer than maxAccepted are rejected (as an inverted cell would be).
class Decay : public unilag::TimeSystem
{
  public:
    double y = 1.0, stable = 0.1, maxAccepted = 1.0;
    bool alwaysFail = false;
    std::vector<double> dumps, accepted;
    int attempts = 0;

    double prepareStep(double, long) override { return stable; }
    void beginAttempts() override {}
    bool attemptStep(double, double dt, int, int& iterations) override
    {
        ++attempts;
        iterations = 0;
        return !alwaysFail && dt <= maxAccepted;
    }
    std::string failure(double, double, int attempts) override
    {
        return "toy failure after " + std::to_string(attempts) + " halvings";
    }
    void acceptStep(double, double dt, int) override
    {
        y *= 1.0 - dt;
        accepted.push_back(dt);
    }
    std::string collapse(double, double, long) override { return "collapsed"; }
    void write(int index, double t) override
    {
        EXPECT_EQ(index, int(dumps.size()));
        dumps.push_back(t);
    }
    std::vector<double> totals() override { return {y}; }
};

unilag::TimeControl control()
{
    unilag::TimeControl c;
    c.endTime = 1.0;
    c.outputInterval = 0.25;
    c.progress = false;
    return c;
}

TEST(TimeLoop, StepRulesOutputTimesAndTotals)
{
    Decay s;
    const auto r = unilag::runTimeLoop(s, control(), MPI_COMM_SELF);
    EXPECT_EQ(r.failure, "");
    EXPECT_DOUBLE_EQ(r.state.t, 1.0);
    EXPECT_EQ(r.state.steps, long(s.accepted.size()));
    EXPECT_DOUBLE_EQ(s.accepted[0], 0.01); // a tenth of the stable step
    // Growth by at most 10%, from the step before an output time cut it: the step after a cut is not held back.
    double t = s.accepted[0];
    int cuts = 0;
    for (std::size_t k = 1; k < s.accepted.size(); ++k)
    {
        const bool cut = std::abs(t / 0.25 - std::round(t / 0.25)) < 1e-12 && s.accepted[k - 1] < s.accepted[k - 2];
        const double base = cut ? 1.1 * s.accepted[k - 2] : s.accepted[k - 1];
        EXPECT_LE(s.accepted[k], 1.1 * base * (1 + 1e-15)) << "step " << k;
        if (cut)
        {
            EXPECT_GT(s.accepted[k], 1.1 * s.accepted[k - 1]) << "step " << k;
            ++cuts;
        }
        t += s.accepted[k];
    }
    EXPECT_GT(cuts, 0); // the toy's steps do cut some output times short
    const std::vector<double> expected{0.0, 0.25, 0.5, 0.75, 1.0};
    ASSERT_EQ(s.dumps.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k)
        EXPECT_NEAR(s.dumps[k], expected[k], 1e-14);
    ASSERT_EQ(r.initialTotals.size(), 1u);
    EXPECT_EQ(r.initialTotals[0], 1.0);
    EXPECT_EQ(r.finalTotals[0], s.y);
    EXPECT_NEAR(s.y, std::exp(-1.0), 0.02); // forward Euler at dt <= 0.1
    EXPECT_EQ(r.state.retries, 0);
}

TEST(TimeLoop, RejectedStepsAreHalvedAndCounted)
{
    Decay s;
    s.maxAccepted = 0.03; // the stable step 0.1 grows past it: those steps are halved until accepted
    const auto r = unilag::runTimeLoop(s, control(), MPI_COMM_SELF);
    EXPECT_EQ(r.failure, "");
    EXPECT_DOUBLE_EQ(r.state.t, 1.0);
    EXPECT_GT(r.state.retries, 0);
    for (double dt : s.accepted)
        EXPECT_LE(dt, 0.03);
    EXPECT_EQ(s.attempts, int(r.state.steps) + r.state.retries);
}

TEST(TimeLoop, FailureAfterRetriesAndStepCap)
{
    Decay s;
    s.alwaysFail = true;
    auto c = control();
    c.maxRetries = 3;
    const auto r = unilag::runTimeLoop(s, c, MPI_COMM_SELF);
    EXPECT_EQ(r.failure, "toy failure after 3 halvings");
    EXPECT_EQ(r.state.steps, 0);
    EXPECT_EQ(s.dumps.size(), 1u); // the initial state only: nothing is written after a failure

    Decay capped;
    c = control();
    c.maxSteps = 7;
    const auto rc = unilag::runTimeLoop(capped, c, MPI_COMM_SELF);
    EXPECT_EQ(rc.state.steps, 7);
    EXPECT_LT(rc.state.t, 1.0);
}

} // namespace
