/*! \file GmshCrashGuard.hpp
 *  \brief A crash inside gmsh, reported as bad input. gmsh 4.8 (Debian bookworm's) dies with a segmentation fault on
 *  some inputs it accepts, such as a .geo that sets Mesh.Algorithm = 8 (Frontal-Delaunay for quads) in 2D; no
 *  exception reaches the caller. While a guard lives, a fatal signal prints one line naming the file and exits with
 *  ExitInput, before any output exists (meshing precedes it).
 */
#pragma once

#include <string>

namespace unilag
{

class GmshCrashGuard
{
  public:
    /*! Installs the handlers (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, and std::terminate for exceptions that
     *  leave gmsh's threads); source names the file in the message. */
    explicit GmshCrashGuard(const std::string& source);
    //! Restores the handlers there were before (Open MPI's signal handlers, for one).
    ~GmshCrashGuard();
    GmshCrashGuard(const GmshCrashGuard&) = delete;
    GmshCrashGuard& operator=(const GmshCrashGuard&) = delete;
};

} // namespace unilag
