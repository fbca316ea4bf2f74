// The GPR solver of every physics variant in 2D.
#include "solver/RunVariant.hpp"

namespace unilag
{

int runScene2D(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options)
{
    return runDim<2>(scene, mesh, options);
}

} // namespace unilag
