/*! \file Types.hpp
 *  \brief The Tpetra typedefs every layer above the kernels shares. Kernels never include this file (they stay
 *  Kokkos-only); the input error and exit codes are in core/Errors.hpp.
 */
#pragma once

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

} // namespace unilag
