//! unilag command line: `unilag run SCENE.yaml [--set key=value ...] [--output DIR] [--check] [--threads N]`.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <mpi.h>

#include <Kokkos_Core.hpp>
#include <Tpetra_Core.hpp>

#include "config/Scene.hpp"
#include "core/ThreadCount.hpp"
#include "solver/Run.hpp"
#include "tube/TubeRun.hpp"
#include "tube/TubeScene.hpp"
#include "unilag/Types.hpp"

namespace
{

const char* usage = R"(unilag: unified Lagrangian continuum mechanics (GPR model), cell-centred finite volumes, and
tubes conveying fluid.

usage:
  unilag run SCENE.yaml [options]     run a scene (works under mpirun -np N): a continuum scene, or a tube scene
                                      (one with a `tube:` section; today its linear stability study)
  unilag --help                       this text

options:
  --set KEY=VALUE    override a scene key; nested keys with dots, e.g. --set mesh.size=0.02 --set time.end=0.5
  --output DIR       output folder (default: the scene's output.directory)
  --check            continuum: assert conservation (momentum, energy, GCL, the cells' tiling), the force
                     balance at every node and no work by walls, to round-off, and the scene's error bounds;
                     tube: every onset speed converged (a twice finer discretisation agrees within 1e-3);
                     exit 3 with the failing figure otherwise
  --restart FILE     continuum: continue the run from a checkpoint (output.checkpoint_interval writes
                     <DIR>/checkpoint.h5) on any number of ranks; the output series goes on in DIR
  --threads N        OpenMP threads per rank, at most 512 (default: OMP_NUM_THREADS if set, else the CPUs this
                     rank may run on, divided among the node's ranks that may run on them)
  --quiet            no progress line

output: <DIR>/unilag.xmf (open in ParaView), unilag_NNNNNN.h5, scene.yaml (resolved scene), summary.json,
        steps.csv. Once the input is validated, a run removes these files of an earlier run from DIR (by name:
        unilag.xmf, unilag_NNNNNN.h5/.xmf, summary.json, steps.csv, scene.yaml) and nothing else.
exit codes: 0 ok, 2 bad input (or output that cannot be written), 3 check failed, 4 the run went unstable
            (with a diagnosis), 5 stopped by time.max_steps before the end time, 6 stopped by SIGTERM / SIGINT
            (after writing <DIR>/checkpoint.h5).
)";

struct Args
{
    std::string scene, output, restart;
    std::vector<std::string> sets;
    bool check = false, quiet = false, help = false;
    int threads = -1;
    std::string error;
};

Args parse(int argc, char** argv)
{
    Args a;
    int i = 1;
    if (argc < 2)
    {
        a.error = "missing command";
        return a;
    }
    const std::string cmd = argv[i++];
    if (cmd == "--help" || cmd == "-h" || cmd == "help")
    {
        a.help = true;
        return a;
    }
    if (cmd != "run")
    {
        a.error = "unknown command '" + cmd + "'";
        return a;
    }
    for (; i < argc; ++i)
    {
        const std::string s = argv[i];
        auto value = [&](const char* opt) -> std::string {
            if (i + 1 >= argc)
            {
                a.error = std::string(opt) + " needs a value";
                return "";
            }
            return argv[++i];
        };
        if (s == "--set")
            a.sets.push_back(value("--set"));
        else if (s.rfind("--set=", 0) == 0)
            a.sets.push_back(s.substr(6));
        else if (s == "--output" || s == "--restart")
        {
            (s == "--output" ? a.output : a.restart) = value(s.c_str());
            if (a.error.empty() && argv[i][0] == '\0')
                a.error = s + (s == "--output" ? " needs a folder" : " needs a checkpoint file") +
                          ", found an empty string";
        }
        else if (s == "--check")
            a.check = true;
        else if (s == "--quiet")
            a.quiet = true;
        else if (s == "--help" || s == "-h")
            a.help = true;
        else if (s == "--threads")
        {
            const std::string v = value("--threads");
            char* end = nullptr;
            a.threads = int(std::strtol(v.c_str(), &end, 10));
            if (v.empty() || *end != '\0' || a.threads < 1)
                a.error = "--threads needs a positive integer, found '" + v + "'";
        }
        else if (s.rfind("--kokkos", 0) == 0)
            continue; // Kokkos' own options pass through
        else if (!s.empty() && s[0] == '-')
            a.error = "unknown option '" + s + "'";
        else if (a.scene.empty())
            a.scene = s;
        else
            a.error = "more than one scene given ('" + a.scene + "', '" + s + "')";
        if (!a.error.empty())
            break;
    }
    if (a.error.empty() && a.scene.empty() && !a.help)
        a.error = "run needs a scene file";
    return a;
}

//! A continuum (GPR) scene: read, validated, run. Throws InputError.
int runContinuum(const Args& args, const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
{
    unilag::Scene scene = unilag::readScene(args.scene, args.sets);
    if (!args.output.empty())
    {
        scene.outputDirectory = args.output;
        scene.outputSource = "--output";
    }
    unilag::RunOptions options;
    options.check = args.check;
    options.restart = args.restart;
    options.progress = !args.quiet;
    options.threads = unilag::ExecSpace::concurrency();
    return unilag::runScene(scene, options, comm);
}

} // namespace

int main(int argc, char** argv)
{
    const Args args = parse(argc, argv);
    if (args.help)
    {
        std::fputs(usage, stdout);
        return 0;
    }
    MPI_Init(&argc, &argv);
    int rank;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (!args.error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %s (see unilag --help)\n", args.error.c_str());
        MPI_Finalize();
        return unilag::ExitInput;
    }
    const unilag::ThreadCount threads = unilag::threadsPerRank(args.threads, MPI_COMM_WORLD);
    // Kokkos' OpenMP backend (this Trilinos 13.2 build) crashes above 512 threads a process (520 segfaulted)
    constexpr int maxThreads = 512;
    int mostThreads = threads.threads;
    MPI_Allreduce(MPI_IN_PLACE, &mostThreads, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (mostThreads > maxThreads)
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %d threads a rank (--threads or OMP_NUM_THREADS): at most %d; run "
                                 "more ranks instead\n", mostThreads, maxThreads);
        MPI_Finalize();
        return unilag::ExitInput;
    }
    if (!threads.warning.empty())
        std::fprintf(stderr, "unilag: warning: %s\n", threads.warning.c_str());
    Kokkos::InitArguments kargs;
    kargs.num_threads = threads.threads;
    kargs.disable_warnings = true;
    Kokkos::initialize(kargs);
    int code = 0;
    {
        Tpetra::initialize(&argc, &argv);
        auto comm = Tpetra::getDefaultComm();
        try
        {
            if (unilag::tube::isTubeScene(args.scene) && !args.restart.empty())
                throw unilag::InputError(args.scene + ": --restart: tube scenes have no checkpoints");
            if (unilag::tube::isTubeScene(args.scene))
                code = unilag::runTube(args.scene, args.sets, args.output, args.check, args.quiet, MPI_COMM_WORLD);
            else
                code = runContinuum(args, comm);
        }
        catch (const unilag::InputError& e)
        {
            if (rank == 0)
                std::fprintf(stderr, "unilag: error: %s\n", e.what());
            code = unilag::ExitInput;
        }
        catch (const unilag::OutputError& e)
        {
            if (rank == 0)
                std::fprintf(stderr, "unilag: error: the output could not be written: %s\n", e.what());
            // HDF5 may hold a file it failed to close (disk full), which its clean-up in MPI_Finalize then crashes
            // on (exit 139; h5py #914 reports the same): end here. A dump's error reaches every rank alike; for a
            // file rank 0 writes alone (summary.json, a CSV), its exit makes mpirun end the others
            std::fflush(nullptr);
            std::_Exit(unilag::ExitInput);
        }
        catch (const std::exception& e)
        {
            std::fprintf(stderr, "unilag: internal error on rank %d: %s\n", rank, e.what());
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        Tpetra::finalize();
    }
    Kokkos::finalize();
    MPI_Finalize();
    return code;
}
