/*! \file TubeRun.hpp
 *  \brief The tube solver's entry point: read a tube scene, run its linear stability study (the mass ratios
 *  split over the ranks), and write stability.csv, stability_loci.csv, summary.json, scene.yaml and
 *  stability.png into the output folder (rank 0 writes).
 */
#pragma once

#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1 // C API only
#endif
#include <mpi.h>

#include <string>
#include <vector>

namespace unilag
{

/*! \brief Run the tube scene at scenePath with `--set` overrides; outputDir (if not empty) replaces the scene's
 *  output.directory. check (--check): every onset speed is converged in the discretisation (a twice finer one
 *  agrees within 1e-3). Collective over comm. Returns the exit code: 0 ok, 2 bad input (one message on stderr
 *  naming the file and key; nothing written), 3 a failed check. */
int runTube(const std::string& scenePath, const std::vector<std::string>& overrides, const std::string& outputDir,
            bool check, bool quiet, MPI_Comm comm);

} // namespace unilag
