/*! \file OutputFolder.hpp
 *  \brief The run's output folder: can it be written (checked before anything is), and the previous run's own
 *  outputs removed from it at the start of a new run.
 */
#pragma once

#include <fstream>
#include <string>
#include <vector>

namespace unilag::io
{

/*! \brief Why \p dir cannot serve as an output folder ("" if it can): a path through a regular file, a folder
 *  that cannot be created or written. Creates nothing that remains (it probes by creating and removing an entry). */
std::string outputFolderProblem(const std::string& dir);

/*! \brief Removes from \p dir the files a run writes, by their names: unilag.xmf, unilag_NNNNNN.h5 and
 *  unilag_NNNNNN.xmf (the dumps), summary.json, steps.csv, scene.yaml, checkpoint.h5, balance.csv. Nothing else is
 *  touched (not other files, not folders). Returns the names removed. */
std::vector<std::string> removeRunOutputs(const std::string& dir);

/*! \brief Closes an output file written through \p out; throws OutputError naming \p file if a write or the close
 *  failed (a folder in its place, a full disk), failures a stream otherwise keeps to itself. */
void finishOutput(std::ofstream& out, const std::string& file);

} // namespace unilag::io
