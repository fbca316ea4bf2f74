/*! \file GmshCrashGuard.hpp
 *  \brief A crash inside gmsh, reported as bad input. gmsh 4.8 (Debian bookworm's) dies on some inputs it accepts:
 *  a segmentation fault with a .geo that sets Mesh.Algorithm = 8 (Frontal-Delaunay for quads) in 2D, an exception
 *  thrown from its own threads (std::terminate) with Mesh.RandomFactor = 0.5 in 3D; neither reaches the caller as an
 *  exception. While a guard lives, a fatal signal or std::terminate prints one line naming the file and exits with
 *  ExitInput, before any output exists (meshing precedes it); so does gmsh ending the process with exit() (a .geo
 *  with Exit;), which returned 0 without a word.
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
