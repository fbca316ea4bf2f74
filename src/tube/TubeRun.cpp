#include "tube/TubeRun.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Mpi.hpp"
#include "io/OutputFolder.hpp"
#include "solver/Summary.hpp"
#include "tube/ArteryRun.hpp"
#include "tube/GasRun.hpp"
#include "tube/LinearStability.hpp"
#include "tube/TubeScene.hpp"
#include "tube/TubeTimeRun.hpp"

#ifndef UNILAG_SOURCE_DIR
#define UNILAG_SOURCE_DIR "."
#endif

namespace unilag
{
namespace
{

namespace fs = std::filesystem;
using namespace tube;

constexpr double kPi = 3.14159265358979323846;

//! The kind of the first instability, as it is stored in the exchanged table and written in the CSV.
enum Kind
{
    KindNone = 0,
    KindFlutter = 1,
    KindDivergence = 2
};
const char* kindName(int k)
{
    return k == KindFlutter ? "flutter" : k == KindDivergence ? "divergence" : "none";
}

//! One row of stability.csv: beta, u_cf, omega_cf, kind, u_cd, the unstable mode (unstableMode; 0: none).
constexpr int kRowWidth = 6;

/*! The results of every beta as flat tables of doubles, so that the ranks' shares add up into rank 0's copy
 *  (each rank fills only its own rows; the others stay 0). */
struct StudyTables
{
    std::vector<double> rows; //!< nBeta x kRowWidth
    std::vector<double> loci; //!< nBeta x points x (1 + 2 modes): u, then Re omega, Im omega of each mode
    int points = 0, modes = 0;
    int lociWidth() const { return 1 + 2 * modes; }
};


//! Divergence applies where no end is free (a free end makes the flow force a follower force).
bool supportedBothEnds(const TubeScene& scene)
{
    return scene.left != EndCondition::Free && scene.right != EndCondition::Free;
}

//! The study at one beta: its row and its loci (the lowest modes' omega for u in [0, factor u_cf]).
void studyOneBeta(const TubeScene& scene, int index, StudyTables& t)
{
    const StabilityStudy& st = scene.stability;
    const double beta = st.beta[index];
    const LinearStability stability(sceneDiscretisation(scene), beta);
    const Onset onset = stability.firstInstability({st.speedMax, st.speedStep, st.tolerance});
    double* row = &t.rows[std::size_t(index) * kRowWidth];
    row[0] = beta;
    row[1] = onset.found ? onset.speed : std::nan("");
    row[2] = onset.found ? onset.frequency : std::nan("");
    row[3] = !onset.found ? KindNone : onset.divergence ? KindDivergence : KindFlutter;
    row[4] = supportedBothEnds(scene) ? stability.divergenceSpeed() : std::nan("");
    row[5] = unstableMode(stability, onset);

    const double uEnd = onset.found ? st.locusSpeedFactor * onset.speed : st.speedMax;
    std::vector<double> speeds(t.points);
    for (int p = 0; p < t.points; ++p)
        speeds[p] = uEnd * p / (t.points - 1);
    const std::vector<std::vector<Mode>> loci = trackModes(stability, speeds, t.modes);
    for (int p = 0; p < t.points; ++p)
    {
        double* out = &t.loci[(std::size_t(index) * t.points + p) * t.lociWidth()];
        out[0] = speeds[p];
        for (int m = 0; m < t.modes; ++m)
        {
            const bool have = m < int(loci[p].size());
            out[1 + 2 * m] = have ? loci[p][m].omega().real() : std::nan("");
            out[2 + 2 * m] = have ? loci[p][m].omega().imag() : std::nan("");
        }
    }
}

//! Every beta, round-robin over the ranks (cost grows with beta), summed into rank 0.
StudyTables runStudy(const TubeScene& scene, MPI_Comm comm)
{
    const int nBeta = int(scene.stability.beta.size()), rank = mpi::rank(comm), size = mpi::size(comm);
    StudyTables t;
    t.points = scene.stability.locusPoints;
    t.modes = scene.stability.locusModes;
    t.rows.assign(std::size_t(nBeta) * kRowWidth, 0.0);
    t.loci.assign(std::size_t(nBeta) * t.points * t.lociWidth(), 0.0);
    for (int i = rank; i < nBeta; i += size)
        studyOneBeta(scene, i, t);
    // 0 + x is exact (also for NaN and inf), so the sum is each owner's values: the same on any number of ranks
    for (auto* v : {&t.rows, &t.loci})
        MPI_Reduce(rank == 0 ? MPI_IN_PLACE : v->data(), v->data(), int(v->size()), MPI_DOUBLE, MPI_SUM, 0, comm);
    return t;
}

/*! --check: each beta's onset again on a twice finer discretisation (elements x2, modes x1.5) must agree within
 *  1e-3 relative (the study is converged in the discretisation), and the onset kind must be the same. The failures,
 *  gathered on rank 0 (each rank checks its own betas). Collective. */
std::vector<std::string> convergenceCheck(const TubeScene& scene, const StudyTables& t, MPI_Comm comm)
{
    const StabilityStudy& st = scene.stability;
    const int nBeta = int(st.beta.size()), rank = mpi::rank(comm), size = mpi::size(comm);
    TubeDiscretisation fine = sceneDiscretisation(scene);
    fine.elements *= 2;
    fine.modes = fine.modes > 0 ? fine.modes + fine.modes / 2 : 0;
    std::vector<double> fineSpeed(nBeta, 0.0);
    for (int i = rank; i < nBeta; i += size)
    {
        const Onset onset = LinearStability(fine, st.beta[i]).firstInstability({st.speedMax, st.speedStep, st.tolerance});
        fineSpeed[i] = onset.found ? onset.speed : -1.0;
    }
    MPI_Reduce(rank == 0 ? MPI_IN_PLACE : fineSpeed.data(), fineSpeed.data(), nBeta, MPI_DOUBLE, MPI_SUM, 0, comm);
    std::vector<std::string> fails;
    for (int i = 0; rank == 0 && i < nBeta; ++i)
    {
        const double coarse = t.rows[std::size_t(i) * kRowWidth + 1], finer = fineSpeed[i];
        const bool foundCoarse = coarse == coarse, foundFine = finer >= 0.0;
        const double change = foundCoarse && foundFine ? std::abs(finer - coarse) / coarse : 0.0;
        if (foundCoarse != foundFine || change > 1e-3)
            fails.push_back("beta = " + jsonNumber(st.beta[i]) + ": onset u = " + jsonNumber(coarse) + " with " +
                            std::to_string(st.elements) + " elements but " + jsonNumber(finer) + " with " +
                            std::to_string(fine.elements) + " (relative change " + jsonNumber(change) +
                            " > 1e-3): refine stability.elements / stability.modes");
    }
    return fails;
}

std::string csvNumber(double v)
{
    std::ostringstream os;
    os << std::setprecision(10) << v; // nan and inf print as such; numpy and pandas read them
    return os.str();
}

void writeStabilityCsv(const TubeScene& scene, const StudyTables& t, const std::string& file)
{
    std::ofstream out(file);
    out << "beta,u_cf,omega_cf,instability,u_cd";
    if (scene.hasPhysical)
        out << ",U_cf_m_per_s,f_cf_hz";
    out << ",mode\n";
    const PhysicalTube& p = scene.physical;
    for (std::size_t i = 0; i < scene.stability.beta.size(); ++i)
    {
        const double* r = &t.rows[i * kRowWidth];
        out << csvNumber(r[0]) << ',' << csvNumber(r[1]) << ',' << csvNumber(r[2]) << ',' << kindName(int(r[3])) << ','
            << csvNumber(r[4]);
        if (scene.hasPhysical)
            out << ',' << csvNumber(r[1] * p.velocityScale()) << ',' << csvNumber(r[2] / (2 * kPi * p.timeScale()));
        out << ',' << int(r[5]) << "\n";
    }
    io::finishOutput(out, file);
}

void writeLociCsv(const TubeScene& scene, const StudyTables& t, const std::string& file)
{
    std::ofstream out(file);
    out << "beta,u";
    for (int m = 0; m < t.modes; ++m)
        out << ",re_omega_" << m + 1 << ",im_omega_" << m + 1;
    out << "\n";
    for (std::size_t i = 0; i < scene.stability.beta.size(); ++i)
        for (int p = 0; p < t.points; ++p)
        {
            const double* r = &t.loci[(i * t.points + p) * t.lociWidth()];
            out << csvNumber(scene.stability.beta[i]);
            for (int c = 0; c < t.lociWidth(); ++c)
                out << ',' << csvNumber(r[c]);
            out << "\n";
        }
    io::finishOutput(out, file);
}

//! stability.png from the two CSVs (matplotlib); a missing python is a warning, not a failed run.
bool runPlotScript(const std::string& dir)
{
    const std::string script = std::string(UNILAG_SOURCE_DIR) + "/apps/tube_stability_plot.py";
    const std::string command = "/usr/bin/python3 '" + script + "' '" + dir + "'";
    if (std::system(command.c_str()) != 0)
    {
        std::fprintf(stderr, "unilag: warning: %s failed; stability.png not written\n", command.c_str());
        return false;
    }
    return true;
}

//! The geometric model's ratios (docs/tube-model.md 7.2) and its area change.
void writeGeometric(Summary& s, const PhysicalTube& p)
{
    const GeometricParameters g = p.geometricParameters();
    const double cutoff = g.shear > 0.0 && g.rotary > 0.0 ? 1.0 / std::sqrt(g.shear * g.rotary) : std::nan("");
    s.object("geometric",
             {{"slenderness", jsonNumber(p.slenderness())},
              {"radius_of_gyration", jsonNumber(p.radiusOfGyration())},
              {"shear", jsonNumber(g.shear)},
              {"extension", jsonNumber(g.extension)},
              {"rotary_inertia", jsonNumber(g.rotary)},
              {"area_change_m2", jsonNumber(p.areaChange)},
              {"area_change_per_outer_radius2", jsonNumber(p.areaChange / (p.outerRadius * p.outerRadius))},
              {"area_change_ratio", jsonNumber(g.areaChange)},
              {"area_change_pressure", p.areaPressure == AreaPressure::Dynamic ? "\"dynamic\"" : "\"static\""},
              {"area_stiffening_per_u2", jsonNumber(g.areaStiffening())},
              {"frequency_cutoff", jsonNumber(cutoff)}});
}

void writeSummary(const TubeScene& scene, const StudyTables& t, int ranks, double wall, bool plotted,
                  const std::string& file)
{
    Summary s;
    s.text("scene", scene.file).text("title", scene.name).text("status", "completed");
    const bool geometric = scene.model == TubeModel::Geometric;
    s.text("solver", "tube linear stability").text("model", geometric ? "geometric" : "euler_bernoulli");
    s.object("ends", {{"left", "\"" + std::string(endName(scene.left)) + "\""},
                      {"right", "\"" + std::string(endName(scene.right)) + "\""}});
    s.integer("elements", scene.stability.elements).integer("modes", scene.stability.modes);
    s.text("sign_convention", "eta ~ exp(i omega tau); unstable where Im(omega) < 0");
    Summary::Pairs ucf, wcf, mode;
    for (std::size_t i = 0; i < scene.stability.beta.size(); ++i)
    {
        const std::string key = csvNumber(scene.stability.beta[i]);
        ucf.emplace_back(key, jsonNumber(t.rows[i * kRowWidth + 1]));
        wcf.emplace_back(key, jsonNumber(t.rows[i * kRowWidth + 2]));
        mode.emplace_back(key, std::to_string(int(t.rows[i * kRowWidth + 5])));
    }
    s.object("u_cf", ucf).object("omega_cf", wcf).object("unstable_mode", mode);
    if (supportedBothEnds(scene))
        s.number("u_cd", t.rows.empty() ? std::nan("") : t.rows[4]);
    if (scene.hasPhysical)
    {
        const PhysicalTube& p = scene.physical;
        s.object("physical", {{"EI", jsonNumber(p.bendingStiffness())},
                              {"fluid_mass_per_length", jsonNumber(p.fluidMassPerLength())},
                              {"wall_mass_per_length", jsonNumber(p.wallMassPerLength())},
                              {"beta", jsonNumber(p.massRatio())},
                              {"velocity_scale", jsonNumber(p.velocityScale())},
                              {"time_scale", jsonNumber(p.timeScale())}});
    }
    if (geometric)
        writeGeometric(s, scene.physical);
    s.integer("ranks", ranks).number("wall_seconds", wall);
    s.raw("plot", plotted ? "\"stability.png\"" : "null");
    s.write(file);
}

//! Rank 0's output; returns an error message (the folder could not be made) or "".
std::string writeOutput(const TubeScene& scene, const StudyTables& t, int ranks, double wall)
{
    const std::string dir = scene.outputDirectory;
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec)
        return scene.file + ": key 'output.directory': cannot create '" + dir + "': " + ec.message();
    writeTubeScene(scene, dir + "/scene.yaml");
    writeStabilityCsv(scene, t, dir + "/stability.csv");
    writeLociCsv(scene, t, dir + "/stability_loci.csv");
    const bool plotted = scene.plot && runPlotScript(dir);
    writeSummary(scene, t, ranks, wall, plotted, dir + "/summary.json");
    return "";
}

} // namespace

int runTube(const std::string& scenePath, const std::vector<std::string>& overrides, const std::string& outputDir,
            bool check, bool quiet, MPI_Comm comm)
{
    const auto start = std::chrono::steady_clock::now();
    const int rank = mpi::rank(comm);
    TubeScene scene;
    std::string error;
    try
    {
        scene = readTubeScene(scenePath, overrides);
        if (!outputDir.empty())
            scene.outputDirectory = outputDir;
        scene.progress = !quiet;
        // as for continuum runs (Run.cpp): an output folder that cannot be written is bad input, before any work
        const std::string problem = rank == 0 ? io::outputFolderProblem(scene.outputDirectory) : std::string();
        if (!problem.empty())
            throw InputError((outputDir.empty() ? scene.file + ": key 'output.directory'" : std::string("--output")) +
                             " '" + scene.outputDirectory + "': " + problem);
    }
    catch (const InputError& e)
    {
        error = e.what();
    }
    error = mpi::firstMessage(comm, error);
    if (!error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
        return ExitInput;
    }
    if (scene.hasDynamics)
        return runTubeDynamics(scene, check, comm);
    if (scene.hasGas)
        return runTubeGas(scene, check, comm);
    if (scene.hasArtery)
        return runTubeArtery(scene, check, comm);
    const StudyTables tables = runStudy(scene, comm);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (rank == 0)
        error = writeOutput(scene, tables, mpi::size(comm), wall);
    error = mpi::firstMessage(comm, error);
    if (!error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
        return ExitInput;
    }
    if (rank == 0)
        std::printf("unilag: %s: tube linear stability at %zu mass ratio(s) on %d rank(s) in %.3g s; output in %s\n",
                    scene.name.c_str(), scene.stability.beta.size(), mpi::size(comm), wall,
                    scene.outputDirectory.c_str());
    if (!check)
        return ExitOk;
    const std::vector<std::string> fails = convergenceCheck(scene, tables, comm);
    return reportCheck(fails, rank == 0); // the failures are gathered on rank 0
}

} // namespace unilag
