#include "tube/HelixDispersion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

extern "C"
{
    void zggev_(const char* jobvl, const char* jobvr, const int* n, std::complex<double>* a, const int* lda,
                std::complex<double>* b, const int* ldb, std::complex<double>* alpha, std::complex<double>* beta,
                std::complex<double>* vl, const int* ldvl, std::complex<double>* vr, const int* ldvr,
                std::complex<double>* work, const int* lwork, double* rwork, int* info);
}

namespace unilag::tube
{
namespace
{

using cd = std::complex<double>;
using Vec3 = std::array<double, 3>;
constexpr cd I1{0.0, 1.0};

/*! A linear form in the unknowns whose coefficients are polynomials of degree <= 2 in omega: c[d][j] is the
 *  coefficient of omega^d x_j. The linearised equations are built from these exactly as written in
 *  docs/tube-helix.md 2, so the code reads like the derivation. */
struct Lin
{
    std::array<std::vector<cd>, 3> c;
    explicit Lin(int n = 0)
    {
        for (auto& v : c)
            v.assign(std::size_t(n), cd{});
    }
    static Lin unit(int n, int j)
    {
        Lin l(n);
        l.c[0][std::size_t(j)] = 1.0;
        return l;
    }
    int size() const { return int(c[0].size()); }
};

Lin operator+(Lin a, const Lin& b)
{
    for (int d = 0; d < 3; ++d)
        for (std::size_t j = 0; j < a.c[d].size(); ++j)
            a.c[d][j] += b.c[d][j];
    return a;
}
Lin operator*(cd s, Lin a)
{
    for (auto& v : a.c)
        for (auto& x : v)
            x *= s;
    return a;
}
Lin operator-(const Lin& a, const Lin& b) { return a + (-1.0) * b; }

//! d/dt of a mode exp(i (omega t - k s)): multiplication by i omega.
Lin dt(const Lin& a)
{
    for (const cd& x : a.c[2])
        if (x != cd{})
            throw std::logic_error("helixPencil: a third time derivative");
    Lin r(a.size());
    r.c[1] = (I1 * a).c[0];
    r.c[2] = (I1 * a).c[1];
    return r;
}
//! d/ds: multiplication by -i k.
Lin ds(const Lin& a, double k) { return cd(0.0, -k) * a; }

using V = std::array<Lin, 3>;

V operator+(V a, const V& b)
{
    for (int i = 0; i < 3; ++i)
        a[i] = a[i] + b[i];
    return a;
}
V operator*(cd s, V a)
{
    for (auto& l : a)
        l = s * l;
    return a;
}
V diag(const Vec3& d, V a)
{
    for (int i = 0; i < 3; ++i)
        a[i] = d[i] * a[i];
    return a;
}
V dt(const V& a) { return {dt(a[0]), dt(a[1]), dt(a[2])}; }
V ds(const V& a, double k) { return {ds(a[0], k), ds(a[1], k), ds(a[2], k)}; }
//! A constant vector times a scalar form: a x.
V along(const Vec3& a, const Lin& x) { return {a[0] * x, a[1] * x, a[2] * x}; }
//! a x b, a constant.
V cross(const Vec3& a, const V& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
//! a x b, b constant.
V cross(const V& a, const Vec3& b) { return -1.0 * cross(b, a); }

V units(int n, int first) { return {Lin::unit(n, first), Lin::unit(n, first + 1), Lin::unit(n, first + 2)}; }

} // namespace

HelixParameters HelixParameters::dimensionless(double beta, double u, double slenderness, double poisson,
                                               double shearCoefficient)
{
    if (!(beta >= 0.0 && beta < 1.0) || (beta == 0.0 && u != 0.0))
        throw std::invalid_argument("HelixParameters::dimensionless: beta must lie in [0, 1) (u = 0 if beta = 0)");
    HelixParameters p;
    const double l2 = slenderness * slenderness;
    p.bendingStiffness = 1.0;
    p.torsionalStiffness = 1.0 / (1.0 + poisson);
    p.axialStiffness = l2;
    p.shearStiffness = shearCoefficient * l2 / (2.0 * (1.0 + poisson));
    p.fluidMass = beta;
    p.wallMass = 1.0 - beta;
    p.bendingInertia = p.wallMass / l2;
    p.torsionalInertia = 2.0 * p.bendingInertia;
    p.flowSpeed = beta > 0.0 ? u / std::sqrt(beta) : 0.0;
    p.length = 1.0;
    p.mu0 = p.zeroPressureMu0();
    return p;
}

std::array<double, 3> HelixParameters::curvature() const
{
    const double c = helixK * M_PI / length;
    return {c * std::cos(helixAngle), c * std::sin(helixAngle), 0.0};
}

double HelixParameters::zeroPressureMu0() const { return 0.5 * fluidMass * flowSpeed * flowSpeed; }
double HelixParameters::equilibriumMu0() const { return 1.5 * fluidMass * flowSpeed * flowSpeed; }
double HelixParameters::axialForce() const { return 1.5 * fluidMass * flowSpeed * flowSpeed - mu0; }

double HelixParameters::equilibriumResidual() const
{
    const Vec3 w = curvature();
    // |Omega_0 x f0 e1| = |f0| sqrt(W2^2 + W3^2)
    return std::abs(axialForce()) * std::hypot(w[1], w[2]);
}

bool HelixParameters::isEquilibrium(double tolerance) const
{
    const double scale =
        (std::abs(axialForce()) + fluidMass * flowSpeed * flowSpeed + bendingStiffness / (length * length)) / length;
    return equilibriumResidual() <= tolerance * scale;
}

HelixPencil helixPencil(const HelixParameters& p, double k)
{
    const int n = kHelixFields + (p.inextensible ? 3 : 0);
    const Vec3 e1{1.0, 0.0, 0.0}, w = p.curvature();
    const double m = p.wallMass, M = p.fluidMass, U = p.flowSpeed, f0 = p.axialForce();
    const Vec3 rotary = p.noRotaryInertia ? Vec3{0.0, 0.0, 0.0}
                                          : Vec3{p.torsionalInertia, p.bendingInertia, p.bendingInertia};
    const Vec3 J{p.torsionalStiffness, p.bendingStiffness, p.bendingStiffness};
    const Vec3 L{p.axialStiffness, p.shearStiffness, p.shearStiffness};
    const Vec3 P0{M * U, 0.0, 0.0}, F0{f0, 0.0, 0.0};

    const V sigma = units(n, 0), psi = units(n, 3);
    const Lin v = Lin::unit(n, 6), q = Lin::unit(n, 7); // delta u, A delta mu
    // body-frame variations (tube.md 1.2) about Gamma_0 = e1, omega_0 = gamma_0 = 0
    const V dOmega = ds(sigma, k) + cross(w, sigma);
    const V dGamma = ds(psi, k) + cross(e1, sigma) + cross(w, psi);
    const V domega = dt(sigma), dgamma = dt(psi);
    const Lin& dG1 = dGamma[0];
    // momenta and stresses (tube.md 1.4 with A' = 0): P = dl/dgamma, pi = dl/domega, Mm = dl/dOmega,
    // F = dl/dGamma - mu dQ/dGamma
    const V dP = m * dgamma + along(e1, M * U * dG1) + M * (dgamma + along(e1, v) + U * dGamma);
    const V dPi = diag(rotary, domega);
    const V dMm = -1.0 * diag(J, dOmega);
    V wall = p.inextensible ? units(n, 8) : -1.0 * diag(L, dGamma);
    V dGammaPerp = dGamma;
    dGammaPerp[0] = Lin(n);
    const V dF = wall + M * (along(e1, U * U * dG1 + 2.0 * U * v) + U * dgamma + U * U * dGamma) +
                 along(e1, M * U * (dgamma[0] + v + U * dG1) - q) + (0.5 * M * U * U - p.mu0) * dGammaPerp;
    // the equations, linearised (omega_0 = gamma_0 = 0, Mm_0 = 0, P_0 = M U e1, F_0 = f0 e1)
    const V e1Eq = dt(dPi) + cross(dgamma, P0) + ds(dMm, k) + cross(w, dMm) + cross(dGamma, F0) + cross(e1, dF);
    const V e2Eq = dt(dP) + cross(domega, P0) + ds(dF, k) + cross(w, dF) + cross(dOmega, F0);
    const Lin dm = M * (2.0 * U * dG1 + dgamma[0] + v); // A delta m, m = rho Gamma.(gamma + u Gamma)
    const Lin e3Eq = dt(dm) + ds(U * dm + M * U * v - q, k);
    const Lin e4Eq = dt(dG1) + ds(U * dG1 + v, k); // (1/A) delta [Q_t + (Q u)_s]

    std::vector<Lin> rows{e1Eq[0], e1Eq[1], e1Eq[2], e2Eq[0], e2Eq[1], e2Eq[2], e3Eq, e4Eq};
    if (p.inextensible)
        for (const Lin& c : dGamma)
            rows.push_back(c);
    HelixPencil pencil;
    pencil.n = n;
    for (int d = 0; d < 3; ++d)
    {
        pencil.m[d].assign(std::size_t(n) * n, cd{});
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                pencil.m[d][std::size_t(i) * n + j] = rows[std::size_t(i)].c[d][std::size_t(j)];
    }
    return pencil;
}

std::vector<HelixMode> helixModes(const HelixParameters& p, double k)
{
    if (p.requireEquilibrium && !p.isEquilibrium())
        throw std::invalid_argument("helixDispersion: the base state is not an equilibrium (residual " +
                                    std::to_string(p.equilibriumResidual()) +
                                    "); take mu0 = equilibriumMu0() or set requireEquilibrium = false");
    HelixPencil pc = helixPencil(p, k);
    const int n = pc.n;
    auto at = [&](int d, int i, int j) -> cd& { return pc.m[d][std::size_t(i) * n + j]; };
    // omega = s nu with s^2 |M2| = |M0| (Fan, Lin & Van Dooren), then row and column equilibration of the pencil
    auto norm = [&](int d)
    {
        double s = 0.0;
        for (const cd& x : pc.m[d])
            s += std::norm(x);
        return std::sqrt(s);
    };
    const double n0 = norm(0), n2 = norm(2);
    const double s = (n0 > 0.0 && n2 > 0.0) ? std::sqrt(n0 / n2) : 1.0;
    for (auto& x : pc.m[1])
        x *= s;
    for (auto& x : pc.m[2])
        x *= s * s;
    std::vector<double> colScale(std::size_t(n), 1.0);
    for (int pass = 0; pass < 3; ++pass)
    {
        for (int i = 0; i < n; ++i)
        {
            double big = 0.0;
            for (int d = 0; d < 3; ++d)
                for (int j = 0; j < n; ++j)
                    big = std::max(big, std::abs(at(d, i, j)));
            if (big > 0.0)
                for (int d = 0; d < 3; ++d)
                    for (int j = 0; j < n; ++j)
                        at(d, i, j) /= big;
        }
        for (int j = 0; j < n; ++j)
        {
            double big = 0.0;
            for (int d = 0; d < 3; ++d)
                for (int i = 0; i < n; ++i)
                    big = std::max(big, std::abs(at(d, i, j)));
            if (big > 0.0)
            {
                colScale[std::size_t(j)] /= big;
                for (int d = 0; d < 3; ++d)
                    for (int i = 0; i < n; ++i)
                        at(d, i, j) /= big;
            }
        }
    }
    // companion form A z = nu B z, z = (x, nu x): A = [[0, I], [-M0, -M1]], B = [[I, 0], [0, M2]] (column-major)
    const int N = 2 * n;
    std::vector<cd> a(std::size_t(N) * N), b(std::size_t(N) * N);
    auto A = [&](int i, int j) -> cd& { return a[std::size_t(i) + std::size_t(j) * N]; };
    auto B = [&](int i, int j) -> cd& { return b[std::size_t(i) + std::size_t(j) * N]; };
    for (int i = 0; i < n; ++i)
    {
        A(i, n + i) = 1.0;
        B(i, i) = 1.0;
        for (int j = 0; j < n; ++j)
        {
            A(n + i, j) = -at(0, i, j);
            A(n + i, n + j) = -at(1, i, j);
            B(n + i, n + j) = at(2, i, j);
        }
    }
    const std::size_t nn = static_cast<std::size_t>(N);
    std::vector<cd> alpha(nn), beta(nn), vr(nn * nn);
    std::vector<double> rwork(std::size_t(8) * N);
    int info = 0, lwork = -1, one = 1;
    cd query;
    cd dummy;
    zggev_("N", "V", &N, a.data(), &N, b.data(), &N, alpha.data(), beta.data(), &dummy, &one, vr.data(), &N, &query,
           &lwork, rwork.data(), &info);
    lwork = std::max(1, int(query.real()));
    std::vector<cd> work(static_cast<std::size_t>(lwork));
    zggev_("N", "V", &N, a.data(), &N, b.data(), &N, alpha.data(), beta.data(), &dummy, &one, vr.data(), &N,
           work.data(), &lwork, rwork.data(), &info);
    if (info != 0)
        throw std::runtime_error("helixDispersion: zggev info " + std::to_string(info));

    std::vector<HelixMode> modes;
    for (int e = 0; e < N; ++e)
    {
        const double al = std::abs(alpha[std::size_t(e)]), be = std::abs(beta[std::size_t(e)]);
        if (al < 1e-13 && be < 1e-13) // a singular pencil (k = 0: a uniform pressure)
            continue;
        if (be <= 1e-12 * al) // infinite: the multipliers and the massless fields
            continue;
        HelixMode mode;
        mode.omega = s * alpha[std::size_t(e)] / beta[std::size_t(e)];
        mode.shape.resize(std::size_t(n));
        for (int j = 0; j < n; ++j)
            mode.shape[std::size_t(j)] = vr[std::size_t(j) + std::size_t(e) * N] * colScale[std::size_t(j)];
        // (Sigma, Psi) of unit 2-norm, its largest entry real and positive
        double nrm = 0.0;
        std::size_t big = 0;
        for (std::size_t j = 0; j < 6; ++j)
        {
            nrm += std::norm(mode.shape[j]);
            if (std::abs(mode.shape[j]) > std::abs(mode.shape[big]))
                big = j;
        }
        const cd phase = nrm > 0.0 ? std::abs(mode.shape[big]) / mode.shape[big] / std::sqrt(nrm) : cd(1.0);
        for (auto& x : mode.shape)
            x *= phase;
        modes.push_back(std::move(mode));
    }
    std::sort(modes.begin(), modes.end(),
              [](const HelixMode& x, const HelixMode& y)
              {
                  if (x.omega.real() != y.omega.real())
                      return x.omega.real() < y.omega.real();
                  return x.omega.imag() < y.omega.imag();
              });
    return modes;
}

std::vector<std::complex<double>> helixDispersion(const HelixParameters& p, double k)
{
    std::vector<std::complex<double>> omegas;
    for (const HelixMode& m : helixModes(p, k))
        omegas.push_back(m.omega);
    return omegas;
}

std::array<std::complex<double>, 2> straightPipeOmega(double k, double u, double beta, double fhat)
{
    const double convected = std::sqrt(beta) * u;
    const std::complex<double> root = std::sqrt(std::complex<double>(beta * u * u + k * k - fhat, 0.0));
    return {k * (convected + root), k * (convected - root)};
}

} // namespace unilag::tube
