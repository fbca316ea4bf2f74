// The guard around gmsh (src/mesh/GmshCrashGuard.*), independent of which gmsh inputs crash: inside its scope a
// fatal signal or std::terminate exits with ExitInput and one line naming the file; after it, the signal's previous
// handling is back. The regression tests error_gmsh_crash / error_gmsh_throw check the same on real gmsh crashes.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <exception>

#include "core/Errors.hpp"
#include "mesh/GmshCrashGuard.hpp"

namespace
{

const char* kMessage = "^unilag: error: shapes/part\\.geo: gmsh crashed reading or meshing it \\(.*\\)\n$";

TEST(GmshCrashGuard, SegmentationFaultIsBadInputNamingTheFile)
{
    EXPECT_EXIT(
        {
            const unilag::GmshCrashGuard guard("shapes/part.geo");
            std::raise(SIGSEGV);
        },
        ::testing::ExitedWithCode(unilag::ExitInput), kMessage);
}

TEST(GmshCrashGuard, TerminateIsBadInputNamingTheFile)
{
    EXPECT_EXIT(
        {
            const unilag::GmshCrashGuard guard("shapes/part.geo");
            std::terminate();
        },
        ::testing::ExitedWithCode(unilag::ExitInput), kMessage);
}

extern "C" void exitSeven(int)
{
    std::_Exit(7);
}

[[noreturn]] void exitEight()
{
    std::_Exit(8);
}

// A handler set before the guard acts again after it: the guard restores it rather than the default.
TEST(GmshCrashGuard, HandlersComeBackAfterItsScope)
{
    EXPECT_EXIT(
        {
            std::signal(SIGSEGV, exitSeven);
            {
                const unilag::GmshCrashGuard guard("shapes/part.geo");
            }
            std::raise(SIGSEGV);
        },
        ::testing::ExitedWithCode(7), "");
    EXPECT_EXIT(
        {
            std::set_terminate(exitEight);
            {
                const unilag::GmshCrashGuard guard("shapes/part.geo");
            }
            std::terminate();
        },
        ::testing::ExitedWithCode(8), "");
}

} // namespace
