#include "mesh/GmshCrashGuard.hpp"

#include <algorithm>
#include <array>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>

#include <unistd.h>

#include "core/Errors.hpp"

namespace unilag
{

namespace
{

constexpr std::array<int, 5> guardedSignals{SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
std::array<struct sigaction, guardedSignals.size()> previous;

// The handler may only call async-signal-safe functions: the message is composed before, write(2) prints it.
char message[1024];
std::size_t messageLength = 0;
std::terminate_handler previousTerminate = nullptr;

extern "C" void reportGmshCrash(int)
{
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, message, messageLength);
    ::_exit(ExitInput);
}

// gmsh also throws from its own threads (a std::string, with Mesh.RandomFactor = 0.5 in 3D): the runtime's
// terminate handler would print that before SIGABRT reached reportGmshCrash; this one prints the message only.
void reportGmshTermination()
{
    reportGmshCrash(SIGABRT);
}

// gmsh's Exit command (and its own fatal errors) end the process through exit(0): unilag returned 0 with no output.
bool guardActive = false;
char exitMessage[1024];
std::size_t exitMessageLength = 0;

extern "C" void reportGmshExit()
{
    if (!guardActive)
        return;
    [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, exitMessage, exitMessageLength);
    ::_exit(ExitInput);
}

} // namespace

GmshCrashGuard::GmshCrashGuard(const std::string& source)
{
    const std::string text = "unilag: error: " + printable(source, 400) +
                             ": gmsh crashed reading or meshing it (gmsh 4.8 dies on some options it accepts, such as "
                             "Mesh.Algorithm = 8 in 2D: change the mesh options, or give a .msh meshed elsewhere)\n";
    messageLength = std::min(text.size(), sizeof(message));
    std::memcpy(message, text.data(), messageLength);
    struct sigaction action = {};
    action.sa_handler = reportGmshCrash;
    sigemptyset(&action.sa_mask);
    for (std::size_t s = 0; s < guardedSignals.size(); ++s)
        sigaction(guardedSignals[s], &action, &previous[s]);
    previousTerminate = std::set_terminate(reportGmshTermination);
    const std::string ended = "unilag: error: " + printable(source, 400) +
                              ": gmsh ended the process while reading or meshing it (an Exit command in the .geo?)\n";
    exitMessageLength = std::min(ended.size(), sizeof(exitMessage));
    std::memcpy(exitMessage, ended.data(), exitMessageLength);
    static const bool registered = std::atexit(reportGmshExit) == 0;
    guardActive = registered;
}

GmshCrashGuard::~GmshCrashGuard()
{
    guardActive = false;
    std::set_terminate(previousTerminate);
    for (std::size_t s = 0; s < guardedSignals.size(); ++s)
        sigaction(guardedSignals[s], &previous[s], nullptr);
}

} // namespace unilag
