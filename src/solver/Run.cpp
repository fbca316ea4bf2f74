// The dispatch of a scene to the solver compiled for its dimension and physics variant.
#include "solver/Run.hpp"

#include <cstdio>

#include "core/Mpi.hpp"
#include "io/OutputFolder.hpp"
#include "mesh/DistributedMesh.hpp"
#include "mesh/GlobalMesh.hpp"

namespace unilag
{

int runScene(const Scene& scene, const RunOptions& options, const Teuchos::RCP<const Comm>& comm)
{
    MPI_Comm mpiComm = mpi::rawComm(comm);
    const int rank = mpi::rank(mpiComm);
    GlobalMesh global;
    std::string error;
    if (rank == 0)
    {
        try
        {
            // Before the mesh (which can take a while): a folder the outputs cannot go to is bad input too.
            const std::string problem = io::outputFolderProblem(scene.outputDirectory);
            if (!problem.empty())
                throw InputError(scene.outputSource + " '" + scene.outputDirectory + "': " + problem);
            global = loadMesh(scene);
            matchScene(scene, global);
        }
        catch (const InputError& e)
        {
            error = e.what();
        }
    }
    error = mpi::firstMessage(mpiComm, error);
    if (!error.empty())
    {
        if (rank == 0)
            std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
        return ExitInput;
    }
    auto mesh = DistributedMesh::distribute(global, comm);
    global = GlobalMesh();
    return mesh->dim == 2 ? runScene2D(scene, mesh, options) : runScene3D(scene, mesh, options);
}

} // namespace unilag
