// tube_helix_dispersion: the dispersion relation omega(k) of a helical tube conveying fluid (docs/tube-helix.md),
// for the study of that document: beta = 0.2, a slender thin tube (L / r_g = 50, nu = 0.3, shear coefficient 0.5),
// helix angle kappa = pi/4, K = 0, 0.5, 1, u = 0 and 2, two models (geometric: extensible, shearable, rotary
// inertia; inextensible: Gamma = chi, no rotary inertia). Units of tube.md 2.1 (L = EI = M + m = 1).
//
// Usage: tube_helix_dispersion [OUTPUT_DIR] [--quick]       (default output/tube_helix)
// Writes dispersion.csv (every root on a k grid), table.md (the roots at a few k), stability.csv (the largest
// growth rate over k against u), screw.csv (the prediction for the nonlinear solver's check, docs/tube-helix.md 6).
// Plot: apps/tube_helix_dispersion_plot.py OUTPUT_DIR.
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "tube/HelixDispersion.hpp"

using namespace unilag::tube;

namespace
{

constexpr double kBeta = 0.2, kAngle = M_PI / 4;

struct Case
{
    std::string name; //!< how the base force is set
    double K;
    bool zeroPressure; //!< p0 = 0 (only an equilibrium for K = 0); else the equilibrium mu0 (no base force)
};

const std::vector<Case> kCases{{"K0_p0", 0.0, true}, {"K0_f0", 0.0, false}, {"K0.5", 0.5, false}, {"K1", 1.0, false}};

HelixParameters parameters(const Case& c, double u, bool inextensible)
{
    HelixParameters p = HelixParameters::dimensionless(kBeta, u);
    p.helixK = c.K;
    p.helixAngle = kAngle;
    p.inextensible = p.noRotaryInertia = inextensible;
    p.mu0 = c.zeroPressure ? p.zeroPressureMu0() : p.equilibriumMu0();
    return p;
}

const char* modelName(bool inextensible) { return inextensible ? "inextensible" : "geometric"; }

std::string fmt(std::complex<double> w)
{
    char buf[64];
    if (std::abs(w.imag()) < 1e-9 * (1.0 + std::abs(w)))
        std::snprintf(buf, sizeof buf, "%.4f", w.real());
    else
        std::snprintf(buf, sizeof buf, "%.4f%+.4fi", w.real(), w.imag());
    return buf;
}

} // namespace

int main(int argc, char** argv)
{
    std::filesystem::path out = "output/tube_helix";
    bool quick = false;
    for (int i = 1; i < argc; ++i)
    {
        if (std::strcmp(argv[i], "--quick") == 0)
            quick = true;
        else if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0)
        {
            std::cout << "usage: tube_helix_dispersion [OUTPUT_DIR] [--quick]\n";
            return 0;
        }
        else
            out = argv[i];
    }
    std::filesystem::create_directories(out);

    // every root on a k grid (k = 0 left out: a uniform pressure makes the pencil singular there)
    {
        std::ofstream csv(out / "dispersion.csv");
        csv << "model,case,K,kappa,u,beta,mu0,f0,k,index,re_omega,im_omega\n";
        csv.precision(10);
        const double dk = quick ? 0.2 : 0.05;
        for (bool inext : {false, true})
            for (const Case& c : kCases)
                for (double u : {0.0, 2.0})
                {
                    const HelixParameters p = parameters(c, u, inext);
                    for (double k = -12.0 + dk / 2; k < 12.0; k += dk)
                    {
                        const auto w = helixDispersion(p, k);
                        for (std::size_t i = 0; i < w.size(); ++i)
                            csv << modelName(inext) << ',' << c.name << ',' << c.K << ',' << kAngle << ',' << u << ','
                                << kBeta << ',' << p.mu0 << ',' << p.axialForce() << ',' << k << ',' << i << ','
                                << w[i].real() << ',' << w[i].imag() << '\n';
                    }
                }
    }

    // the table of docs/tube-helix.md 5: roots with |Re omega| <= 100 (the geometric model's shear and extension
    // branches above are left out)
    {
        std::ostringstream md;
        md << "| model | case | u | k | omega (|Re| <= 100, sorted by Re) |\n|---|---|---|---|---|\n";
        for (bool inext : {true, false})
            for (const Case& c : kCases)
                for (double u : {0.0, 2.0})
                {
                    if (u == 0.0 && c.name == "K0_f0")
                        continue; // the same as K0_p0
                    const HelixParameters p = parameters(c, u, inext);
                    for (double k : {0.5, 1.0, 2.0, 4.0, 8.0})
                    {
                        md << "| " << modelName(inext) << " | " << c.name << " | " << u << " | " << k << " |";
                        for (const auto& w : helixDispersion(p, k))
                            if (std::abs(w.real()) <= 100.0)
                                md << ' ' << fmt(w);
                        md << " |\n";
                    }
                }
        std::ofstream(out / "table.md") << md.str();
        std::cout << md.str();
    }

    // stability: the largest growth rate -Im omega over |k| <= 12 against u
    {
        std::ofstream csv(out / "stability.csv");
        csv << "model,case,K,u,max_growth,k_at_max,k_unstable_min,k_unstable_max\n";
        csv.precision(8);
        const double dk = quick ? 0.2 : 0.05, du = quick ? 2.0 : 0.5;
        for (bool inext : {false, true})
            for (const Case& c : kCases)
                for (double u = 0.0; u <= 10.0 + 1e-9; u += du)
                {
                    const HelixParameters p = parameters(c, u, inext);
                    double growth = 0.0, kMax = 0.0, kLo = NAN, kHi = NAN;
                    for (double k = -12.0 + dk / 2; k < 12.0; k += dk)
                        for (const auto& w : helixDispersion(p, k))
                        {
                            const double g = -w.imag();
                            if (g > 1e-8 * (1.0 + std::abs(w)))
                            {
                                kLo = std::isnan(kLo) ? k : std::min(kLo, k);
                                kHi = std::isnan(kHi) ? k : std::max(kHi, k);
                                if (g > growth)
                                {
                                    growth = g;
                                    kMax = k;
                                }
                            }
                        }
                    csv << modelName(inext) << ',' << c.name << ',' << c.K << ',' << u << ',' << growth << ',' << kMax
                        << ',' << kLo << ',' << kHi << '\n';
                }
    }

    // the nonlinear solver's check: a screw-periodic helix of length L = 1, K = 1, kappa = pi/4, no flow;
    // body-periodic perturbations have k = 2 pi n. The rod alone (beta = 0) and the tube full of fluid at rest
    // (beta = 0.2); omega > 0 and the amplitudes (Sigma, Psi) of each mode, ~ exp(i (omega t - k s)).
    {
        std::ofstream csv(out / "screw.csv");
        csv << "model,beta,n,k,index,omega";
        for (const char* f : {"Sigma1", "Sigma2", "Sigma3", "Psi1", "Psi2", "Psi3"})
            csv << ',' << f << "_re," << f << "_im";
        csv << '\n';
        csv.precision(10);
        for (bool inext : {false, true})
            for (double beta : {0.0, kBeta})
            {
                HelixParameters p = HelixParameters::dimensionless(beta, 0.0);
                p.helixK = 1.0;
                p.helixAngle = kAngle;
                p.inextensible = p.noRotaryInertia = inext;
                for (int n : {1, 2, 3})
                {
                    const double k = 2 * M_PI * n;
                    int index = 0;
                    for (const HelixMode& m : helixModes(p, k))
                    {
                        if (m.omega.real() <= 0.0)
                            continue;
                        csv << modelName(inext) << ',' << beta << ',' << n << ',' << k << ',' << index++ << ','
                            << m.omega.real();
                        for (int j = 0; j < 6; ++j)
                            csv << ',' << m.shape[std::size_t(j)].real() << ',' << m.shape[std::size_t(j)].imag();
                        csv << '\n';
                    }
                }
            }
    }
    std::cout << "wrote " << (out / "dispersion.csv").string() << ", table.md, stability.csv, screw.csv\n";
    return 0;
}
