// The entropy filter (kernels/unilag/EntropyFilter.hpp) on hand-built distorted simplex meshes, without MPI maps:
// a linear eps is left alone, a random one exchanges energy conservatively and only from hotter to colder cells,
// and shocked cells neither give nor take.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "HostMesh.hpp"
#include "unilag/EntropyFilter.hpp"

namespace
{

using unilag::Aux;
using unilag::Field;
using unilag::LO;
using PH = unilag::PhysicsHydro;
using unilag_test::HostMesh;

template <int D> struct Filter
{
    using S = unilag::StateLayout<D, PH>;
    static constexpr int NV = D + 1;

    HostMesh<D> h;
    LO nCells;
    unilag::MeshView<D> mesh;
    unilag::BoundaryView bc;
    Field x, state, aux, grad;
    unilag::View<double*> mass;
    unilag::CellGeometry geom;

    explicit Filter(HostMesh<D> hm)
        : h(std::move(hm)), nCells(h.nCells()), x("x", h.nNodes(), D), state("state", nCells, S::ncomp),
          aux("aux", nCells, Aux::ncomp<PH>()), grad("grad", nCells, D), mass("mass", nCells), geom(nCells, D)
    {
        unilag_test::connect<D>(h, unilag_test::wallGroup);
        mesh = unilag_test::deviceMesh<D>(h, x);
        unilag::View<int*> type("type", 2 * D); // free boundaries: no mirror images, the plain least squares
        Kokkos::deep_copy(type, int(unilag::BcFree));
        bc.type = type;
        EXPECT_GT(unilag::computeGeometry<D>(mesh, x, geom, nCells), 0.0) << "the distorted mesh is tangled";
    }

    //! eps(i, centroid), density 1 + 0.3 u, sound speed 1, signal speed (shocked: 2, else 1); mass = rho |T|.
    template <class Eps, class Shocked> void initialize(const Eps& eps, const Shocked& shocked, unsigned seed)
    {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom.centroid);
        auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom.volume);
        auto sh = Kokkos::create_mirror_view(state);
        auto ah = Kokkos::create_mirror_view(aux);
        auto mh = Kokkos::create_mirror_view(mass);
        Kokkos::deep_copy(sh, 0.0);
        Kokkos::deep_copy(ah, 0.0);
        for (LO i = 0; i < nCells; ++i)
        {
            double xc[3] = {0.0, 0.0, 0.0};
            for (int d = 0; d < D; ++d)
                xc[d] = c(i, d);
            const double rho = 1.0 + 0.3 * u(rng);
            sh(i, S::omega) = 1.0 / rho;
            const double e = eps(i, xc);
            sh(i, S::energy) = e;
            ah(i, Aux::eps) = e;
            ah(i, Aux::sound) = 1.0;
            ah(i, Aux::signal) = shocked(i) ? 2.0 : 1.0;
            mh(i) = rho * v(i);
        }
        Kokkos::deep_copy(state, sh);
        Kokkos::deep_copy(aux, ah);
        Kokkos::deep_copy(mass, mh);
    }

    //! One filter step of dt with coefficient C; the energy change of every cell on the host.
    std::vector<double> run(double dt, double coefficient)
    {
        unilag::epsGradientFromFaces<D>(mesh, aux, geom, x, bc, grad);
        auto before = Kokkos::create_mirror(state); // a copy: a mirror *view* of a host field is the field itself
        Kokkos::deep_copy(before, state);
        unilag::filterEntropy<D, PH>(mesh, state, aux, geom, mass, grad, dt, coefficient);
        auto after = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), state);
        std::vector<double> dE(nCells);
        for (LO i = 0; i < nCells; ++i)
            dE[i] = after(i, S::energy) - before(i, S::energy);
        return dE;
    }

    double minLength() const
    {
        auto l = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), geom.length);
        double m = 1e300;
        for (LO i = 0; i < nCells; ++i)
            m = std::min(m, l(i));
        return m;
    }
};

template <int D> HostMesh<D> distorted()
{
    if constexpr (D == 2)
        return unilag_test::squareMesh(12, 0.3, 41);
    else
        return unilag_test::cubeMesh(5, 0.3, 42);
}

auto never = [](LO) { return false; };

template <int D> void checkLinear()
{
    Filter<D> f(distorted<D>());
    f.initialize([](LO, const double* c) { return 2.0 + 0.7 * c[0] - 0.4 * c[1] + 0.3 * c[2]; }, never, 1);
    const auto dE = f.run(0.5 * f.minLength(), 0.25);
    for (LO i = 0; i < f.nCells; ++i)
        EXPECT_LE(std::abs(dE[i]), 1e-13) << "cell " << i;
}

TEST(EntropyFilter, LeavesLinearFieldsAlone2D) { checkLinear<2>(); }
TEST(EntropyFilter, LeavesLinearFieldsAlone3D) { checkLinear<3>(); }

/*! The fit behind the gradient, on directions of every rank: g . u_s = w_s for a linear field's differences (the
 *  residual's need), including one direction, two in 3D, and nearly parallel ones (a corner's mirror images). */
TEST(EntropyFilter, FitsLinearDifferencesOfAnyRank)
{
    const unilag::Vec<3> slope{{0.7, -0.4, 0.3}};
    const unilag::Vec<3> sets[][4] = {
        {{{0.3, 0.1, -0.2}}, {{-0.1, 0.4, 0.05}}, {{0.02, -0.1, 0.3}}, {{-0.2, -0.2, -0.1}}}, // full rank, 4 faces
        {{{0.3, 0.1, -0.2}}, {{-0.6, -0.2, 0.4}}, {{0.15, 0.05, -0.1}}, {{0.3, 0.1, -0.2}}},  // one direction
        {{{0.3, 0.1, -0.2}}, {{-0.1, 0.4, 0.05}}, {{0.2, 0.5, -0.15}}, {{0.3, 0.1, -0.2}}},   // a plane
        {{{0.3, 0.1, -0.2}}, {{0.3, 0.1, -0.19}}, {{-0.1, 0.4, 0.05}}, {{0.3, 0.1, -0.2}}},   // nearly parallel pair
    };
    for (const auto& u : sets)
    {
        double w[4];
        for (int s = 0; s < 4; ++s)
            w[s] = unilag::dot(slope, u[s]);
        const unilag::Vec<3> g = unilag::entropy_filter::fitInSpan<3>(u, w, 4);
        const bool nearlyParallel = &u == &sets[3];
        for (int s = 0; s < 4; ++s)
        {
            // u_1 of the last set is dropped from the span: its error is (g - slope) . (u_1 - u_0), |g - slope| <= |slope|
            const double bound = nearlyParallel && s == 1 ? unilag::norm(slope) * unilag::norm(u[1] - u[0]) : 2e-15;
            EXPECT_NEAR(unilag::dot(g, u[s]), w[s], bound) << "direction " << s << " of set " << (&u - sets);
        }
    }
}

/*! Where the first D directions span well, fitInSpan solves the normal equations directly (session 25): the same
 *  weighted fit as the Gram-Schmidt path for any data, not only linear (random directions and values, 2D and 3D). */
template <int D> void checkNormalEquations()
{
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int direct = 0;
    for (int trial = 0; trial < 200; ++trial)
    {
        unilag::Vec<D> dirs[D + 1];
        double w[D + 1];
        for (int s = 0; s < D + 1; ++s)
        {
            for (int a = 0; a < D; ++a)
                dirs[s][a] = u(rng);
            w[s] = u(rng);
        }
        const int n = D + trial % 2; // D + 1 faces, or one face without a neighbour
        if (!unilag::entropy_filter::spansWell<D>(dirs))
            continue;
        ++direct;
        const auto fast = unilag::entropy_filter::fitInSpan<D>(dirs, w, n);
        const auto gramSchmidt = unilag::entropy_filter::fitInSpanGramSchmidt<D>(dirs, w, n);
        for (int a = 0; a < D; ++a)
            EXPECT_NEAR(fast[a], gramSchmidt[a], 1e-12 * (1.0 + std::abs(gramSchmidt[a]))) << "trial " << trial;
    }
    EXPECT_GT(direct, 150); // random directions nearly always span well
}

TEST(EntropyFilter, NormalEquationsAreTheGramSchmidtFit2D) { checkNormalEquations<2>(); }
TEST(EntropyFilter, NormalEquationsAreTheGramSchmidtFit3D) { checkNormalEquations<3>(); }

/*! A random eps: the exchange conserves the energy to round-off, moves heat from hotter to colder cells only
 *  (sum_i m_i dE_i eps_i <= 0, each face's flux times the jump against it), changes most cells, and shocked cells
 *  (every fifth) keep their energy. */
template <int D> void checkRandom()
{
    constexpr int NV = D + 1;
    Filter<D> f(distorted<D>());
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> eps(f.nCells);
    for (auto& e : eps)
        e = 1.0 + u(rng);
    auto shocked = [](LO i) { return i % 5 == 0; };
    f.initialize([&](LO i, const double*) { return eps[i]; }, shocked, 2);
    const auto dE = f.run(0.5 * f.minLength(), 0.25);
    auto m = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.mass);
    double sum = 0.0, scale = 0.0, work = 0.0;
    int changed = 0;
    for (LO i = 0; i < f.nCells; ++i)
    {
        sum += m(i) * dE[i];
        scale += std::abs(m(i) * dE[i]);
        work += m(i) * dE[i] * eps[i];
        changed += dE[i] != 0.0;
        if (shocked(i))
        {
            EXPECT_EQ(dE[i], 0.0) << "shocked cell " << i;
        }
        bool isolated = true; // every neighbour shocked or across the boundary: nothing to exchange
        for (int k = 0; k < NV; ++k)
        {
            const LO j = f.h.neighbour[NV * i + k];
            isolated = isolated && (j < 0 || shocked(j));
        }
        if (isolated)
        {
            EXPECT_EQ(dE[i], 0.0) << "cell " << i << " has no unshocked neighbour";
        }
    }
    EXPECT_GT(changed, f.nCells / 2);
    EXPECT_LE(std::abs(sum), 1e-14 * scale) << "sum " << sum << " scale " << scale;
    EXPECT_LT(work, 0.0) << "heat must flow from hotter to colder cells";
}

TEST(EntropyFilter, ConservesAndFlowsDownhill2D) { checkRandom<2>(); }
TEST(EntropyFilter, ConservesAndFlowsDownhill3D) { checkRandom<3>(); }

} // namespace
