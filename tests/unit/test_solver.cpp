// The solver's own classes on small distorted meshes (HostMesh.hpp, distributed on one rank): the field set's halo
// and migration, the forward-Euler and midpoint integrators through the operator, and stored stages combined with
// weights, by the operator and by hand.
#include <gtest/gtest.h>

#include "SolverHarness.hpp"

namespace
{

using unilag::LO;
using unilag_test::expression;

//! One ideal gas in the unit square or cube, slip walls all round, moving with a smooth velocity field.
unilag::Scene gasScene(int dim, int order)
{
    auto s = unilag_test::gasScene(dim, expression("1 + 0.2 * x"), expression("1 + 0.5 * y"),
                                   {expression("0.3 * sin(_pi * x) * cos(_pi * y)"),
                                    expression("-0.3 * cos(_pi * x) * sin(_pi * y)"), expression("")});
    s.boundaries["wall"] = unilag_test::slipWall();
    s.order = order;
    return s;
}

//! The distorted unit square (or cube), every boundary face in group "wall".
template <int D> unilag::GlobalMesh globalMesh(int n)
{
    unilag_test::HostMesh<D> h;
    if constexpr (D == 2)
        h = unilag_test::squareMesh(n, 0.2, 7);
    else
        h = unilag_test::cubeMesh(n, 0.2, 7);
    unilag_test::connect<D>(h, [](int) { return 0; });
    return unilag_test::globalMesh<D>(h, {"wall"});
}

//! The GPR model of the gas scene on the distorted mesh, initialised (state at t = 0, EOS and geometry current).
template <int D> struct Harness : unilag_test::SolverHarness<D>
{
    explicit Harness(int n, int order = 1) : unilag_test::SolverHarness<D>(gasScene(D, order), globalMesh<D>(n)) {}
    //! The rates at t^n that do not depend on dt, and the stable step.
    double prepare()
    {
        this->op.setBoundaryTime(0.0);
        this->op.solveNodes();
        return this->op.stableTimeStep();
    }
};

//! Stored rates of one stage with weight 1 give the fused forward-Euler update bit for bit.
template <int D> void checkStoredStageEqualsEuler()
{
    Harness<D> h(4);
    ASSERT_EQ(h.error, "");
    const double dt = h.prepare();
    ASSERT_GT(dt, 0.0);
    unilag::ForwardEuler<D, unilag::PhysicsHydro> euler(h.op);
    unilag::StageResult r;
    ASSERT_TRUE(euler.step(0.0, dt, r));
    const auto fused = h.host("state_new");
    h.op.storeStageRates("rates_0");
    const auto check = h.op.updateFromStages(dt, {{"rates_0", 1.0}});
    EXPECT_TRUE(unilag::admissible(check));
    const auto stored = h.host("state_new");
    const LO owned = h.model.m.nOwnedCells, rows = LO(fused.size() / (D + 2));
    for (int c = 0; c < D + 2; ++c)
        for (LO i = 0; i < owned; ++i)
            ASSERT_EQ(stored[c * rows + i], fused[c * rows + i]) << "cell " << i << " component " << c;
}

/*! Two stages (the rates at t^n and those after one step) combined with weights by the operator, and by hand from the
 *  stored rates: velocity and energy agree to the last bit. */
template <int D> void checkTwoStagesByHand()
{
    using S = unilag::StateLayout<D>;
    using R = unilag::RateLayout<D, unilag::PhysicsHydro>;
    Harness<D> h(4);
    ASSERT_EQ(h.error, "");
    double dt = h.prepare();
    h.op.storeStageRates("rates_a");
    unilag::ForwardEuler<D, unilag::PhysicsHydro> euler(h.op);
    unilag::StageResult r;
    ASSERT_TRUE(euler.step(0.0, dt, r));
    h.op.advance();
    dt = h.prepare();
    h.op.storeStageRates("rates_b");
    const double wa = 0.25, wb = 0.75;
    EXPECT_TRUE(unilag::admissible(h.op.updateFromStages(dt, {{"rates_a", wa}, {"rates_b", wb}})));
    const auto q0 = h.host("state"), q1 = h.host("state_new"), ra = h.host("rates_a"), rb = h.host("rates_b");
    const auto mass = h.host("mass");
    const LO rows = LO(mass.size());
    for (LO i = 0; i < h.model.m.nOwnedCells; ++i)
    {
        const double dtm = dt / mass[i];
        for (int d = 0; d < D; ++d)
        {
            const double rate = wa * ra[(R::momentum + d) * rows + i] + wb * rb[(R::momentum + d) * rows + i];
            ASSERT_EQ(q1[(S::vel + d) * rows + i], q0[(S::vel + d) * rows + i] + dtm * rate) << "cell " << i;
        }
        const double power = wa * ra[R::power * rows + i] + wb * rb[R::power * rows + i];
        ASSERT_EQ(q1[S::energy * rows + i], q0[S::energy * rows + i] + dtm * power) << "cell " << i;
    }
}

TEST(Solver, StoredStageEqualsForwardEuler2D)
{
    checkStoredStageEqualsEuler<2>();
}
TEST(Solver, StoredStageEqualsForwardEuler3D)
{
    checkStoredStageEqualsEuler<3>();
}
TEST(Solver, TwoStagesCombinedByHand2D)
{
    checkTwoStagesByHand<2>();
}
TEST(Solver, TwoStagesCombinedByHand3D)
{
    checkTwoStagesByHand<3>();
}

/*! The midpoint integrator through the operator conserves mass and total energy to round-off over a few steps (slip
 *  walls do no work) and leaves the GCL defect at round-off. */
TEST(Solver, MidpointConservesEnergy2D)
{
    Harness<2> h(6, 2);
    ASSERT_EQ(h.error, "");
    double before[unilag::TotalsLayout<2>::size], after[unilag::TotalsLayout<2>::size];
    unilag::totals(h.model, before);
    unilag::Midpoint<2, unilag::PhysicsHydro> midpoint(h.op);
    for (int step = 0; step < 5; ++step)
    {
        const double dt = 0.5 * h.prepare();
        h.model.fields.copy("v_node", "v_node0");
        unilag::StageResult r;
        ASSERT_TRUE(midpoint.step(0.0, dt, r)) << r.failure;
        EXPECT_LT(r.check.maxGclDefect, 1e-13);
        h.op.advance();
    }
    unilag::totals(h.model, after);
    EXPECT_NEAR(after[0], before[0], 1e-14 * before[0]);
    EXPECT_NEAR(after[3], before[3], 1e-13 * before[3]);
}

//! halo() fills ghost rows from their owners; migrate() onto the same distribution keeps persistent fields and
//! reallocates scratch ones.
TEST(FieldSet, HaloAndMigrate)
{
    auto mesh = unilag::DistributedMesh::distribute(globalMesh<2>(4), Tpetra::getDefaultComm());
    unilag::FieldSet fields(mesh);
    fields.add("a", unilag::Entity::Cell, 2, unilag::Lifetime::Persistent);
    fields.add("b", unilag::Entity::Node, 1, unilag::Lifetime::Scratch);
    {
        auto a = fields["a"].getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (LO i = 0; i < mesh->nCells; ++i)
            for (int c = 0; c < 2; ++c)
                a(i, c) = i < mesh->nOwnedCells ? double(mesh->cellGid[i]) + 0.5 * c : -1.0;
        fields["b"].putScalar(3.0);
    }
    fields.halo("a");
    fields.migrate(mesh);
    auto a = fields["a"].getLocalViewHost(Tpetra::Access::ReadOnly);
    for (LO i = 0; i < mesh->nCells; ++i)
        for (int c = 0; c < 2; ++c)
            ASSERT_EQ(a(i, c), double(mesh->cellGid[i]) + 0.5 * c);
    EXPECT_EQ(fields["b"].getVector(0)->normInf(), 0.0);
    EXPECT_EQ(fields.names(unilag::Lifetime::Persistent), std::vector<std::string>{"a"});
    EXPECT_THROW(fields.add("a", unilag::Entity::Cell, 1, unilag::Lifetime::Scratch), std::logic_error);
}

} // namespace
