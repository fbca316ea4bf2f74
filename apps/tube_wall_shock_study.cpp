// Shock Mach number against shock strength in a soft, latex-like gas-filled tube (docs/tube-wall.md 4): a
// closed shock tube (driver at p4 on an inflated wall, driven air at p1 = p_ext on the unloaded wall), the
// gas + wall coupling of src/tube/GasWallCoupling.cpp. Mach relative to the gas sound speed a1 AND to the
// compliant linear speed c1 of tube.md 3; strength p2/p1 measured behind the shock.
//   tube_wall_shock_study [outdir=.] [cells=800]
// writes outdir/tube_wall_shock_mach.csv and outdir/tube_wall_shock_profile.csv (the p4/p1 = 2 run);
// apps/tube_wall_shock_study_plot.py draws them.
#include <Kokkos_Core.hpp>

#include "StudyArgs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "tube/GasWallCoupling.hpp"
#include "tube/RiemannExact.hpp"

namespace
{

using namespace unilag::tube;

constexpr double kGamma = 1.4;
constexpr double kP1 = 101325.0, kRho1 = 1.2; // air at rest ahead of the shock, p1 = p_ext
constexpr double kLength = 4.0, kDriver = 1.0; // tube and driver section (m)

//! Latex-like wall: E 1 MPa, nu 0.5, h 1 mm, rho_w 1000 kg/m^3, R0 5 mm; a viscous wall force c = 200 N s/m^2
//! (damping ratio about 0.3 of the wall's own oscillation) so that the wall ringing behind the shock settles.
WallMaterial latex()
{
    WallMaterial m;
    m.youngModulus = 1.0e6;
    m.poisson = 0.5;
    m.thickness = 1.0e-3;
    m.density = 1000.0;
    m.restRadius = 5.0e-3;
    m.viscosity = 200.0;
    return m;
}

double slope(const std::vector<double>& x, const std::vector<double>& y)
{
    double mx = 0, my = 0, sxy = 0, sxx = 0;
    for (size_t i = 0; i < x.size(); ++i)
        mx += x[i] / x.size(), my += y[i] / y.size();
    for (size_t i = 0; i < x.size(); ++i)
        sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
    return sxy / sxx;
}

//! Mean pressure over cells with s in [from, to].
double meanPressure(const GasFields& f, double from, double to)
{
    double sum = 0;
    int count = 0;
    for (size_t j = 0; j < f.s.size(); ++j)
        if (f.s[j] >= from && f.s[j] <= to)
            sum += f.p[j], ++count;
    return sum / std::max(count, 1);
}

struct ShockResult
{
    double p4, p2, speed;
};

/*! One shock tube: snapshots at 8 times; the shock at each is where p crosses (p1 + p2)/2, p2 the mean over
 *  [0.35, 0.7] m behind a first estimate of the front (the front is spread over ~0.3 m by the wall) (where p first
 *  exceeds p1 + 5% of p4 - p1). */
ShockResult runShockTube(const WallCoefficients& w, double p4, int cells, const std::string& profilePath)
{
    GasSetup setup;
    setup.length = kLength;
    setup.cells = cells;
    setup.gamma = kGamma;
    GasWallCoupling tube(setup, w);
    // the driver edge is a tanh ramp 0.03 m wide, p and R on the quasi-static law, isentropic rho: a jump of R
    // from 3.2 R0 to R0 between two cells (area x10) drove the MUSCL-HLLC transport to NaN at p4/p1 = 2.8
    auto driverPressure = [p4](double s) { return kP1 + (p4 - kP1) * 0.5 * (1.0 - std::tanh((s - kDriver) / 0.03)); };
    tube.setState([&](double s) { return equilibriumRadius(w, driverPressure(s)); },
                  [&](double s) {
                      const double p = driverPressure(s);
                      return GasPrimitive{kRho1 * std::pow(p / kP1, 1.0 / kGamma), 0.0, p};
                  });
    const double tEnd = 2.2 / std::sqrt(kGamma * kP1 / kRho1); // the fastest front stays inside the tube
    std::vector<double> times;
    std::vector<GasFields> snaps;
    for (int k = 1; k <= 8; ++k)
    {
        tube.advanceTo(tEnd * (0.3 + 0.7 * k / 8.0));
        times.push_back(tube.time());
        snaps.push_back(tube.gas().fields());
    }
    const double front = leadingShockPosition(snaps.back(), kP1 + 0.05 * (p4 - kP1));
    const double p2 = meanPressure(snaps.back(), front - 0.7, front - 0.35); // behind the spread front
    std::vector<double> x;
    for (const GasFields& f : snaps)
        x.push_back(leadingShockPosition(f, 0.5 * (kP1 + p2)));
    if (!profilePath.empty())
    {
        FILE* out = unilag::study::openOutput("unilag_tube_wall_shock", profilePath);
        const WallFields wf = tube.wall().fields();
        std::fprintf(out, "s,p,rho,u,R\n");
        const GasFields& f = snaps.back();
        for (size_t j = 0; j < f.s.size(); ++j)
            std::fprintf(out, "%.6g,%.8g,%.8g,%.8g,%.8g\n", f.s[j], f.p[j], f.rho[j], f.u[j], wf.radius[j]);
        std::fclose(out);
    }
    return ShockResult{p4, p2, slope(times, x)};
}

} // namespace

int main(int argc, char* argv[])
{
    Kokkos::ScopeGuard guard(argc, argv);
    std::setvbuf(stdout, nullptr, _IONBF, 0);
    const char* program = "unilag_tube_wall_shock";
    const std::string dir = unilag::study::outputFolder(program, argc > 1 ? argv[1] : ".");
    const int cells = argc > 2 ? unilag::study::integerArg(program, "CELLS", argv[2], 2) : 800;
    const WallCoefficients w = wallCoefficients(latex(), kP1);
    const double a1 = std::sqrt(kGamma * kP1 / kRho1), c1 = compliantSpeed(w, kRho1, kP1, kGamma);
    std::printf("latex wall: a = %.5g kg/m, b = %.5g N/m^2, c = %.3g N s/m^2, bulge limit p - p_ext = %.4g Pa\n",
                w.a, w.b, w.c, w.b / (2.0 * 3.14159265358979323846));
    std::printf("air: a1 = %.2f m/s, compliant c1 = %.2f m/s\n", a1, c1);
    FILE* out = unilag::study::openOutput(program, dir + "/tube_wall_shock_mach.csv");
    std::fprintf(out, "p4_over_p1,p2_over_p1,shock_speed,mach_a1,mach_c1,mach_rigid_relation\n");
    for (double ratio : {1.05, 1.1, 1.2, 1.35, 1.5, 1.75, 2.0, 2.25, 2.5, 2.8})
    {
        const bool profile = ratio == 2.0;
        ShockResult r{};
        try
        {
            r = runShockTube(w, ratio * kP1, cells, profile ? dir + "/tube_wall_shock_profile.csv" : std::string());
        }
        catch (const std::exception& e) // the wall failing near its bulge limit: say so, go on
        {
            std::printf("p4/p1 %.2f: failed (%s)\n", ratio, e.what());
            continue;
        }
        const double rigid = shockMachFromPressureRatio(r.p2 / kP1, kGamma);
        std::printf("p4/p1 %.2f: p2/p1 %.4f, U_s %.2f m/s, U_s/a1 %.4f, U_s/c1 %.4f (rigid tube at this p2/p1: %.4f)\n",
                    ratio, r.p2 / kP1, r.speed, r.speed / a1, r.speed / c1, rigid);
        std::fprintf(out, "%.4f,%.6f,%.6f,%.6f,%.6f,%.6f\n", ratio, r.p2 / kP1, r.speed, r.speed / a1, r.speed / c1,
                     rigid);
    }
    std::fclose(out);
    return 0;
}
