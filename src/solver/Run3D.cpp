// The GPR solver of every physics variant in 3D.
#include "solver/RunVariant.hpp"

namespace unilag
{

int runScene3D(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options)
{
    return runDim<3>(scene, mesh, options);
}

} // namespace unilag
