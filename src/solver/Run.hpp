/*! \file Run.hpp
 *  \brief Running one continuum scene: mesh, distribution, then the GPR solver for the scene's dimension and
 *  physics variant.
 */
#pragma once

#include <memory>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "config/Scene.hpp"
#include "core/Errors.hpp"
#include "solver/RunOptions.hpp"

namespace unilag
{

/*! \brief Run a validated scene on all ranks of comm; returns an ExitCode. Messages go to stderr on rank 0. */
int runScene(const Scene& scene, const RunOptions& options, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

class DistributedMesh;
//! The GPR solver in 2D and in 3D for the scene's physics variant (Run2D.cpp, Run3D.cpp). Collective.
int runScene2D(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options);
int runScene3D(const Scene& scene, std::shared_ptr<DistributedMesh> mesh, const RunOptions& options);

} // namespace unilag
