// Simplex geometry (kernels/unilag/Geometry.hpp): corner vectors c_k = d|T|/dx_k, volumes, characteristic
// lengths and outward face area vectors, on random triangles and tetrahedra (well and badly shaped, all
// positively oriented), checked against independent long-double formulas; and computeGeometry over a View.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "unilag/Geometry.hpp"

namespace
{

using unilag::Simplex;
using unilag::Vec;

template <int D> using Nodes = std::array<Vec<D>, D + 1>;

template <int D> Simplex<D> simplexOf(const Nodes<D>& x)
{
    Vec<D> c[D + 1];
    std::copy(x.begin(), x.end(), c);
    return Simplex<D>(c);
}

// ---- independent reference formulas in long double ----

using LD = long double;

template <int D> std::array<LD, D> diff(const Vec<D>& a, const Vec<D>& b)
{
    std::array<LD, D> r;
    for (int d = 0; d < D; ++d)
        r[d] = LD(a[d]) - LD(b[d]);
    return r;
}

std::array<LD, 3> cross(const std::array<LD, 3>& u, const std::array<LD, 3>& w)
{
    return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
}

template <std::size_t N> LD length(const std::array<LD, N>& u)
{
    LD s = 0;
    for (LD v : u)
        s += v * v;
    return std::sqrt(s);
}

//! Signed volume: det[x1 - x0, ..., xD - x0] / D!.
template <int D> LD refVolume(const Nodes<D>& x)
{
    if constexpr (D == 2)
    {
        const auto a = diff<2>(x[1], x[0]), b = diff<2>(x[2], x[0]);
        return (a[0] * b[1] - a[1] * b[0]) / 2;
    }
    else
    {
        const auto a = diff<3>(x[1], x[0]), b = diff<3>(x[2], x[0]), c = diff<3>(x[3], x[0]);
        const auto n = cross(b, c);
        return (a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6;
    }
}

//! Measure of the face opposite node k (edge length in 2D, triangle area in 3D).
template <int D> LD refFaceArea(const Nodes<D>& x, int k)
{
    int f[D], n = 0;
    for (int j = 0; j <= D; ++j)
        if (j != k)
            f[n++] = j;
    if constexpr (D == 2)
        return length(diff<2>(x[f[1]], x[f[0]]));
    else
        return length(cross(diff<3>(x[f[1]], x[f[0]]), diff<3>(x[f[2]], x[f[0]]))) / 2;
}

//! Longest edge and largest coordinate: the round-off scale of the double computation.
template <int D> double magnitude(const Nodes<D>& x)
{
    double m = 0.0;
    for (int a = 0; a <= D; ++a)
        for (int b = 0; b <= D; ++b)
            m = std::max(m, double(length(diff<D>(x[a], x[b]))));
    for (const auto& p : x)
        for (int d = 0; d < D; ++d)
            m = std::max(m, std::abs(p[d]));
    return m;
}

// ---- random simplices ----

template <int D> Vec<D> randomPoint(std::mt19937& rng, double lo, double hi)
{
    std::uniform_real_distribution<double> u(lo, hi);
    Vec<D> p;
    for (int d = 0; d < D; ++d)
        p[d] = u(rng);
    return p;
}

//! Random rotation (orthonormalised Gaussian matrix, determinant +1).
template <int D> std::array<Vec<D>, D> randomRotation(std::mt19937& rng)
{
    std::normal_distribution<double> g;
    std::array<Vec<D>, D> q;
    for (int a = 0; a < D; ++a)
    {
        for (int d = 0; d < D; ++d)
            q[a][d] = g(rng);
        for (int b = 0; b < a; ++b)
            q[a] = q[a] - unilag::dot(q[a], q[b]) * q[b];
        q[a] = (1.0 / unilag::norm(q[a])) * q[a];
    }
    if constexpr (D == 2)
    {
        if (q[0][0] * q[1][1] - q[0][1] * q[1][0] < 0)
            q[1] = -1.0 * q[1];
    }
    else
    {
        const double det = q[0][0] * (q[1][1] * q[2][2] - q[1][2] * q[2][1]) -
                           q[0][1] * (q[1][0] * q[2][2] - q[1][2] * q[2][0]) +
                           q[0][2] * (q[1][0] * q[2][1] - q[1][1] * q[2][0]);
        if (det < 0)
            q[2] = -1.0 * q[2];
    }
    return q;
}

template <int D> Vec<D> apply(const std::array<Vec<D>, D>& q, const Vec<D>& p)
{
    Vec<D> r = Vec<D>::zero();
    for (int a = 0; a < D; ++a)
        r = r + p[a] * q[a];
    return r;
}

/*! A random positively oriented simplex; kind 0: well spread, 1: strongly anisotropic (flattened along random
 *  axes), 2: flat cap (last node almost on the opposite face), 3: needle (D nodes in a tiny ball, one far),
 *  4: the 3D sliver (four nearly coplanar nodes; a flat cap in 2D). Random scale 1e-2..1e2 and an offset from
 *  the origin of up to twice the size. */
template <int D> Nodes<D> randomSimplex(std::mt19937& rng, int kind)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (;;)
    {
        Nodes<D> x;
        switch (kind)
        {
        case 0:
            for (auto& p : x)
                p = randomPoint<D>(rng, -1.0, 1.0);
            break;
        case 1:
        {
            for (auto& p : x)
                p = randomPoint<D>(rng, -1.0, 1.0);
            Vec<D> s;
            for (int d = 0; d < D; ++d)
                s[d] = std::pow(10.0, -3.0 * u(rng));
            const auto q = randomRotation<D>(rng);
            for (auto& p : x)
            {
                for (int d = 0; d < D; ++d)
                    p[d] *= s[d];
                p = apply<D>(q, p);
            }
            break;
        }
        case 2:
        case 4:
            if (D == 3 && kind == 4)
            {
                const double delta = std::pow(10.0, -1.0 - 3.0 * u(rng));
                const double pts[4][3] = {{1, 0, delta}, {-1, 0, delta}, {0, 1, -delta}, {0, -1, -delta}};
                const auto q = randomRotation<D>(rng);
                for (int k = 0; k < 4; ++k)
                {
                    Vec<D> p;
                    for (int d = 0; d < D; ++d)
                        p[d] = pts[k][d];
                    x[k] = apply<D>(q, p);
                }
            }
            else
            {
                // last node = random convex combination of the others, lifted by a tiny amount off their face
                Vec<D> c = Vec<D>::zero();
                double wsum = 0.0;
                for (int k = 0; k < D; ++k)
                {
                    x[k] = randomPoint<D>(rng, -1.0, 1.0);
                    const double w = u(rng) + 0.05;
                    c = c + w * x[k];
                    wsum += w;
                }
                x[D] = (1.0 / wsum) * c + std::pow(10.0, -1.0 - 3.0 * u(rng)) * randomPoint<D>(rng, -1.0, 1.0);
            }
            break;
        default:
        {
            const double r = std::pow(10.0, -1.0 - 2.0 * u(rng));
            for (int k = 0; k < D; ++k)
                x[k] = r * randomPoint<D>(rng, -1.0, 1.0);
            x[D] = randomPoint<D>(rng, -1.0, 1.0);
            break;
        }
        }
        const double scale = std::pow(10.0, -2.0 + 4.0 * u(rng));
        const Vec<D> offset = randomPoint<D>(rng, -2.0, 2.0);
        for (auto& p : x)
            p = scale * (p + offset);
        if (refVolume<D>(x) < 0)
            std::swap(x[0], x[1]);
        // keep shapes that are bad but not degenerate to the double round-off
        if (double(refVolume<D>(x)) > 1e-7 * std::pow(magnitude<D>(x), D))
            return x;
    }
}

template <int D> std::vector<Nodes<D>> randomSimplices(unsigned seed, int count)
{
    std::mt19937 rng(seed);
    std::vector<Nodes<D>> all;
    const int kinds = D == 2 ? 4 : 5;
    for (int n = 0; n < count; ++n)
        all.push_back(randomSimplex<D>(rng, n % kinds));
    return all;
}

constexpr int kCount = 400;

template <class Dim> class SimplexTest : public ::testing::Test
{
};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(SimplexTest, Dims);

} // namespace

TYPED_TEST(SimplexTest, VolumeMatchesDeterminantAndIsPositive)
{
    constexpr int D = TypeParam::value;
    for (const auto& x : randomSimplices<D>(11, kCount))
    {
        const auto s = simplexOf<D>(x);
        const double mag = magnitude<D>(x);
        ASSERT_GT(s.volume, 0.0);
        EXPECT_NEAR(s.volume, double(refVolume<D>(x)), 1e-14 * std::pow(mag, D));
    }
}

TYPED_TEST(SimplexTest, CornerVectorsSumToZero)
{
    constexpr int D = TypeParam::value;
    for (const auto& x : randomSimplices<D>(12, kCount))
    {
        const auto s = simplexOf<D>(x);
        Vec<D> sum = Vec<D>::zero();
        for (int k = 0; k <= D; ++k)
            sum = sum + s.c[k];
        // round-off scale of a corner vector: (largest edge or coordinate)^(D-1), as the edge differences
        // carry errors relative to the coordinates
        const double tol = 1e-14 * std::pow(magnitude<D>(x), D - 1);
        for (int d = 0; d < D; ++d)
            EXPECT_NEAR(sum[d], 0.0, tol);
    }
}

TYPED_TEST(SimplexTest, CornerVectorsReproduceVolume)
{
    constexpr int D = TypeParam::value;
    for (const auto& x : randomSimplices<D>(13, kCount))
    {
        const auto s = simplexOf<D>(x);
        double v = 0.0, size = 0.0;
        for (int k = 0; k <= D; ++k)
        {
            v += unilag::dot(s.c[k], x[k]) / D;
            size += std::abs(unilag::dot(s.c[k], x[k])) / D;
        }
        EXPECT_NEAR(v, double(refVolume<D>(x)), 1e-14 * size + 1e-14 * std::pow(magnitude<D>(x), D));
    }
}

TYPED_TEST(SimplexTest, CornerVectorIsVolumeGradient)
{
    constexpr int D = TypeParam::value;
    for (const auto& x : randomSimplices<D>(14, kCount))
    {
        const auto s = simplexOf<D>(x);
        double cmax = 0.0;
        for (int k = 0; k <= D; ++k)
            cmax = std::max(cmax, unilag::norm(s.c[k]));
        // |T| is affine in each node's position, so a central difference has no truncation error: a large
        // step keeps the round-off of the differenced volumes small.
        const double h = 1e-3 * magnitude<D>(x);
        for (int k = 0; k <= D; ++k)
            for (int d = 0; d < D; ++d)
            {
                Nodes<D> xp = x, xm = x;
                xp[k][d] += h;
                xm[k][d] -= h;
                const double fd = (simplexOf<D>(xp).volume - simplexOf<D>(xm).volume) / (2.0 * h);
                EXPECT_NEAR(s.c[k][d], fd, 1e-7 * std::abs(fd) + 1e-10 * cmax) << "node " << k << " dir " << d;
            }
    }
}

TYPED_TEST(SimplexTest, TranslationInvariant)
{
    constexpr int D = TypeParam::value;
    std::mt19937 rng(15);
    for (const auto& x : randomSimplices<D>(15, kCount))
    {
        const auto s = simplexOf<D>(x);
        const double mag = magnitude<D>(x);
        const Vec<D> t = mag * randomPoint<D>(rng, -2.0, 2.0);
        Nodes<D> y = x;
        for (auto& p : y)
            p = p + t;
        const auto st = simplexOf<D>(y);
        const double magT = magnitude<D>(y);
        EXPECT_NEAR(st.volume, s.volume, 1e-14 * std::pow(magT, D));
        for (int k = 0; k <= D; ++k)
            for (int d = 0; d < D; ++d)
                EXPECT_NEAR(st.c[k][d], s.c[k][d], 1e-14 * std::pow(magT, D - 1));
    }
}

TYPED_TEST(SimplexTest, CharLengthIsInscribedDiameter)
{
    constexpr int D = TypeParam::value;
    for (const auto& x : randomSimplices<D>(16, kCount))
    {
        const auto s = simplexOf<D>(x);
        const LD v = refVolume<D>(x);
        LD boundary = 0; // perimeter (2D) or total face area (3D)
        for (int k = 0; k <= D; ++k)
            boundary += refFaceArea<D>(x, k);
        const double expected = double((D == 2 ? 4 : 6) * v / boundary);
        // relative round-off of the double volume grows as the simplex flattens
        const double rel = 1e-14 * std::pow(magnitude<D>(x), D) / double(v) + 1e-14;
        EXPECT_NEAR(s.charLength(), expected, rel * expected);
    }
}

TYPED_TEST(SimplexTest, FaceAreaVectorsPointOutward)
{
    constexpr int D = TypeParam::value;
    for (const auto& x : randomSimplices<D>(17, kCount))
    {
        const auto s = simplexOf<D>(x);
        const double mag = magnitude<D>(x);
        const double v = double(refVolume<D>(x));
        for (int k = 0; k <= D; ++k)
        {
            const Vec<D> n = (-double(D)) * s.c[k]; // claimed outward area vector of the face opposite k
            Vec<D> centroid = Vec<D>::zero();
            for (int j = 0; j <= D; ++j)
                if (j != k)
                {
                    centroid = centroid + (1.0 / D) * x[j];
                    // normal to the face: orthogonal to its edges
                    for (int i = j + 1; i <= D; ++i)
                        if (i != k)
                        {
                            EXPECT_NEAR(unilag::dot(n, x[i] - x[j]), 0.0, 1e-14 * std::pow(mag, D));
                        }
                }
            // magnitude = face measure
            const double area = double(refFaceArea<D>(x, k));
            EXPECT_NEAR(unilag::norm(n), area, 1e-14 * std::pow(mag, D - 1)) << "face " << k;
            // pointing away from node k: n . (face - x_k) = D |T| > 0 (pyramid volume = base * height / D)
            const double away = unilag::dot(n, centroid - x[k]);
            EXPECT_GT(away, 0.0) << "face " << k;
            EXPECT_NEAR(away, D * v, 1e-13 * std::pow(mag, D)) << "face " << k;
        }
    }
}

// ---- computeGeometry over a View of cells ----

namespace
{

//! Cells with their own nodes (cell i uses nodes i*NV .. i*NV+D), coordinates and connectivity in Views.
template <int D> struct CellSoup
{
    static constexpr int NV = D + 1;
    std::vector<Nodes<D>> simplices;
    Kokkos::View<unilag::LO**, Kokkos::LayoutLeft, unilag::MemSpace> cellNodes;
    unilag::Field x;

    explicit CellSoup(const std::vector<Nodes<D>>& s)
        : simplices(s), cellNodes("cellNodes", s.size(), NV), x("x", s.size() * NV, D)
    {
        auto cn = Kokkos::create_mirror_view(cellNodes);
        auto xh = Kokkos::create_mirror_view(x);
        for (std::size_t i = 0; i < s.size(); ++i)
            for (int k = 0; k < NV; ++k)
            {
                cn(i, k) = unilag::LO(i * NV + k);
                for (int d = 0; d < D; ++d)
                    xh(i * NV + k, d) = s[i][k][d];
            }
        Kokkos::deep_copy(cellNodes, cn);
        Kokkos::deep_copy(x, xh);
    }

    unilag::MeshView<D> view() const
    {
        unilag::MeshView<D> m;
        m.cellNodes = cellNodes;
        m.nCells = m.nOwnedCells = unilag::LO(simplices.size());
        m.nNodes = m.nOwnedNodes = unilag::LO(simplices.size() * NV);
        return m;
    }
};

} // namespace

TYPED_TEST(SimplexTest, ComputeGeometryMatchesSimplexPerCell)
{
    constexpr int D = TypeParam::value;
    const auto simplices = randomSimplices<D>(18, 120);
    CellSoup<D> soup(simplices);
    const unilag::LO n = unilag::LO(simplices.size());
    unilag::CellGeometry g(n, D);
    const double vmin = unilag::computeGeometry<D>(soup.view(), soup.x, g, n);

    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), g.volume);
    auto len = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), g.length);
    auto cor = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), g.corner);
    double expectedMin = simplexOf<D>(simplices[0]).volume;
    for (unilag::LO i = 0; i < n; ++i)
    {
        const auto s = simplexOf<D>(simplices[i]);
        expectedMin = std::min(expectedMin, s.volume);
        EXPECT_DOUBLE_EQ(vol(i), s.volume) << "cell " << i;
        EXPECT_DOUBLE_EQ(len(i), s.charLength()) << "cell " << i;
        for (int k = 0; k <= D; ++k)
        {
            for (int d = 0; d < D; ++d)
                EXPECT_DOUBLE_EQ(cor(i, k * D + d), s.c[k][d]) << "cell " << i << " corner " << k;
            // the subcell matrices' weight beside it (cornerInvNorm), the very bits 1 / |c_k| gives
            EXPECT_EQ(cor(i, (D + 1) * D + k), 1.0 / unilag::norm(s.c[k])) << "cell " << i << " corner " << k;
        }
    }
    EXPECT_GT(vmin, 0.0);
    EXPECT_EQ(vmin, expectedMin);
}

TYPED_TEST(SimplexTest, ComputeGeometryFlagsInvertedCell)
{
    constexpr int D = TypeParam::value;
    const auto simplices = randomSimplices<D>(19, 60);
    CellSoup<D> soup(simplices);
    const unilag::LO n = unilag::LO(simplices.size()), bad = 37;
    // invert one cell by swapping two of its nodes
    auto cn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), soup.cellNodes);
    std::swap(cn(bad, 0), cn(bad, 1));
    Kokkos::deep_copy(soup.cellNodes, cn);

    unilag::CellGeometry g(n, D);
    const double vmin = unilag::computeGeometry<D>(soup.view(), soup.x, g, n);
    const auto s = simplexOf<D>(simplices[bad]);
    const double mag = magnitude<D>(simplices[bad]);
    EXPECT_LT(vmin, 0.0);
    EXPECT_NEAR(vmin, -s.volume, 1e-14 * std::pow(mag, D));

    // the corner vector of each node is the gradient of the (now negative) volume: it flips sign
    auto vol = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), g.volume);
    auto cor = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), g.corner);
    EXPECT_EQ(vol(bad), vmin);
    for (int k = 0; k <= D; ++k)
    {
        const int old = k == 0 ? 1 : (k == 1 ? 0 : k); // new local node k was old local node `old`
        for (int d = 0; d < D; ++d)
            EXPECT_NEAR(cor(bad, k * D + d), -s.c[old][d], 1e-14 * std::pow(mag, D - 1));
    }
    for (unilag::LO i = 0; i < n; ++i)
        if (i != bad)
        {
            EXPECT_GT(vol(i), 0.0) << "cell " << i;
        }
}

// ---- orthonormalBasis: the slip-plane normals of the nodal solver and of the first lagged node velocity ----

TEST(OrthonormalBasis, NonOrthogonalPlanesSpanTheirNormals)
{
    // Two walls at 60 degrees and a third parallel to the first (counts once): the basis spans both normals, is
    // orthonormal, and removing it from a vector leaves no component along either wall's normal.
    const double c = std::cos(M_PI / 3.0), s = std::sin(M_PI / 3.0);
    const Vec<3> u[3] = {{{2.0, 0.0, 0.0}}, {{c, s, 0.0}}, {{-5.0, 0.0, 0.0}}};
    Vec<3> Q[3];
    const int nq = unilag::orthonormalBasis<3>(u, 3, Q);
    ASSERT_EQ(nq, 2);
    for (int a = 0; a < nq; ++a)
        for (int b = 0; b < nq; ++b)
            EXPECT_NEAR(unilag::dot(Q[a], Q[b]), a == b ? 1.0 : 0.0, 1e-15);
    Vec<3> v = {{0.3, -1.7, 2.5}};
    for (int a = 0; a < nq; ++a)
        v = v - unilag::dot(v, Q[a]) * Q[a];
    for (const Vec<3>& n : u)
        EXPECT_NEAR(unilag::dot(v, n), 0.0, 1e-14);
    EXPECT_NEAR(v[2], 2.5, 1e-15); // the direction along both walls is kept
    // Plane by plane projection (the earlier first lagged velocity) leaves part of the first normal:
    Vec<3> w = {{0.3, -1.7, 2.5}};
    for (int p = 0; p < 2; ++p)
        w = w - unilag::dot(w, (1.0 / unilag::norm(u[p])) * u[p]) * ((1.0 / unilag::norm(u[p])) * u[p]);
    EXPECT_GT(std::abs(unilag::dot(w, u[0])), 0.1);
}

TEST(OrthonormalBasis, AxisPlanesAreCopiedExactly)
{
    // The quadrant's and octant's planes: the basis is the unit normals themselves, bit for bit.
    const Vec<3> u[3] = {{{0.0, -0.7, 0.0}}, {{0.3, 0.0, 0.0}}, {{0.0, 0.0, -2.0}}};
    Vec<3> Q[3];
    ASSERT_EQ(unilag::orthonormalBasis<3>(u, 3, Q), 3);
    EXPECT_EQ(Q[0][1], -1.0);
    EXPECT_EQ(Q[1][0], 1.0);
    EXPECT_EQ(Q[2][2], -1.0);
    EXPECT_EQ(Q[0][0], 0.0);
    EXPECT_EQ(Q[1][1], 0.0);
}
