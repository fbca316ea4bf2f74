// The floor on the subcell matrices at nodes of imposed traction (kernels/unilag/Geometry.hpp, freeSurfaceFloor;
// docs/gpr-model.md 2.2, Boundaries): smallestEigenvalueBelow against Jacobi's eigenvalues, well-shaped corners
// untouched, and on a stretched corner the zero-traction velocity M^-1 c bounded by 8 (it was unbounded).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "unilag/Hydro.hpp"
#include "unilag/Sym3.hpp"

namespace
{

using unilag::Mat;
using unilag::Vec;

template <int D> unilag::CellGeometry geometryOf(const Vec<D> (&x)[D + 1])
{
    unilag::CellGeometry g(1, D);
    unilag::storeGeometry<D>(g, 0, unilag::Simplex<D>(x));
    return g;
}

double jacobiSmallest(const Mat<3>& S)
{
    const unilag::gpr::Sym3 s{S.a[0][0], S.a[1][1], S.a[2][2], S.a[0][1], S.a[0][2], S.a[1][2]};
    return unilag::gpr::eigen(s).value[0];
}

} // namespace

// smallestEigenvalueBelow(S, ceiling) is lambda_min to round-off where lambda_min < ceiling, and >= ceiling otherwise.
TEST(FreeSurfaceFloor, SmallestEigenvalueIsJacobis)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int n = 0; n < 2000; ++n)
    {
        Mat<3> S = Mat<3>::zero();
        for (int k = 0; k < 3; ++k) // a Gram matrix of three random vectors, one of them short now and then
        {
            Vec<3> v{u(rng), u(rng), u(rng)};
            S.addOuter(k == 0 && n % 4 == 0 ? 1e-6 : 1.0, v);
        }
        const double exact = jacobiSmallest(S);
        const double scale = S.a[0][0] + S.a[1][1] + S.a[2][2];
        EXPECT_NEAR(unilag::smallestEigenvalueBelow<3>(S, 10.0 * scale), exact, 1e-12 * scale) << n;
        const double ceiling = 0.5 * scale * std::abs(u(rng));
        const double below = unilag::smallestEigenvalueBelow<3>(S, ceiling);
        if (exact < ceiling * (1.0 - 1e-9))
        {
            EXPECT_NEAR(below, exact, 1e-12 * scale) << n;
        }
        else if (exact > ceiling * (1.0 + 1e-9))
        {
            EXPECT_GE(below, ceiling) << n;
        }
    }
    Mat<2> T = Mat<2>::zero(); // 2D: [[2, 1], [1, 2]] has eigenvalues 1 and 3
    T.a[0][0] = T.a[1][1] = 2.0;
    T.a[0][1] = T.a[1][0] = 1.0;
    EXPECT_NEAR(unilag::smallestEigenvalueBelow<2>(T, 10.0), 1.0, 1e-15);
}

// An equilateral triangle and a regular tetrahedron: lambda_min(M_ik) = |c_k| / 2 and |c_k| / 3, above the floor.
TEST(FreeSurfaceFloor, WellShapedCornersAreUntouched)
{
    const Vec<2> tri[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.5, std::sqrt(0.75)}};
    const Vec<3> tet[4] = {{1.0, 1.0, 1.0}, {1.0, -1.0, -1.0}, {-1.0, 1.0, -1.0}, {-1.0, -1.0, 1.0}};
    const auto g2 = geometryOf<2>(tri);
    const auto g3 = geometryOf<3>(tet);
    for (int k = 0; k < 3; ++k)
    {
        const Mat<2> M = unilag::subcellMatrix<2>(g2.corner, 0, k);
        Mat<2> F = M;
        unilag::freeSurfaceFloor<2>(F, unilag::cornerInvNorm<2>(g2.corner, 0, k));
        EXPECT_NEAR(unilag::smallestEigenvalueBelow<2>(M, 1.0) * unilag::cornerInvNorm<2>(g2.corner, 0, k), 0.5,
                    1e-14);
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
                EXPECT_EQ(F.a[a][b], M.a[a][b]);
    }
    for (int k = 0; k < 4; ++k)
    {
        const Mat<3> M = unilag::subcellMatrix<3>(g3.corner, 0, k);
        Mat<3> F = M;
        unilag::freeSurfaceFloor<3>(F, unilag::cornerInvNorm<3>(g3.corner, 0, k));
        EXPECT_NEAR(jacobiSmallest(M) * unilag::cornerInvNorm<3>(g3.corner, 0, k), 1.0 / 3.0, 1e-13);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                EXPECT_EQ(F.a[a][b], M.a[a][b]);
    }
}

// The tip of a thin spike, the one cell at a free node: its zero-traction velocity relative to the cell is
// (p/z) M^-1 c, which grows as the spike's length over its width without the floor and stays <= 8 p/z with it.
TEST(FreeSurfaceFloor, BoundsTheSpikeTipsVelocity)
{
    for (double length : {1.0, 10.0, 100.0, 1000.0})
    {
        const Vec<2> x[3] = {{-length, 0.0}, {0.0, -0.01}, {0.0, 0.01}}; // the tip is corner 0
        const auto g = geometryOf<2>(x);
        const Vec<2> c = unilag::cornerVec<2>(g.corner, 0, 0);
        const Mat<2> M = unilag::subcellMatrix<2>(g.corner, 0, 0);
        Mat<2> F = M;
        unilag::freeSurfaceFloor<2>(F, unilag::cornerInvNorm<2>(g.corner, 0, 0));
        const double bare = unilag::norm(unilag::solve(M, c)), floored = unilag::norm(unilag::solve(F, c));
        if (length >= 10.0)
        {
            EXPECT_GT(bare, 0.2 * length / 0.01) << length; // about length / width: the runaway
        }
        EXPECT_LE(floored, 8.0 * (1.0 + 1e-9)) << length; // M^-1 c solved at condition number ~length^2
        EXPECT_GE(floored, 1.0) << length; // still moves out at least at p / z
    }
}
