// The load balance's online cost fit (src/solver/CostFit.hpp): from ranks' busy times and cost terms it recovers the
// cost of a term in cell-steps, follows a cost that changes, and keeps the prior where the data do not determine it
// (every rank with the same mix of terms) or give an unphysical (negative) cost.
#include <gtest/gtest.h>

#include <vector>

#include "solver/CostFit.hpp"

namespace
{

using unilag::CostFit;

//! Busy seconds of ranks with the given cell-steps and evaluations: a cell-step costs 2 us, an evaluation w times
//! that; each rank's time off by the given relative noise.
std::vector<double> busyTimes(const std::vector<std::vector<double>>& terms, double w, const std::vector<double>& noise)
{
    std::vector<double> busy;
    for (std::size_t p = 0; p < terms.size(); ++p)
        busy.push_back(2e-6 * (terms[p][0] + w * terms[p][1]) * (1.0 + noise[p]));
    return busy;
}

const std::vector<std::vector<double>> fourRanks = {{1000, 0}, {1200, 3000}, {800, 8000}, {1000, 500}};
const std::vector<std::vector<double>> afterRepartition = {{1300, 100}, {1000, 2500}, {700, 6000}, {1000, 1500}};
const std::vector<double> noise = {0.02, -0.015, 0.01, -0.02};

TEST(CostFit, RecoversTheEvaluationCost)
{
    CostFit fit({1.0, 0.1});
    fit.add(busyTimes(fourRanks, 0.4, noise), fourRanks);
    EXPECT_TRUE(fit.fitted());
    EXPECT_NEAR(fit.weights()[0], 1.0, 1e-15);
    EXPECT_NEAR(fit.weights()[1], 0.4, 0.04);
    fit.add(busyTimes(afterRepartition, 0.4, {-0.01, 0.02, -0.02, 0.01}), afterRepartition);
    EXPECT_NEAR(fit.weights()[1], 0.4, 0.03);
}

TEST(CostFit, FollowsACostThatChanges)
{
    CostFit fit({1.0, 0.1});
    for (int check = 0; check < 4; ++check)
        fit.add(busyTimes(check % 2 ? fourRanks : afterRepartition, 0.1, noise),
                check % 2 ? fourRanks : afterRepartition);
    EXPECT_NEAR(fit.weights()[1], 0.1, 0.02);
    for (int check = 0; check < 8; ++check) // weighted down 0.7 per check, the old ones weigh 0.7^8 = 6%
        fit.add(busyTimes(check % 2 ? fourRanks : afterRepartition, 0.5, noise),
                check % 2 ? fourRanks : afterRepartition);
    EXPECT_NEAR(fit.weights()[1], 0.5, 0.05);
}

TEST(CostFit, KeepsThePriorWhereTheRanksMixTheTermsAlike)
{
    // every rank 5 evaluations per cell-step: any split of the time between the two terms fits
    const std::vector<std::vector<double>> alike = {{1000, 5000}, {1200, 6000}, {800, 4000}, {1000, 5000}};
    CostFit fit({1.0, 0.1});
    fit.add(busyTimes(alike, 0.4, noise), alike);
    EXPECT_FALSE(fit.fitted());
    EXPECT_EQ(fit.weights()[1], 0.1);
}

TEST(CostFit, KeepsThePriorForANegativeCost)
{
    // ranks with more evaluations took less time: noise, not a cost
    CostFit fit({1.0, 0.1});
    fit.add(busyTimes(fourRanks, 0.0, {0.3, 0.0, -0.4, 0.1}), fourRanks);
    EXPECT_FALSE(fit.fitted());
    EXPECT_EQ(fit.weights()[1], 0.1);
}

TEST(CostFit, OneTermHasNothingToFit)
{
    CostFit fit({1.0});
    fit.add({1.0, 2.0}, {{1000}, {1000}});
    EXPECT_FALSE(fit.fitted());
    EXPECT_EQ(fit.weights(), std::vector<double>{1.0});
}

} // namespace
