/*! \file Errors.hpp
 *  \brief The input error every reader throws and the CLI's exit codes.
 */
#pragma once

#include <stdexcept>

namespace unilag
{

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
    ExitInput = 2,   //!< bad scene or mesh
    ExitCheck = 3,   //!< --check failed
    ExitUnstable = 4 //!< the run went unstable and was stopped
};

} // namespace unilag
