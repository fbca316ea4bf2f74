/*! \file Types.hpp
 *  \brief What every layer above the kernels shares: the Tpetra typedefs, the CLI's exit codes and the input
 *  error. Kernels never include this file (they stay Kokkos-only).
 */
#pragma once

#include <stdexcept>

#include <Teuchos_Comm.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include "unilag/Types.hpp"

namespace unilag
{

using Map = Tpetra::Map<LO>;
using GO = Map::global_ordinal_type;
using MV = Tpetra::MultiVector<double, LO, GO>;
using Importer = Tpetra::Import<LO, GO>;
using Comm = Teuchos::Comm<int>;

//! Bad input: the message names the file and the key (or element); the CLI prints it and exits with 2.
class InputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

//! Exit codes of the CLI.
enum ExitCode : int
{
    ExitOk = 0,
    ExitInput = 2,    //!< bad scene or mesh
    ExitCheck = 3,    //!< --check failed
    ExitUnstable = 4  //!< the run went unstable and was stopped
};

} // namespace unilag
