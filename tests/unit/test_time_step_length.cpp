// The time step's length (kernels/unilag/Geometry.hpp, timeStepLength; docs/gpr-model.md 1.5): the insphere
// diameter, or the relaxation length 4|T| / lambda_max(sum_k M_ik) where that is smaller, so that the subcell
// forces' relaxation of the cell velocity stays within lambda dt <= 4 CFL. Checked against the Jacobi
// eigen-decomposition of the sum of the subcell matrices (Hydro.hpp) built here corner by corner.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <type_traits>

#include "unilag/Hydro.hpp"
#include "unilag/Sym3.hpp"

namespace
{

using unilag::Mat;
using unilag::Vec;

template <int D> Vec<D> point(std::initializer_list<double> values)
{
    Vec<D> p;
    int d = 0;
    for (double v : values)
        p[d++] = v;
    return p;
}

// the cell's length and lambda_max(sum_k M_ik) / |T| (the relaxation rate per unit impedance and density)
template <int D> std::pair<double, double> lengthAndRate(const Vec<D> (&x)[D + 1])
{
    const unilag::Simplex<D> s(x);
    unilag::CellGeometry g(1, D);
    unilag::storeGeometry<D>(g, 0, s);
    const double h = unilag::timeStepLength<D>(g.corner, 0, g.length(0), g.volume(0));
    Mat<D> sum = Mat<D>::zero();
    for (int k = 0; k < D + 1; ++k)
    {
        const Mat<D> M = unilag::subcellMatrix<D>(g.corner, 0, k);
        for (int a = 0; a < D; ++a)
            for (int b = 0; b < D; ++b)
                sum.a[a][b] += M.a[a][b];
    }
    unilag::gpr::Sym3 S{sum.a[0][0], sum.a[1][1], D == 3 ? sum.a[D - 1][D - 1] : 0.0, sum.a[0][1],
                        D == 3 ? sum.a[0][D - 1] : 0.0, D == 3 ? sum.a[1][D - 1] : 0.0};
    const double lambda = unilag::gpr::eigen(S).value[2];
    return {h, lambda / s.volume};
}

} // namespace

// largestEigenvalueAbove(S, 0) is lambda_max to round-off (and never below it); with a floor, it says only whether
// lambda_max exceeds it.
TEST(TimeStepLength, LargestEigenvalueIsJacobis)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int n = 0; n < 3000; ++n)
    {
        // positive semi-definite: random Gram matrices (n % 3 == 0), and with repeated eigenvalues: a multiple of I
        // plus a rank-one term (1: the rank-one eigenvalue on top, simple), of I alone (2)
        Mat<3> A = Mat<3>::zero();
        const Vec<3> w = point<3>({u(rng), u(rng), u(rng)});
        Vec<3> rows[3];
        for (auto& r : rows)
            r = point<3>({u(rng), u(rng), u(rng)});
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                A.a[a][b] = n % 3 == 0 ? unilag::dot(rows[a], rows[b])
                                       : (a == b ? 2.0 : 0.0) + (n % 3 == 1 ? w[a] * w[b] : 0.0);
        const unilag::gpr::Sym3 S{A.a[0][0], A.a[1][1], A.a[2][2], A.a[0][1], A.a[0][2], A.a[1][2]};
        const double exact = unilag::gpr::eigen(S).value[2];
        const double bound = unilag::largestEigenvalueAbove(A, 0.0);
        // a root of multiplicity m moves by eps^(1/m) with the polynomial's coefficients: 2I's triple root to 6e-6
        const double tolerance = n % 3 == 2 ? 1e-5 : 1e-10;
        EXPECT_NEAR(bound, exact, tolerance * exact) << n;
        const double floor = (0.5 + 0.5 * std::abs(u(rng))) * (A.a[0][0] + A.a[1][1] + A.a[2][2]);
        const double above = unilag::largestEigenvalueAbove(A, floor);
        if (exact > floor * (1.0 + tolerance))
        {
            EXPECT_NEAR(above, exact, tolerance * exact) << n;
        }
        else if (exact < floor * (1.0 - tolerance))
        {
            EXPECT_EQ(above, floor) << n;
        }
    }
}

// Every triangle's relaxation length is at least its incircle diameter (lambda_max <= 2 sum |c_k|), however flat the
// triangle: 2D takes the incircle diameter without the eigenvalue.
TEST(TimeStepLength, TrianglesNeverNeedTheRelaxationLength)
{
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int n = 0; n < 2000; ++n)
    {
        const double flat = std::pow(10.0, -4.0 * u(rng));
        const Vec<2> x[3] = {point<2>({0.0, 0.0}), point<2>({1.0, 0.0}), point<2>({u(rng), flat * (0.01 + u(rng))})};
        const unilag::Simplex<2> s(x);
        const auto [h, rate] = lengthAndRate<2>(x);
        EXPECT_EQ(h, s.charLength()) << n;
        // lambda dt <= 4 CFL in 2D too: the relaxation length 4 |T| / lambda_max is at least h
        EXPECT_LE(rate * h, 4.0 * (1.0 + 1e-12)) << n;
    }
}

TEST(TimeStepLength, RegularTetrahedronKeepsTheInsphereDiameter)
{
    const Vec<3> x[4] = {point<3>({1.0, -1.0, -1.0}), point<3>({1.0, 1.0, 1.0}), point<3>({-1.0, 1.0, -1.0}),
                         point<3>({-1.0, -1.0, 1.0})};
    const unilag::Simplex<3> s(x);
    ASSERT_GT(s.volume, 0.0);
    const auto [h, rate] = lengthAndRate<3>(x);
    EXPECT_EQ(h, s.charLength());
    EXPECT_NEAR(rate * h, 2.0, 1e-13); // lambda dt = 2 CFL on a regular cell
}

// Flat tetrahedra (gmsh's slivers, split prisms): the relaxation length decides, and it keeps lambda dt <= 4 CFL,
// which the insphere diameter alone lets reach 6 CFL.
TEST(TimeStepLength, FlatTetrahedraBoundTheRelaxationRate)
{
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int bound = 0;
    for (int n = 0; n < 2000; ++n)
    {
        const double flat = std::pow(10.0, -3.0 * u(rng));
        const Vec<3> x[4] = {point<3>({0.0, 0.0, 0.0}), point<3>({1.0, 0.0, 0.0}),
                             point<3>({u(rng), 0.2 + u(rng), 0.0}),
                             point<3>({u(rng), u(rng), flat * (0.05 + u(rng))})};
        const unilag::Simplex<3> s(x);
        const auto [h, rate] = lengthAndRate<3>(x);
        EXPECT_LE(h, s.charLength()) << n;
        EXPECT_LE(rate * h, 4.0 * (1.0 + 1e-12)) << n;
        if (h < s.charLength())
        {
            ++bound;
            EXPECT_NEAR(rate * h, 4.0, 1e-11) << n;
        }
    }
    EXPECT_GT(bound, 1000); // most of these shapes are flat enough to be bound
}

// shapeQuality (the summary's min_shape_quality): 1 on the regular triangle and tetrahedron at any size, the
// insphere over the longest edge on others, towards 0 on flat cells.
TEST(TimeStepLength, ShapeQualityIsOneOnRegularSimplices)
{
    auto quality = [](const auto& x) {
        constexpr int D = std::extent<std::remove_reference_t<decltype(x)>>::value - 1;
        const unilag::Simplex<D> s(x);
        return unilag::shapeQuality<D>(x, s.charLength());
    };
    const double r3 = std::sqrt(3.0);
    const Vec<2> triangle[3] = {point<2>({0, 0}), point<2>({2, 0}), point<2>({1, r3})};
    EXPECT_NEAR(quality(triangle), 1.0, 1e-14);
    const Vec<3> tet[4] = {point<3>({1, 1, 1}), point<3>({-1, 1, -1}), point<3>({1, -1, -1}), point<3>({-1, -1, 1})};
    EXPECT_NEAR(quality(tet), 1.0, 1e-14);
    // the right isosceles triangle: insphere diameter 2 - sqrt(2) over sqrt(2) / sqrt(3) (the regular triangle's
    // with edge sqrt(2))
    const Vec<2> right[3] = {point<2>({0, 0}), point<2>({1, 0}), point<2>({0, 1})};
    EXPECT_NEAR(quality(right), (2.0 - std::sqrt(2.0)) * r3 / std::sqrt(2.0), 1e-14);
    // a sliver: two crossed edges of length 2 pressed to 2e-3 apart; its quality goes with that gap
    const Vec<3> sliver[4] = {point<3>({1, 0, 1e-3}), point<3>({-1, 0, 1e-3}), point<3>({0, 1, -1e-3}),
                              point<3>({0, -1, -1e-3})};
    const double q = quality(sliver);
    EXPECT_GT(q, 1e-3);
    EXPECT_LT(q, 5e-3);
}
