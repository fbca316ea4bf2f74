/*! \file RankZero.hpp
 *  \brief A tube run is one rank's work (a tube has a few hundred nodes; threads do the parallel part): rank 0
 *  runs it, the other ranks wait for its exit code.
 */
#pragma once

#include <cstdio>
#include <exception>
#include <string>

#include "core/Errors.hpp"
#include "core/Mpi.hpp"

namespace unilag::tube
{

/*! Calls run() on rank 0 of comm and returns its exit code on every rank. An exception (bad input found while
 *  setting the run up: an unknown state, a tube without a critical speed) becomes one message on stderr and
 *  ExitInput. An OutputError (a file that cannot be written) goes on from rank 0, once the others have the code,
 *  to the CLI, which says so and ends the process (HDF5 may hold a file it could not close). Collective. */
template <class Run> int onRankZero(MPI_Comm comm, Run&& run)
{
    int code = ExitOk;
    std::string error;
    std::exception_ptr output;
    if (mpi::rank(comm) == 0)
    {
        try
        {
            code = run();
        }
        catch (const OutputError&)
        {
            output = std::current_exception();
            code = ExitInput;
        }
        catch (const std::exception& e)
        {
            error = e.what();
            code = ExitInput;
        }
    }
    MPI_Bcast(&code, 1, MPI_INT, 0, comm);
    if (output)
        std::rethrow_exception(output);
    if (!error.empty())
        std::fprintf(stderr, "unilag: error: %s\n", error.c_str());
    return code;
}

} // namespace unilag::tube
