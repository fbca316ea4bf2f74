// Unit-test main (Cabana pattern, Tpetra flavour): MPI + Kokkos through Tpetra's scope guard.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

int main(int argc, char* argv[])
{
    Tpetra::ScopeGuard scope(&argc, &argv);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
