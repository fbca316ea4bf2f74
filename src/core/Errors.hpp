/*! \file Errors.hpp
 *  \brief The input error every reader throws, the CLI's exit codes, and how --check reports.
 */
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace unilag
{

//! Bad input: the message names the file and the key (or element); the CLI prints it and exits with 2.
class InputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

/*! A file of the run's output could not be written (a dump, the XDMF collection): the CLI prints the message and
 *  exits with 2. Every rank throws it alike (the writer shares the outcome), so no rank waits on another. */
class OutputError : public std::runtime_error
{
  public:
    using std::runtime_error::runtime_error;
};

/*! Text read from a file, fit for a one-line message: bytes outside printable ASCII become '?' and more than max
 *  characters are cut (a corrupt file's strings would print raw bytes). */
inline std::string printable(const std::string& text, std::size_t max = 80)
{
    std::string s = text.substr(0, max);
    for (char& c : s)
        if (c < 0x20 || c > 0x7e)
            c = '?';
    return text.size() > max ? s + "..." : s;
}

//! Exit codes of the CLI.
enum ExitCode : int
{
    ExitOk = 0,
    ExitInput = 2,   //!< bad scene or mesh
    ExitCheck = 3,   //!< --check failed
    ExitUnstable = 4, //!< the run went unstable and was stopped
    ExitMaxSteps = 5, //!< time.max_steps stopped the run before its end time
    ExitInterrupted = 6 //!< SIGTERM or SIGINT stopped the run, after a checkpoint
};

/*! --check's verdict: each failed bound as one line on stderr, or "check passed"; printed only where print is
 *  true (rank 0). Returns ExitCheck if any bound failed, else ExitOk. */
inline int reportCheck(const std::vector<std::string>& fails, bool print = true)
{
    if (print)
    {
        for (const auto& f : fails)
            std::fprintf(stderr, "unilag: check failed: %s\n", f.c_str());
        if (fails.empty())
            std::printf("unilag: check passed\n");
    }
    return fails.empty() ? ExitOk : ExitCheck;
}

} // namespace unilag
