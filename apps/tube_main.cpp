// unilag_tube: a temporary driver of the tube solver (runTube) until `unilag run` dispatches tube scenes to it.
//   unilag_tube SCENE [--set key=value]... [--output DIR]
#include <cstdio>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "tube/TubeRun.hpp"

int main(int argc, char** argv)
{
    MPI_Init(&argc, &argv);
    std::string scene, output, error;
    std::vector<std::string> sets;
    for (int i = 1; i < argc && error.empty(); ++i)
    {
        const std::string a = argv[i];
        if ((a == "--set" || a == "--output") && i + 1 < argc)
            (a == "--set" ? sets.emplace_back() : output) = argv[++i];
        else if (a == "--quiet")
            continue;
        else if (!a.empty() && a[0] != '-' && scene.empty())
            scene = a;
        else
            error = "unexpected argument '" + a + "'";
    }
    if (scene.empty() && error.empty())
        error = "usage: unilag_tube SCENE [--set key=value]... [--output DIR]";
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    int code = unilag::ExitInput;
    if (!error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag_tube: error: %s\n", error.c_str());
    }
    else
        code = unilag::runTube(scene, sets, output, MPI_COMM_WORLD);
    MPI_Finalize();
    return code;
}
