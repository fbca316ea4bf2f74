#include "tube/LinearStability.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "tube/TubeElement.hpp"

namespace unilag::tube
{
namespace
{

using lapack::Matrix;

/*! Growth above this fraction of |lambda| is an instability: below it, the growth of a neutral mode is the
 *  eigensolver's round-off (the cantilever at beta = 0 is undamped below u_cf). */
constexpr double kRelativeGrowth = 1e-8;
//! A mode whose frequency is below this fraction of |lambda| at onset is a divergence (static) mode.
constexpr double kRealAxis = 1e-6;

//! The four global matrices over all dofs (node-major: node i holds dofs [i dpn, (i + 1) dpn)).
struct GlobalMatrices
{
    Matrix inertia, bending, flow, coriolis;
};

void scatterAdd(Matrix& global, const std::vector<double>& local, int size, int first, double scale = 1.0)
{
    for (int i = 0; i < size; ++i)
        for (int j = 0; j < size; ++j)
            global(first + i, first + j) += scale * local[i * size + j];
}

//! Assembly over equal elements on [0, 1]; the end terms [v eta']_0^1 go into the flow stiffness.
GlobalMatrices assemble(const TubeElement& element, int elements)
{
    const int dpn = element.dofsPerNode(), n = dpn * (elements + 1);
    const double h = 1.0 / elements;
    GlobalMatrices g{Matrix(n), Matrix(n), Matrix(n), Matrix(n)};
    const ElementMatrices e = element.matrices(h);
    for (int el = 0; el < elements; ++el)
    {
        const int first = el * dpn;
        scatterAdd(g.inertia, e.inertia, e.size, first);
        scatterAdd(g.bending, e.bending, e.size, first);
        scatterAdd(g.flow, e.centrifugal, e.size, first);
        scatterAdd(g.coriolis, e.coriolis, e.size, first);
    }
    // K_f = (v', eta') - [v eta']_0^1: the weak form of -eta'' (docs/tube-model.md 2)
    scatterAdd(g.flow, element.endTerm(h, true), e.size, (elements - 1) * dpn, -1.0);
    scatterAdd(g.flow, element.endTerm(h, false), e.size, 0, +1.0);
    // the area change stiffens psi'^2 by a u^2 term (docs/tube-model.md 7.3): it goes with the flow's u^2
    if (!e.areaStiffening.empty())
        for (int el = 0; el < elements; ++el)
            scatterAdd(g.flow, e.areaStiffening, e.size, el * dpn, -1.0);
    return g;
}

//! The dofs the end conditions leave free.
std::vector<int> freeDofs(const TubeElement& element, int elements, EndCondition left, EndCondition right)
{
    const int dpn = element.dofsPerNode(), n = dpn * (elements + 1);
    std::vector<bool> held(n, false);
    for (int c : element.constrained(left))
        held[c] = true;
    for (int c : element.constrained(right))
        held[elements * dpn + c] = true;
    std::vector<int> dofs;
    for (int i = 0; i < n; ++i)
        if (!held[i])
            dofs.push_back(i);
    return dofs;
}

Matrix restrictTo(const Matrix& a, const std::vector<int>& dofs)
{
    Matrix r(int(dofs.size()));
    for (int i = 0; i < r.n; ++i)
        for (int j = 0; j < r.n; ++j)
            r(i, j) = a(dofs[i], dofs[j]);
    return r;
}

bool byFrequency(const Mode& a, const Mode& b)
{
    if (a.frequency() != b.frequency())
        return a.frequency() < b.frequency();
    return a.growth() < b.growth();
}

//! The mode with the largest growth relative to its size (the one that crosses first).
Mode leadingMode(const std::vector<Mode>& modes)
{
    return *std::max_element(
        modes.begin(), modes.end(),
        [](const Mode& a, const Mode& b)
        { return a.growth() / (1.0 + std::abs(a.lambda)) < b.growth() / (1.0 + std::abs(b.lambda)); });
}

} // namespace

LinearStability::LinearStability(const TubeDiscretisation& disc, double beta) : beta_(beta)
{
    const auto element = makeElement(disc.model, disc.geometric);
    const GlobalMatrices g = assemble(*element, disc.elements);
    const std::vector<int> dofs = freeDofs(*element, disc.elements, disc.left, disc.right);
    mass_ = restrictTo(g.inertia, dofs);
    bending_ = restrictTo(g.bending, dofs);
    flow_ = restrictTo(g.flow, dofs);
    coriolis_ = restrictTo(g.coriolis, dofs);
    const GeometricParameters& geo = disc.geometric;
    if (disc.model == TubeModel::Geometric && geo.shear > 0.0 && geo.rotary > 0.0)
        frequencyCutoff_ = 1.0 / std::sqrt(geo.shear * geo.rotary);
    if (disc.modes > 0 && disc.modes < mass_.n)
        projectOnModes(disc.modes);
    invMassBending_ = lapack::solveSpd(mass_, bending_);
    invMassFlow_ = lapack::solveSpd(mass_, flow_);
    invMassCoriolis_ = lapack::solveSpd(mass_, coriolis_);
}

/*! Galerkin projection on the lowest modes Phi of K_b x = w^2 M x: Phi^T M Phi = I, Phi^T K_b Phi = diag(w^2),
 *  and the flow matrices Phi^T K_f Phi, Phi^T G Phi (full, not symmetric). */
void LinearStability::projectOnModes(int modes)
{
    std::vector<double> values, phi;
    lapack::symmetricEigenpairs(bending_, mass_, modes, values, phi);
    const int n = mass_.n;
    auto project = [&](const Matrix& a)
    {
        Matrix r(modes);
        std::vector<double> aPhi(std::size_t(n) * modes, 0.0);
        for (int k = 0; k < modes; ++k)
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i)
                    aPhi[i + std::size_t(k) * n] += a(i, j) * phi[j + std::size_t(k) * n];
        for (int k = 0; k < modes; ++k)
            for (int l = 0; l < modes; ++l)
                for (int i = 0; i < n; ++i)
                    r(l, k) += phi[i + std::size_t(l) * n] * aPhi[i + std::size_t(k) * n];
        return r;
    };
    flow_ = project(flow_);
    coriolis_ = project(coriolis_);
    mass_ = Matrix(modes);
    bending_ = Matrix(modes);
    for (int k = 0; k < modes; ++k)
    {
        mass_(k, k) = 1.0;
        bending_(k, k) = values[k];
    }
}

//! [[0, I], [-M^{-1} K(u), -M^{-1} C(u)]] for the state (eta, eta_t).
Matrix LinearStability::firstOrderMatrix(double u) const
{
    const int n = mass_.n;
    const double coriolis = 2.0 * std::sqrt(beta_) * u, centrifugal = u * u;
    Matrix a(2 * n);
    for (int i = 0; i < n; ++i)
        a(i, n + i) = 1.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
        {
            a(n + i, j) = -invMassBending_(i, j) + centrifugal * invMassFlow_(i, j);
            a(n + i, n + j) = -coriolis * invMassCoriolis_(i, j);
        }
    return a;
}

std::vector<Mode> LinearStability::spectrum(double u) const
{
    std::vector<Mode> modes;
    for (const auto& l : lapack::eigenvalues(firstOrderMatrix(u)))
        modes.push_back(Mode{l});
    std::sort(modes.begin(), modes.end(), byFrequency);
    return modes;
}

std::vector<Mode> LinearStability::lowestModes(double u, int count) const
{
    std::vector<Mode> modes;
    for (const Mode& m : spectrum(u))
        if (m.frequency() >= 0.0 && int(modes.size()) < count)
            modes.push_back(m);
    return modes;
}

std::vector<Mode> LinearStability::modesBelowCutoff(double u) const
{
    std::vector<Mode> modes = spectrum(u);
    modes.erase(std::remove_if(modes.begin(), modes.end(),
                               [&](const Mode& m) { return std::abs(m.frequency()) >= frequencyCutoff_; }),
                modes.end());
    return modes;
}

double LinearStability::growthRate(double u) const
{
    double g = -std::numeric_limits<double>::infinity();
    for (const Mode& m : modesBelowCutoff(u))
        g = std::max(g, m.growth());
    return g;
}

bool LinearStability::unstable(double u) const
{
    const Mode m = leadingMode(modesBelowCutoff(u));
    return m.growth() > kRelativeGrowth * (1.0 + std::abs(m.lambda));
}

Onset LinearStability::firstInstability(const ScanOptions& scan) const
{
    Onset onset;
    double stableU = 0.0, unstableU = -1.0;
    const int steps = int(std::ceil(scan.speedMax / scan.speedStep));
    for (int i = 1; i <= steps && unstableU < 0.0; ++i)
    {
        const double u = std::min(i * scan.speedStep, scan.speedMax);
        if (unstable(u))
            unstableU = u;
        else
            stableU = u;
    }
    if (unstableU < 0.0)
        return onset;
    while (unstableU - stableU > scan.tolerance)
    {
        const double mid = 0.5 * (stableU + unstableU);
        (unstable(mid) ? unstableU : stableU) = mid;
    }
    const Mode m = leadingMode(modesBelowCutoff(unstableU));
    onset.found = true;
    onset.speed = 0.5 * (stableU + unstableU);
    onset.frequency = std::abs(m.frequency());
    onset.divergence = onset.frequency < kRealAxis * (1.0 + std::abs(m.lambda));
    if (onset.divergence)
        onset.frequency = 0.0;
    return onset;
}

double LinearStability::divergenceSpeed() const
{
    double best = std::numeric_limits<double>::infinity();
    for (const auto& mu : lapack::generalizedEigenvalues(bending_, flow_))
        if (mu.real() > 0.0 && std::abs(mu.imag()) <= 1e-8 * std::abs(mu))
            best = std::min(best, std::sqrt(mu.real()));
    return best;
}

TubeDiscretisation geometricDiscretisation(const PhysicalTube& tube, int elements, int modes, EndCondition left,
                                           EndCondition right)
{
    TubeDiscretisation d;
    d.model = TubeModel::Geometric;
    d.geometric = tube.geometricParameters();
    d.elements = elements;
    d.modes = modes;
    d.left = left;
    d.right = right;
    return d;
}

Onset criticalFlutterSpeed(const TubeDiscretisation& disc, double beta, const ScanOptions& scan)
{
    return LinearStability(disc, beta).firstInstability(scan);
}

std::vector<std::vector<Mode>> trackModes(const LinearStability& stability, const std::vector<double>& speeds,
                                          int count)
{
    std::vector<std::vector<Mode>> loci;
    for (std::size_t p = 0; p < speeds.size(); ++p)
    {
        if (p == 0)
        {
            loci.push_back(stability.lowestModes(speeds[0], count));
            continue;
        }
        std::vector<Mode> candidates = stability.lowestModes(speeds[p], stability.dofs() * 2);
        std::vector<bool> used(candidates.size(), false);
        std::vector<Mode> next;
        for (const Mode& previous : loci.back())
        {
            std::size_t best = candidates.size();
            for (std::size_t c = 0; c < candidates.size(); ++c)
                if (!used[c] && (best == candidates.size() || std::abs(candidates[c].lambda - previous.lambda) <
                                                                  std::abs(candidates[best].lambda - previous.lambda)))
                    best = c;
            if (best == candidates.size())
                break;
            used[best] = true;
            next.push_back(candidates[best]);
        }
        loci.push_back(next);
    }
    return loci;
}

int unstableMode(const LinearStability& stability, const Onset& onset, int count, int points)
{
    if (!onset.found)
        return 0;
    std::vector<double> speeds(points);
    for (int p = 0; p < points; ++p)
        speeds[p] = onset.speed * (1.0 + 1e-4) * p / (points - 1);
    // a copy: a reference into the temporary loci would dangle
    const std::vector<Mode> last = trackModes(stability, speeds, count).back();
    // The mode that carries the onset's eigenvalue i omega_cf, not the one that grows most over all: at a
    // divergence the followed eigenvalue may be the stable one of the real pair it splits into, and at an onset
    // near u = 0 every mode's growth is round-off. Two modes there (a coalescence, beta = 0): the growing one.
    const std::complex<double> atOnset(0.0, onset.frequency);
    std::vector<double> distance(last.size());
    for (std::size_t m = 0; m < last.size(); ++m)
        distance[m] = std::abs(last[m].lambda - atOnset);
    if (distance.empty())
        return 0;
    const double nearest = *std::min_element(distance.begin(), distance.end());
    int best = -1;
    double others = std::numeric_limits<double>::infinity(); // the nearest mode outside the group at onset
    for (std::size_t m = 0; m < last.size(); ++m)
        if (distance[m] > 2.0 * nearest)
            others = std::min(others, distance[m]);
        else if (best < 0 || last[m].growth() > last[best].growth())
            best = int(m);
    return nearest < 0.5 * others ? best + 1 : 0;
}

std::array<std::complex<double>, 2> dispersionOmega(double k, double u, double beta)
{
    const std::complex<double> root = std::sqrt(std::complex<double>(k * k - (1.0 - beta) * u * u, 0.0));
    const double convected = std::sqrt(beta) * u;
    return {k * (convected + root), k * (convected - root)};
}

int freeDofCount(const TubeDiscretisation& disc)
{
    return int(freeDofs(*makeElement(disc.model, disc.geometric), disc.elements, disc.left, disc.right).size());
}

TubeDiscretisation sceneDiscretisation(const TubeScene& scene)
{
    TubeDiscretisation d;
    d.model = scene.model;
    d.left = scene.left;
    d.right = scene.right;
    d.elements = scene.stability.elements;
    d.modes = scene.stability.modes;
    if (scene.model == TubeModel::Geometric)
        d.geometric = scene.physical.geometricParameters();
    return d;
}

} // namespace unilag::tube
