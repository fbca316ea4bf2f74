/*! \file Run.hpp
 *  \brief Running one scene: mesh, distribution, time loop, output, summary and self-check.
 */
#pragma once

#include <string>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "io/Scene.hpp"

namespace unilag
{

struct RunOptions
{
    bool check = false; //!< assert conservation and the scene's error bounds
    int threads = 1;    //!< Kokkos threads (reported)
    bool progress = true;
};

//! Exit codes of the CLI.
enum ExitCode : int
{
    ExitOk = 0,
    ExitInput = 2,    //!< bad scene or mesh
    ExitCheck = 3,    //!< --check failed
    ExitUnstable = 4  //!< the run went unstable and was stopped
};

/*! \brief Run a validated scene on all ranks of comm; returns an ExitCode. Messages go to stderr on rank 0. */
int runScene(const Scene& scene, const RunOptions& options, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

} // namespace unilag
