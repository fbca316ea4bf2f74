// The hydro solver as a run steps it (GprSystem: prepareStep, beginAttempts, attemptStep, acceptStep) on small
// distorted simplex meshes (HostMesh.hpp, distributed on one rank), at first order (forward Euler) and at second order
// (the midpoint predictor-corrector with the limited reconstruction of the scene's default limiter):
//  - free stream: a uniform state with every boundary node driven at the stream velocity stays uniform to round-off,
//    and the mesh travels with the stream;
//  - slip walls (one group per wall, or one group around corners and edges): mass (through the GCL) and total energy
//    are conserved to round-off, momentum changes by the boundary impulse sum dt f_r, wall nodes have no normal
//    velocity and interior nodes no net force.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "SolverHarness.hpp"

namespace
{

using unilag::GO;
using unilag::LO;
using unilag_test::connect;
using unilag_test::constant;
using unilag_test::cubeMesh;
using unilag_test::expression;
using unilag_test::HostMesh;
using unilag_test::squareMesh;
using unilag_test::wallGroup;
using P = unilag::PhysicsHydro;

template <int D> double length(const double* a, LO stride = 1)
{
    double s = 0.0;
    for (int d = 0; d < D; ++d)
        s += a[d * stride] * a[d * stride];
    return std::sqrt(s);
}

/*! Free stream: uniform state, every boundary node driven at the stream velocity u. The state and the node
 *  velocities must stay uniform to round-off on the distorted mesh, at the stable time step. */
template <int D> void checkFreeStream(HostMesh<D> h, const std::array<double, 3>& u, int order)
{
    using S = unilag::StateLayout<D, P>;
    const double gamma = 1.4, rho0 = 1.0, p0 = 1.0;
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, [](int) { return 0; }));
    std::vector<unilag::Expr> velocity;
    for (int d = 0; d < D; ++d)
        velocity.push_back(constant(u[d]));
    auto scene = unilag_test::gasScene(D, constant(rho0), constant(p0), velocity, gamma);
    scene.boundaries["stream"] = unilag_test::imposedVelocity(u);
    scene.order = order;
    unilag_test::SolverHarness<D> hs(scene, unilag_test::globalMesh<D>(h, {"stream"}));
    ASSERT_EQ(hs.error, "");
    const auto& dm = *hs.model.mesh;
    unilag::GprSystem<D, P> system(hs.model);
    system.start();

    double kin = 0.0;
    for (int d = 0; d < D; ++d)
        kin += 0.5 * u[d] * u[d];
    const double E0 = p0 / ((gamma - 1.0) * rho0) + kin;

    double t = 0.0;
    for (int step = 0; step < 5; ++step)
    {
        // the node velocities the step's update used (the corrector's at second order)
        auto nodes = [&](double)
        {
            const auto vn = hs.host("v_node");
            double worst = 0.0;
            LO at = -1;
            for (LO r = 0; r < dm.nNodes; ++r)
                for (int d = 0; d < D; ++d)
                    if (std::abs(vn[d * dm.nNodes + r] - u[d]) > worst)
                    {
                        worst = std::abs(vn[d * dm.nNodes + r] - u[d]);
                        at = LO(dm.nodeGid[r]);
                    }
            EXPECT_LE(worst, 1e-14) << "step " << step << " node " << at;
        };
        const double dt = unilag_test::loopStep(system, t, step, nodes);
        ASSERT_GT(dt, 0.0);
        t += dt;
        EXPECT_LT(system.maxGclDefect(), 1e-13) << "step " << step;

        const auto s = hs.host("state");
        const LO rows = dm.nCells;
        for (LO i = 0; i < dm.nOwnedCells; ++i)
        {
            ASSERT_NEAR(1.0 / s[S::omega * rows + i], rho0, 1e-13 * rho0) << "step " << step << " cell " << i;
            for (int d = 0; d < D; ++d)
                ASSERT_NEAR(s[(S::vel + d) * rows + i], u[d], 1e-13)
                    << "step " << step << " cell " << i << " dir " << d;
            ASSERT_NEAR(s[S::energy * rows + i], E0, 1e-13 * E0) << "step " << step << " cell " << i;
        }
    }
    // the mesh has travelled with the stream (the steps were not trivially small): HostMesh node 0 started at 0
    const auto x = hs.host("x");
    LO origin = -1;
    for (LO r = 0; r < dm.nNodes; ++r)
        if (dm.nodeGid[r] == 0)
            origin = r;
    ASSERT_GE(origin, 0);
    for (int d = 0; d < D; ++d)
        EXPECT_NEAR(x[d * dm.nNodes + origin], u[d] * t, 1e-13);
    EXPECT_GT(t, 0.01);
}

/*! Slip walls on the faces of the box (one group per wall, or one group for all walls, so that a group has corners
 *  and edges): mass (through the GCL) and total energy are conserved, momentum changes by the boundary impulse,
 *  walls see no normal node velocity and interior nodes no net force. */
template <int D> void checkConservation(HostMesh<D> h, int steps, bool oneGroup, int order)
{
    std::vector<std::string> names;
    if (oneGroup)
    {
        ASSERT_NO_FATAL_FAILURE(connect<D>(h, [](int common) { return wallGroup(common) >= 0 ? 0 : -1; }));
        names = {"walls"};
    }
    else
    {
        ASSERT_NO_FATAL_FAILURE(connect<D>(h, wallGroup)); // groups 0 .. 2D-1: x = 0, x = 1, y = 0, ...
        names = {"x0", "x1", "y0", "y1", "z0", "z1"};
        names.resize(2 * D);
    }
    // + 0.5 x in the pressure: unequal pressure on the two x-walls, so the boundary impulse is not small
    auto scene =
        unilag_test::gasScene(D, expression("1 + 0.2 * x"),
                              expression("1 + 0.5 * sin(2 * _pi * x) * cos(2 * _pi * y) * cos(_pi * z) + 0.5 * x"),
                              {expression("0.1 * y"), expression("-0.2 * x"), expression("0.15 * x * y")});
    for (const auto& name : names)
        scene.boundaries[name] = unilag_test::slipWall();
    scene.order = order;
    unilag_test::SolverHarness<D> hs(scene, unilag_test::globalMesh<D>(h, names));
    ASSERT_EQ(hs.error, "");
    const auto& dm = *hs.model.mesh;
    // one rank: every node is owned, so fnode (owned nodes) covers the mesh and local node r is HostMesh node gid
    ASSERT_EQ(dm.nOwnedNodes, dm.nNodes);
    unilag::GprSystem<D, P> system(hs.model);
    system.start();

    const auto initial = hs.totals();
    double impulse[D] = {}, t = 0.0;
    for (int step = 0; step < steps; ++step)
    {
        // the node velocities and force sums the step's update used (the corrector's at second order)
        auto nodes = [&](double dt)
        {
            const auto vn = hs.host("v_node");
            auto fn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hs.model.fnode);
            const LO rows = dm.nNodes;
            double vmax = 0.0;
            for (LO r = 0; r < rows; ++r)
                vmax = std::max(vmax, length<D>(&vn[r], rows));
            ASSERT_GT(vmax, 0.0);
            double worstNormal = 0.0, worstForce = 0.0;
            GO normalAt = -1, forceAt = -1;
            for (LO r = 0; r < rows; ++r)
            {
                const int wall = h.wall[dm.nodeGid[r]];
                double f[D];
                for (int d = 0; d < D; ++d)
                {
                    f[d] = fn(r, d);
                    impulse[d] += dt * fn(r, d);
                    // on x_d = 0 or x_d = 1: no normal velocity
                    if ((wall & (3 << (2 * d))) && std::abs(vn[d * rows + r]) > worstNormal)
                    {
                        worstNormal = std::abs(vn[d * rows + r]);
                        normalAt = dm.nodeGid[r];
                    }
                }
                if (!wall && length<D>(f) > worstForce) // interior nodes exert no net force
                {
                    worstForce = length<D>(f);
                    forceAt = dm.nodeGid[r];
                }
            }
            EXPECT_LE(worstNormal, 1e-15 * vmax) << "normal velocity, step " << step << " node " << normalAt;
            EXPECT_LE(worstForce, 1e-12) << "interior net force, step " << step << " node " << forceAt;
        };
        const double dt = unilag_test::loopStep(system, t, step, nodes);
        ASSERT_GT(dt, 0.0);
        t += dt;
        EXPECT_LT(system.maxGclDefect(), 1e-12) << "step " << step;

        const auto now = hs.totals();
        EXPECT_NEAR(now[0], initial[0], 1e-13 * initial[0]) << "mass (GCL), step " << step;
        EXPECT_NEAR(now[1 + D], initial[1 + D], 1e-13 * initial[1 + D]) << "total energy, step " << step;
        const double scale = now[2 + D] + length<D>(impulse);
        for (int d = 0; d < D; ++d)
        {
            EXPECT_NEAR(now[1 + d] - initial[1 + d], impulse[d], 1e-13 * scale)
                << "momentum " << d << ", step " << step;
            // the run's own bookkeeping (acceptStep) sums the same forces
            EXPECT_NEAR(system.impulse()[d], impulse[d], 1e-13 * scale) << "system impulse " << d;
        }
        // slip walls do no work: the run's boundary work stays at round-off of the total energy
        EXPECT_NEAR(system.work(), 0.0, 1e-13 * initial[1 + D]) << "step " << step;
    }
    // the walls did push: the momentum balance above is not 0 = 0
    EXPECT_GT(std::abs(impulse[0]), 1e-3);
    // and the flow did move: the momentum changed well above round-off
    const auto last = hs.totals();
    EXPECT_GT(std::abs(last[1] - initial[1]), 1e-3 * last[2 + D]);
}

TEST(HydroSolver, FreeStreamPreserved2D)
{
    checkFreeStream<2>(squareMesh(12, 0.3, 2024), {1.0, 0.5, 0.0}, 1);
}
TEST(HydroSolver, FreeStreamPreserved3D)
{
    checkFreeStream<3>(cubeMesh(4, 0.2, 2025), {1.0, 0.5, -0.25}, 1);
}
TEST(HydroSolver, FreeStreamPreservedSecondOrder2D)
{
    checkFreeStream<2>(squareMesh(12, 0.3, 2024), {1.0, 0.5, 0.0}, 2);
}
TEST(HydroSolver, FreeStreamPreservedSecondOrder3D)
{
    checkFreeStream<3>(cubeMesh(4, 0.2, 2025), {1.0, 0.5, -0.25}, 2);
}

TEST(HydroSolver, ConservationWithSlipWalls2D)
{
    checkConservation<2>(squareMesh(12, 0.3, 7), 10, false, 1);
}
TEST(HydroSolver, ConservationWithSlipWalls3D)
{
    checkConservation<3>(cubeMesh(4, 0.2, 8), 10, false, 1);
}
TEST(HydroSolver, ConservationWithOneSlipGroupAroundCorners2D)
{
    checkConservation<2>(squareMesh(12, 0.3, 7), 10, true, 1);
}
TEST(HydroSolver, ConservationWithOneSlipGroupAroundCorners3D)
{
    checkConservation<3>(cubeMesh(4, 0.2, 11), 10, true, 1);
}
TEST(HydroSolver, ConservationSecondOrder2D)
{
    checkConservation<2>(squareMesh(12, 0.3, 7), 10, false, 2);
}
TEST(HydroSolver, ConservationSecondOrder3D)
{
    checkConservation<3>(cubeMesh(4, 0.2, 8), 10, true, 2);
}

} // namespace
