// The second-order corner load (kernels/unilag/Hydro.hpp, cornerLoad; docs/gpr-model.md 2.5) on distorted simplex
// meshes: for a linear traction T = p I - sigma and a linear velocity, the loads of a cell's corners give its net
// force, integral of T n = |T_i| div T, and their work on the node velocities is the exact flux, integral of v . T n =
// |T_i| (div T . v(x_i) + T(x_i) : grad v). The lumped load T(x_k) c_k has the same net force but not that work
// (an O(h^3) error per cell, the lumped scheme's entropy noise on smooth flows; scheme.corner_load: lumped, the
// default, keeps it bit for bit); the test prints its size.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "HostMesh.hpp"
#include "unilag/Hydro.hpp"

namespace
{

using unilag::Field;
using unilag::LO;
using Strain = unilag::Physics<true, false, false>;

constexpr double kGradP[3] = {0.3, -0.7, 0.45};
constexpr double kA[3][3] = {{0.2, -0.5, 0.1}, {0.4, 0.3, -0.2}, {-0.1, 0.25, 0.6}}; // grad v

//! The linear shear stress sigma(x) = S0 + x . dS as Sym3 entries xx yy zz xy xz yz, and their gradients.
constexpr double kS0[6] = {0.5, -0.2, 0.1, 0.3, -0.15, 0.05};
constexpr double kDS[6][3] = {{0.2, 0.1, -0.3}, {-0.4, 0.25, 0.1}, {0.15, -0.05, 0.2},
                              {0.3, -0.2, 0.05}, {-0.1, 0.35, 0.2}, {0.05, 0.1, -0.25}};
constexpr int kComp[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};

template <int D, class P> void checkCornerLoad(unilag_test::HostMesh<D> h, bool strain)
{
    using R = unilag::ReconLayout<D, P>;
    constexpr int NV = D + 1;
    ASSERT_NO_FATAL_FAILURE(unilag_test::connect<D>(h, [](int) { return 0; }));
    const LO nCells = h.nCells();
    Field x("x", h.nNodes(), D), grad("grad", nCells, R::ncomp), out("out", nCells, D + 3);
    const unilag::MeshView<D> mesh = unilag_test::deviceMesh<D>(h, x);
    unilag::CellGeometry geom(nCells, D);
    ASSERT_GT(unilag::computeGeometry<D>(mesh, x, geom, nCells), 0.0) << "the distorted mesh is tangled";
    const unilag::Reconstruction<D> rec{grad, x, geom.centroid, geom.volume, true};
    const unilag::Reconstruction<D> lumpedRec{grad, x, geom.centroid, geom.volume, false};
    auto centroid = geom.centroid;
    auto corner = geom.corner;
    auto volume = geom.volume;

    // per cell: net force (D), work on v(x_r) = A x_r, and the lumped rule's work
    auto loads = KOKKOS_LAMBDA(const LO i)
    {
        for (int a = 0; a < D; ++a)
        {
            grad(i, R::pressure * D + a) = kGradP[a];
            if constexpr (P::strain)
                for (int c = 0; c < 6; ++c)
                    grad(i, (R::stress + c) * D + a) = kDS[c][a];
        }
        double pi = 1.0;
        unilag::gpr::Sym3 si{kS0[0], kS0[1], kS0[2], kS0[3], kS0[4], kS0[5]};
        for (int a = 0; a < D; ++a)
        {
            pi += kGradP[a] * centroid(i, a);
            si = si + centroid(i, a) * unilag::gpr::Sym3{kDS[0][a], kDS[1][a], kDS[2][a], kDS[3][a], kDS[4][a],
                                                          kDS[5][a]};
        }
        unilag::Vec<D> net = unilag::Vec<D>::zero();
        double work = 0.0, lumped = 0.0, lumpMismatch = 0.0;
        for (int k = 0; k < NV; ++k)
        {
            const LO r = mesh.cellNodes(i, k);
            const unilag::Vec<D> dx = rec.offset(i, r);
            const double pk = pi + rec.delta(i, R::pressure, dx);
            unilag::gpr::Sym3 sk = si;
            if constexpr (P::strain)
                sk = si + unilag::gpr::Sym3{rec.delta(i, R::stress + 0, dx), rec.delta(i, R::stress + 1, dx),
                                            rec.delta(i, R::stress + 2, dx), rec.delta(i, R::stress + 3, dx),
                                            rec.delta(i, R::stress + 4, dx), rec.delta(i, R::stress + 5, dx)};
            unilag::Vec<D> vr;
            for (int a = 0; a < D; ++a)
            {
                vr[a] = 0.0;
                for (int b = 0; b < D; ++b)
                    vr[a] += kA[a][b] * x(r, b);
            }
            const unilag::Vec<D> load = unilag::cornerLoad<D, P>(mesh, corner, rec, i, k, pk, sk);
            const unilag::Vec<D> ck = unilag::cornerVec<D>(corner, i, k);
            const unilag::Vec<D> lump = unilag::cornerLoad<D, P>(mesh, corner, lumpedRec, i, k, pk, sk);
            unilag::Vec<D> byHand = pk * ck; // the lumped load: the corner values on the corner vector
            if constexpr (P::strain)
                byHand = byHand - unilag::stressTimes<D>(sk, ck);
            for (int a = 0; a < D; ++a)
                lumpMismatch = Kokkos::Experimental::fmax(lumpMismatch,
                                                          Kokkos::Experimental::fabs(lump[a] - byHand[a]));
            net = net + load;
            work += unilag::dot(load, vr);
            lumped += unilag::dot(lump, vr);
        }
        // exact: |T| div T and |T| (div T . v(x_i) + T(x_i) : A), T = p I - sigma
        double exactWork = 0.0;
        for (int a = 0; a < D; ++a)
        {
            double divT = kGradP[a], va = 0.0;
            for (int b = 0; b < D; ++b)
            {
                if constexpr (P::strain)
                    divT -= kDS[kComp[a][b]][b];
                va += kA[a][b] * centroid(i, b);
                const double Tab = (a == b ? pi : 0.0) - (P::strain ? si(a, b) : 0.0);
                exactWork += volume(i) * Tab * kA[a][b];
            }
            exactWork += volume(i) * divT * va;
            out(i, a) = net[a] - volume(i) * divT;
        }
        out(i, D) = work - exactWork;
        out(i, D + 1) = lumped - exactWork;
        out(i, D + 2) = lumpMismatch;
    };
    Kokkos::parallel_for("test::corner_load", nCells, loads);
    auto o = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), volume);
    double worstNet = 0.0, worstWork = 0.0, worstLumped = 0.0;
    for (LO i = 0; i < nCells; ++i)
    {
        for (int a = 0; a < D; ++a)
            worstNet = std::fmax(worstNet, std::fabs(o(i, a)) / vol(i));
        worstWork = std::fmax(worstWork, std::fabs(o(i, D)) / vol(i));
        worstLumped = std::fmax(worstLumped, std::fabs(o(i, D + 1)) / vol(i));
        EXPECT_EQ(o(i, D + 2), 0.0) << "scheme.corner_load: lumped is not (p I - sigma)(x_k) c_k, cell " << i;
    }
    std::printf("%dD%s: per unit volume, net force error %.1e, work error %.1e (lumped corner values: %.1e)\n", D,
                strain ? " with shear stress" : "", worstNet, worstWork, worstLumped);
    EXPECT_LT(worstNet, 1e-12);
    EXPECT_LT(worstWork, 1e-12);
    EXPECT_GT(worstLumped, 1e-4); // the lumped rule's error: a test of this test, the fields are not degenerate
}

} // namespace

TEST(CornerLoad, LinearTractionWorkExact2D)
{
    checkCornerLoad<2, unilag::PhysicsHydro>(unilag_test::squareMesh(8, 0.3, 41), false);
}

TEST(CornerLoad, LinearTractionWorkExact3D)
{
    checkCornerLoad<3, unilag::PhysicsHydro>(unilag_test::cubeMesh(3, 0.2, 42), false);
}

TEST(CornerLoad, LinearStressWorkExact2D)
{
    checkCornerLoad<2, Strain>(unilag_test::squareMesh(8, 0.3, 43), true);
}

TEST(CornerLoad, LinearStressWorkExact3D)
{
    checkCornerLoad<3, Strain>(unilag_test::cubeMesh(3, 0.2, 44), true);
}
