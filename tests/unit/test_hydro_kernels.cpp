// Hydro kernels (kernels/unilag/Hydro.hpp, Reconstruction.hpp) on hand-built distorted simplex meshes, without MPI
// maps: the second-order reconstruction, whose least-squares gradients are exact for linear fields (slip walls
// mirrored, imposed pressures fitted) and whose limited node values stay within the neighbours' cell values; and
// computeEos's signal speed per material. Free stream and conservation of whole steps are checked on the solver
// itself (test_solver_hydro.cpp), not on a copy of its step sequence.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "HostMesh.hpp"
#include "HydroFixture.hpp"
#include "unilag/CellUpdate.hpp"

namespace
{

using unilag::BcSlipWall;
using unilag::Field;
using unilag::LO;
using unilag::MemSpace;
using unilag_test::connect;
using unilag_test::cubeMesh;
using unilag_test::HostMesh;
using unilag_test::Hydro;
using unilag_test::squareMesh;
using unilag_test::wallGroup;

/*! Reconstruction of p = 1 + g . x and v = A x on the distorted mesh: the least-squares gradients are exact (every
 *  cell, boundary cells included); the limited ones keep every vertex value within the cell's and its face
 *  neighbours' values, and are not all clipped to zero. */
template <int D> void checkReconstruction(HostMesh<D> h)
{
    using R = unilag::ReconLayout<D, unilag::PhysicsHydro>;
    const double gamma = 1.4;
    const double g[3] = {0.3, -0.7, 0.45};
    const double A[3][3] = {{0.2, -0.5, 0.1}, {0.4, 0.3, -0.2}, {-0.1, 0.25, 0.6}};
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, [](int) { return 0; }));
    Hydro<D> hydro(h, gamma, {{BcSlipWall, {0.0, 0.0, 0.0}}});
    ASSERT_NO_FATAL_FAILURE(hydro.initialize(
        [&](const double* c, double& rho, double& p, double* v)
        {
            rho = 1.0;
            p = 1.0;
            for (int a = 0; a < D; ++a)
            {
                p += g[a] * c[a];
                v[a] = 0.0;
                for (int b = 0; b < D; ++b)
                    v[a] += A[a][b] * c[b];
            }
        },
        gamma));
    unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                      hydro.geom, hydro.x, hydro.grad, unilag::BoundaryView(),
                                                      unilag::Limiter::None);
    auto gr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.grad);
    for (LO i = 0; i < hydro.nCells; ++i)
        for (int a = 0; a < D; ++a)
        {
            ASSERT_NEAR(gr(i, R::pressure * D + a), g[a], 1e-12) << "cell " << i;
            for (int b = 0; b < D; ++b)
                ASSERT_NEAR(gr(i, (R::vel + b) * D + a), A[b][a], 1e-12) << "cell " << i;
        }

    unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                      hydro.geom, hydro.x, hydro.grad);
    Kokkos::deep_copy(gr, hydro.grad);
    auto aux = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.aux);
    auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.x);
    auto ch = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.geom.centroid);
    auto cn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.mesh.cellNodes);
    auto nb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.mesh.cellNeighbour);
    double kept = 0.0, gnorm = 0.0;
    for (int a = 0; a < D; ++a)
        gnorm += g[a] * g[a];
    gnorm = std::sqrt(gnorm);
    // extrema of the pressure over cell i and its face neighbours
    auto faceBounds = [&](LO i, double& lo, double& hi)
    {
        lo = hi = aux(i, unilag::Aux::pressure);
        for (int k = 0; k < D + 1; ++k)
            if (nb(i, k) >= 0)
            {
                lo = std::min(lo, aux(nb(i, k), unilag::Aux::pressure));
                hi = std::max(hi, aux(nb(i, k), unilag::Aux::pressure));
            }
    };
    // the reconstructed pressure of cell i at its vertex k
    auto vertexValue = [&](LO i, int k)
    {
        double w = aux(i, unilag::Aux::pressure);
        for (int a = 0; a < D; ++a)
            w += gr(i, R::pressure * D + a) * (xh(cn(i, k), a) - ch(i, a));
        return w;
    };
    for (LO i = 0; i < hydro.nCells; ++i)
    {
        double lo, hi;
        faceBounds(i, lo, hi);
        for (int k = 0; k < D + 1; ++k)
        {
            const double w = vertexValue(i, k);
            EXPECT_GE(w, lo - 1e-14) << "cell " << i << " vertex " << k;
            EXPECT_LE(w, hi + 1e-14) << "cell " << i << " vertex " << k;
        }
        // the limiter only scales the gradient
        double dotg = 0.0, n2 = 0.0;
        for (int a = 0; a < D; ++a)
        {
            dotg += gr(i, R::pressure * D + a) * g[a];
            n2 += gr(i, R::pressure * D + a) * gr(i, R::pressure * D + a);
        }
        EXPECT_NEAR(dotg, std::sqrt(n2) * gnorm, 1e-12) << "cell " << i;
        kept += std::sqrt(n2) / gnorm / hydro.nCells;
    }
    // Face-neighbour bounds clip linear fields at many vertices, but the mean kept fraction of the slope stays well
    // above zero (measured 0.585 in 2D and 0.429 in 3D on these meshes; 0 would be first order).
    EXPECT_GT(kept, D == 2 ? 0.5 : 0.3);
    std::printf("mean limiter factor on a linear field: %.3f\n", kept);

    // Vertex-based bounds: each vertex value within the extrema of the cell, its face neighbours and the cells around
    // that vertex; a linear field keeps its whole slope in every cell without a boundary vertex (an interior vertex
    // lies inside the hull of the centroids around it), so smooth flows keep second order there.
    unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                      hydro.geom, hydro.x, hydro.grad, unilag::BoundaryView(),
                                                      unilag::Limiter::VertexBased);
    Kokkos::deep_copy(gr, hydro.grad);
    std::vector<double> nodeMin(hydro.nNodes, 1e300), nodeMax(hydro.nNodes, -1e300);
    for (LO i = 0; i < hydro.nCells; ++i)
        for (int k = 0; k < D + 1; ++k)
        {
            nodeMin[cn(i, k)] = std::min(nodeMin[cn(i, k)], aux(i, unilag::Aux::pressure));
            nodeMax[cn(i, k)] = std::max(nodeMax[cn(i, k)], aux(i, unilag::Aux::pressure));
        }
    int interiorCells = 0;
    double keptVertex = 0.0;
    for (LO i = 0; i < hydro.nCells; ++i)
    {
        double lo, hi;
        faceBounds(i, lo, hi);
        bool interior = true;
        for (int k = 0; k < D + 1; ++k)
        {
            const double w = vertexValue(i, k);
            EXPECT_GE(w, std::min(lo, nodeMin[cn(i, k)]) - 1e-14) << "cell " << i << " vertex " << k;
            EXPECT_LE(w, std::max(hi, nodeMax[cn(i, k)]) + 1e-14) << "cell " << i << " vertex " << k;
            interior = interior && h.wall[cn(i, k)] == 0;
        }
        double n2 = 0.0;
        for (int a = 0; a < D; ++a)
            n2 += gr(i, R::pressure * D + a) * gr(i, R::pressure * D + a);
        keptVertex += std::sqrt(n2) / gnorm / hydro.nCells;
        if (interior)
        {
            ++interiorCells;
            for (int a = 0; a < D; ++a)
                EXPECT_NEAR(gr(i, R::pressure * D + a), g[a], 1e-12) << "interior cell " << i;
        }
    }
    EXPECT_GT(interiorCells, 0);
    EXPECT_GT(keptVertex, 0.85); // measured 0.93 (2D), 0.96 (3D); face-neighbour bounds keep 0.59, 0.43
    std::printf("vertex-based: mean limiter factor %.3f, %d of %d cells (no boundary vertex) keep the whole slope\n",
                keptVertex, interiorCells, int(hydro.nCells));

    // The velocity alone: its gradients bitwise those of VertexBased, the pressure's zero (cell values).
    unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                      hydro.geom, hydro.x, hydro.grad, unilag::BoundaryView(),
                                                      unilag::Limiter::VertexBased, unilag::Reconstructed::Velocity);
    auto velocityOnly = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.grad);
    for (LO i = 0; i < hydro.nCells; ++i)
        for (int a = 0; a < D; ++a)
        {
            ASSERT_EQ(velocityOnly(i, R::pressure * D + a), 0.0) << "cell " << i;
            for (int b = 0; b < D; ++b)
                ASSERT_EQ(velocityOnly(i, (R::vel + b) * D + a), gr(i, (R::vel + b) * D + a)) << "cell " << i;
        }
}

} // namespace

TEST(HydroKernels, ReconstructionLinearExactAndBounded2D)
{
    checkReconstruction<2>(squareMesh(12, 0.3, 31));
}

TEST(HydroKernels, ReconstructionLinearExactAndBounded3D)
{
    checkReconstruction<3>(cubeMesh(4, 0.2, 32));
}

namespace
{

/*! The node sums (LeastSquares.hpp) against their definition, summed cell by cell on the host: the unlimited gradient
 *  of a curved pressure field minimises sum_r sum_{j around r} w_jr (p_j - p_i - g . (x_j - x_i))^2 over the nodes r
 *  of cell i, w_jr = 1 / |x_j - x_r|^2. A wrong weight (the distance to cell i, as before session 24) or a wrong term
 *  of the expanded normal equations gives a different gradient wherever the field is not linear. */
template <int D> void checkNodeSumsDefinition(HostMesh<D> h)
{
    using R = unilag::ReconLayout<D, unilag::PhysicsHydro>;
    const double gamma = 1.4;
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, [](int) { return 0; }));
    Hydro<D> hydro(h, gamma, {{BcSlipWall, {0.0, 0.0, 0.0}}});
    ASSERT_NO_FATAL_FAILURE(hydro.initialize(
        [&](const double* c, double& rho, double& p, double* v)
        {
            rho = 1.0;
            p = 1e3 + std::sin(3.0 * c[0]) + c[1] * c[1] + (D == 3 ? c[0] * c[2] : 0.0); // a large offset: round-off
            for (int a = 0; a < D; ++a)
                v[a] = 0.0;
        },
        gamma));
    unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                      hydro.geom, hydro.x, hydro.grad, unilag::BoundaryView(),
                                                      unilag::Limiter::None);
    auto gr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.grad);
    auto aux = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.aux);
    auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.x);
    auto ch = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.geom.centroid);
    auto cn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.mesh.cellNodes);
    std::vector<std::vector<LO>> cellsAround(hydro.nNodes);
    for (LO i = 0; i < hydro.nCells; ++i)
        for (int k = 0; k < D + 1; ++k)
            cellsAround[cn(i, k)].push_back(i);
    double largestDifference = 0.0, largestPairDifference = 0.0;
    for (LO i = 0; i < hydro.nCells; ++i)
    {
        // normal equations with the node weights (M, b) and with the pair weights 1 / |x_j - x_i|^2 (Mp, bp)
        unilag::Mat<D> M = unilag::Mat<D>::zero(), Mp = unilag::Mat<D>::zero();
        unilag::Vec<D> b = unilag::Vec<D>::zero(), bp = unilag::Vec<D>::zero();
        for (int k = 0; k < D + 1; ++k)
        {
            const LO r = cn(i, k);
            for (LO j : cellsAround[r])
            {
                unilag::Vec<D> d, e;
                for (int a = 0; a < D; ++a)
                {
                    d[a] = ch(j, a) - ch(i, a);
                    e[a] = ch(j, a) - xh(r, a);
                }
                const double dp = aux(j, unilag::Aux::pressure) - aux(i, unilag::Aux::pressure);
                const double w = 1.0 / unilag::dot(e, e);
                M.addOuter(w, d);
                b = b + (w * dp) * d;
                if (j != i)
                {
                    const double wp = 1.0 / unilag::dot(d, d);
                    Mp.addOuter(wp, d);
                    bp = bp + (wp * dp) * d;
                }
            }
        }
        const unilag::Vec<D> g = unilag::solve(M, b), gp = unilag::solve(Mp, bp);
        for (int a = 0; a < D; ++a)
        {
            const double kernel = gr(i, R::pressure * D + a);
            largestDifference = std::max(largestDifference, std::fabs(kernel - g[a]));
            largestPairDifference = std::max(largestPairDifference, std::fabs(kernel - gp[a]));
        }
    }
    EXPECT_LT(largestDifference, 1e-9) << "the node sums differ from their definition";
    EXPECT_GT(largestPairDifference, 1e-3) << "the test cannot tell the node weights from the pair weights";
    std::printf("node sums against their definition: %.2e; against the pair weights: %.2e\n", largestDifference,
                largestPairDifference);
}

} // namespace

TEST(HydroKernels, ReconstructionNodeSumsAreTheirDefinition2D)
{
    checkNodeSumsDefinition<2>(squareMesh(12, 0.3, 33));
}

TEST(HydroKernels, ReconstructionNodeSumsAreTheirDefinition3D)
{
    checkNodeSumsDefinition<3>(cubeMesh(4, 0.2, 34));
}

/*! Slip walls and symmetry planes enter the stencil as mirror images: of the cell across its wall face, and of the
 *  cells around a wall node across the wall. A linear field that is symmetric about the wall x = 0 (pressure and
 *  tangential velocity even in x, normal velocity odd) stays exact in every cell; one that is not (pressure odd in x)
 *  is not exact in the cells with a vertex on the wall, which shows the mirrors are used, and exact in the others. */
template <int D> void checkMirror(HostMesh<D> h)
{
    using R = unilag::ReconLayout<D, unilag::PhysicsHydro>;
    const double gamma = 1.4;
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, wallGroup)); // groups 0 .. 2D-1: x = 0, x = 1, y = 0, ...
    std::vector<std::pair<int, std::array<double, 3>>> bcs(2 * D, {unilag::BcFree, {0.0, 0.0, 0.0}});
    bcs[0].first = BcSlipWall;
    for (const double odd : {0.0, 0.8})
    {
        Hydro<D> hydro(h, gamma, bcs);
        ASSERT_NO_FATAL_FAILURE(hydro.initialize(
            [&](const double* c, double& rho, double& p, double* v)
            {
                rho = 1.0;
                p = 2.0 + odd * c[0] + 0.3 * c[1] - (D == 3 ? 0.2 * c[D - 1] : 0.0);
                v[0] = 0.7 * c[0];
                for (int b = 1; b < D; ++b)
                    v[b] = 0.4 * c[1] - 0.25 * b * c[D - 1];
            },
            gamma));
        unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                          hydro.geom, hydro.x, hydro.grad, hydro.bc,
                                                          unilag::Limiter::None);
        auto gr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.grad);
        auto fg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.mesh.cellFaceGroup);
        int wallCells = 0;
        for (LO i = 0; i < hydro.nCells; ++i)
        {
            bool atWall = false; // a vertex on the wall x = 0 (a face there, or a node only)
            for (int k = 0; k < D + 1; ++k)
                atWall = atWall || fg(i, k) == 0 || h.x[D * h.cells[(D + 1) * i + k]] == 0.0;
            const double gp[3] = {odd, 0.3, D == 3 ? -0.2 : 0.0};
            if (odd == 0.0 || !atWall)
            {
                for (int a = 0; a < D; ++a)
                {
                    ASSERT_NEAR(gr(i, R::pressure * D + a), gp[a], 1e-12) << "cell " << i;
                    for (int b = 0; b < D; ++b)
                    {
                        double ga = 0.0; // d v_b / d x_a
                        if (b == 0)
                            ga = a == 0 ? 0.7 : 0.0;
                        else
                            ga = (a == 1 ? 0.4 : 0.0) - (a == D - 1 ? 0.25 * b : 0.0);
                        ASSERT_NEAR(gr(i, (R::vel + b) * D + a), ga, 1e-12) << "cell " << i;
                    }
                }
            }
            else
            {
                ++wallCells;
                EXPECT_GT(std::abs(gr(i, R::pressure * D) - odd), 1e-3) << "wall cell " << i;
            }
        }
        if (odd != 0.0)
        {
            EXPECT_GT(wallCells, 0);
        }
    }
}

TEST(HydroKernels, ReconstructionMirrorsSlipWalls2D)
{
    checkMirror<2>(squareMesh(10, 0.3, 41));
}

TEST(HydroKernels, ReconstructionMirrorsSlipWalls3D)
{
    checkMirror<3>(cubeMesh(4, 0.2, 42));
}

/*! An imposed boundary pressure is a data point of the pressure's least-squares fit at the face centroid. A linear
 *  pressure that takes the imposed value on the wall x = 0 stays exact in every cell; for p = 1 + 3 x^2 (imposed 1
 *  at x = 0) the wall cells' reconstruction at their wall vertices (where the nodal solver reads it) is closer to the
 *  imposed value with the boundary value in the fit than without it. */
template <int D> void checkImposedPressureFit(HostMesh<D> h)
{
    using R = unilag::ReconLayout<D, unilag::PhysicsHydro>;
    const double gamma = 1.4;
    ASSERT_NO_FATAL_FAILURE(connect<D>(h, wallGroup)); // groups 0 .. 2D-1: x = 0, x = 1, y = 0, ...
    std::vector<std::pair<int, std::array<double, 3>>> bcs(2 * D, {unilag::BcFree, {0.0, 0.0, 0.0}});
    for (const bool linear : {true, false})
    {
        bcs[0] = {unilag::BcPressure, {linear ? 2.0 : 1.0, 0.0, 0.0}};
        Hydro<D> hydro(h, gamma, bcs);
        ASSERT_NO_FATAL_FAILURE(hydro.initialize(
            [&](const double* c, double& rho, double& p, double* v)
            {
                rho = 1.0;
                p = linear ? 2.0 + 0.5 * c[0] : 1.0 + 3.0 * c[0] * c[0];
                for (int a = 0; a < D; ++a)
                    v[a] = 0.0;
            },
            gamma));
        auto fg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.mesh.cellFaceGroup);
        auto ch = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.geom.centroid);
        auto cn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.mesh.cellNodes);
        auto xh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.x);
        auto aux = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.aux);
        // mean error of the wall cells' pressure at their wall vertices (and every cell's gradient must be exact for
        // the linear field)
        auto wallError = [&](const unilag::BoundaryView& bc, int& wallCells)
        {
            unilag::limitedGradients<D, unilag::PhysicsHydro>(hydro.mesh, hydro.state, hydro.aux, unilag::ConstField(),
                                                              hydro.geom, hydro.x, hydro.grad, bc,
                                                              unilag::Limiter::None);
            auto gr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), hydro.grad);
            double err = 0.0;
            wallCells = 0;
            for (LO i = 0; i < hydro.nCells; ++i)
            {
                if (linear)
                {
                    for (int a = 0; a < D; ++a)
                    {
                        EXPECT_NEAR(gr(i, R::pressure * D + a), a == 0 ? 0.5 : 0.0, 1e-12) << "cell " << i;
                    }
                }
                for (int f = 0; f < D + 1; ++f)
                    if (fg(i, f) == 0)
                    {
                        ++wallCells;
                        for (int k = 0; k < D + 1; ++k)
                            if (k != f)
                            {
                                double pv = aux(i, unilag::Aux::pressure);
                                for (int a = 0; a < D; ++a)
                                    pv += gr(i, R::pressure * D + a) * (xh(cn(i, k), a) - ch(i, a));
                                err += std::abs(pv - bcs[0].second[0]) / D;
                            }
                    }
            }
            return err / std::max(wallCells, 1);
        };
        int wallCells = 0;
        const double errWith = wallError(hydro.bc, wallCells);
        const double errWithout = wallError(unilag::BoundaryView(), wallCells);
        if (!linear)
        {
            ASSERT_GT(wallCells, 0);
            std::printf("pressure error at the wall vertices, mean: %.2e with the boundary value, %.2e without\n",
                        errWith, errWithout);
            // measured 0.76 (2D) and 0.84 (3D) of the error without (0.69 and 0.79 with the pair weights before
            // session 24); 1 if the boundary value were not used
            EXPECT_LT(errWith, 0.85 * errWithout);
        }
    }
}

TEST(HydroKernels, ReconstructionFitsImposedPressures2D)
{
    checkImposedPressureFit<2>(squareMesh(10, 0.3, 43));
}

TEST(HydroKernels, ReconstructionFitsImposedPressures3D)
{
    checkImposedPressureFit<3>(cubeMesh(4, 0.2, 44));
}

/*! Walls meeting at the apex of a wedge with interior angle theta (the unit square sheared so that its sides x = 0
 *  and y = 0 meet at theta, both slip walls): the mean cell velocity at the apex node keeps no part normal to either
 *  wall where they are two planes (a 30-degree wedge), and only the part along the mean wall where they are one
 *  faceted wall (150 degrees: normals 30 degrees apart). With a test on |cosine| the 30-degree wedge was one plane
 *  through its bisector, and the apex kept a velocity along it. */
void checkWedgeApex(double thetaDegrees, bool twoPlanes)
{
    const double theta = thetaDegrees * M_PI / 180.0, gamma = 1.4;
    HostMesh<2> h = squareMesh(6, 0.1, 45);
    for (LO r = 0; r < h.nNodes(); ++r)
    {
        const double x = h.x[2 * r], y = h.x[2 * r + 1];
        h.x[2 * r] = x + std::cos(theta) * y;
        h.x[2 * r + 1] = std::sin(theta) * y;
    }
    ASSERT_NO_FATAL_FAILURE(connect<2>(h, wallGroup)); // groups 0 .. 3: x = 0, x = 1, y = 0, y = 1
    std::vector<std::pair<int, std::array<double, 3>>> bcs(4, {unilag::BcFree, {0.0, 0.0, 0.0}});
    bcs[0].first = bcs[2].first = BcSlipWall;
    Hydro<2> hydro(h, gamma, bcs);
    const double v0[2] = {1.0, 0.5};
    ASSERT_NO_FATAL_FAILURE(hydro.initialize(
        [&](const double*, double& rho, double& p, double* v)
        {
            rho = p = 1.0;
            v[0] = v0[0];
            v[1] = v0[1];
        },
        gamma));
    Field vnode("vnode", hydro.nNodes, 2);
    unilag::meanCellVelocityAtNodes<2>(hydro.mesh, hydro.state, hydro.x, vnode, hydro.bc);
    auto vh = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), vnode);
    ASSERT_EQ(h.x[0], 0.0); // node 0 is the apex
    ASSERT_EQ(h.x[1], 0.0);
    double expect[2] = {0.0, 0.0};
    if (!twoPlanes) // one plane, normal to the sum of the two walls' outward unit normals
    {
        const double n[2] = {-std::sin(theta), std::cos(theta) - 1.0}; // (0, -1) + (-sin, cos)
        const double len = std::hypot(n[0], n[1]), vn = (v0[0] * n[0] + v0[1] * n[1]) / (len * len);
        expect[0] = v0[0] - vn * n[0];
        expect[1] = v0[1] - vn * n[1];
        ASSERT_GT(std::hypot(expect[0], expect[1]), 0.1);
    }
    EXPECT_NEAR(vh(0, 0), expect[0], 1e-14);
    EXPECT_NEAR(vh(0, 1), expect[1], 1e-14);
}

TEST(HydroKernels, WedgeApexHasTwoWallPlanes) { checkWedgeApex(30.0, true); }
TEST(HydroKernels, WideCornerIsOneFacetedWall) { checkWedgeApex(150.0, false); }

/* The signal speed a = sqrt(c0^2 + 4/3 c_sh^2 + c_h^2) and the impedance rho a that computeEos forms
 * (docs/gpr-model.md 1.5), for each combination of shear and heat conduction: the shear term only with shear, the
 * heat term only with conduction, and c_h^2 = alpha^2 theta / (cv rho^2) at the local density (rho = 2 rho0 here). */
TEST(HydroKernels, SignalSpeedPerMaterial)
{
    constexpr int D = 2;
    using P = unilag::Physics<true, false, true>;
    using S = unilag::StateLayout<D, P>;
    const double gamma = 1.4, cv = 2.5, csh = 3.0, alpha = 2.0, rho = 2.0, p = 1.5;
    const double eps = p / ((gamma - 1.0) * rho), g = std::cbrt(rho * rho); // rho0 = 1: G = (rho/rho0)^{2/3} I
    const double v[D] = {0.3, -0.4};
    const LO n = 4; // cell i: shear if i & 1, heat if i & 2
    unilag::View<unilag::Material*> materials("materials", n);
    unilag::View<int*> cellMaterial("cellMaterial", n);
    Field state("state", n, S::ncomp), aux("aux", n, unilag::Aux::ncomp<P>()), stress("stress", n, 6);
    auto mh = Kokkos::create_mirror_view(materials);
    auto ch = Kokkos::create_mirror_view(cellMaterial);
    auto sh = Kokkos::create_mirror_view(state);
    for (LO i = 0; i < n; ++i)
    {
        unilag::Material m = unilag::fluidMaterial(unilag::gpr::idealGasEos(gamma, cv));
        if (i & 1)
        {
            m.strainLaw = unilag::StrainConstant;
            m.csh = csh;
            m.tau1 = 1.0;
        }
        if (i & 2)
        {
            m.heat = 1;
            m.alpha = alpha;
            m.tau2 = 1.0;
        }
        mh(i) = m;
        ch(i) = i;
        sh(i, S::omega) = 1.0 / rho;
        sh(i, S::energy) = eps; // an isotropic G and J = 0 carry no energy
        for (int d = 0; d < D; ++d)
        {
            sh(i, S::vel + d) = v[d];
            sh(i, S::energy) += 0.5 * v[d] * v[d];
            sh(i, S::J + d) = 0.0;
        }
        for (int c = 0; c < 6; ++c)
            sh(i, S::G + c) = c < 3 ? g : 0.0;
    }
    Kokkos::deep_copy(materials, mh);
    Kokkos::deep_copy(cellMaterial, ch);
    Kokkos::deep_copy(state, sh);
    unilag::computeEos<D, P>(state, cellMaterial, materials, aux, n, stress);
    auto ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), aux);
    for (LO i = 0; i < n; ++i)
    {
        double a2 = gamma * p / rho;
        if (i & 1)
            a2 += 4.0 / 3.0 * csh * csh;
        if (i & 2)
            a2 += alpha * alpha * (eps / cv) / (cv * rho * rho);
        const double a = std::sqrt(a2);
        EXPECT_NEAR(ah(i, unilag::Aux::pressure), p, 1e-14 * p) << i;
        EXPECT_NEAR(ah(i, unilag::Aux::sound), a, 1e-14 * a) << i;
        EXPECT_NEAR(ah(i, unilag::Aux::impedance), rho * a, 1e-14 * rho * a) << i;
    }
}
