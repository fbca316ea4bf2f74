// Threads per rank (core/ThreadCount.hpp): the default never lets a node's OpenMP threads outnumber its CPUs, which
// ran the impact scene 50x slower (4 ranks of 2 threads on 2 cores); --threads and OMP_NUM_THREADS still decide.
#include <gtest/gtest.h>

#include <sched.h>

#include <cstdlib>
#include <string>

#include "core/ThreadCount.hpp"

namespace
{

//! Sets or unsets OMP_NUM_THREADS for one scope, and puts it back.
class OmpNumThreads
{
  public:
    explicit OmpNumThreads(const char* value)
    {
        if (const char* old = std::getenv("OMP_NUM_THREADS"))
            old_ = old, had_ = true;
        if (value)
            setenv("OMP_NUM_THREADS", value, 1);
        else
            unsetenv("OMP_NUM_THREADS");
    }
    ~OmpNumThreads()
    {
        if (had_)
            setenv("OMP_NUM_THREADS", old_.c_str(), 1);
        else
            unsetenv("OMP_NUM_THREADS");
    }

  private:
    std::string old_;
    bool had_ = false;
};

//! The ranks of this node, as ThreadCount sees them; free it after use.
MPI_Comm nodeComm()
{
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    return node;
}

int nodeSum(int v)
{
    MPI_Comm node = nodeComm();
    int sum = 0;
    MPI_Allreduce(&v, &sum, 1, MPI_INT, MPI_SUM, node);
    MPI_Comm_free(&node);
    return sum;
}

//! The CPUs any rank of this node may run on (the union of their affinity masks).
int cpusOfNode()
{
    cpu_set_t mine, all;
    CPU_ZERO(&mine);
    sched_getaffinity(0, sizeof(mine), &mine);
    MPI_Comm node = nodeComm();
    MPI_Allreduce(&mine, &all, int(sizeof(cpu_set_t)), MPI_BYTE, MPI_BOR, node);
    MPI_Comm_free(&node);
    return CPU_COUNT(&all);
}

} // namespace

TEST(ThreadCount, TheDefaultDividesTheNodesCpusAmongItsRanks)
{
    OmpNumThreads unset(nullptr);
    const unilag::ThreadCount count = unilag::threadsPerRank(-1, MPI_COMM_WORLD);
    EXPECT_GE(count.threads, 1);
    const int ranks = nodeSum(1);
    EXPECT_LE(nodeSum(count.threads), std::max(cpusOfNode(), ranks));
    EXPECT_TRUE(count.warning.empty()) << count.warning;
}

TEST(ThreadCount, TheUserDecidesAndIsWarnedOfOversubscription)
{
    const int many = 4 * cpusOfNode();
    {
        OmpNumThreads env("3");
        EXPECT_EQ(unilag::threadsPerRank(-1, MPI_COMM_WORLD).threads, 3);
        EXPECT_EQ(unilag::threadsPerRank(2, MPI_COMM_WORLD).threads, 2); // --threads before the environment
    }
    OmpNumThreads unset(nullptr);
    const unilag::ThreadCount count = unilag::threadsPerRank(many, MPI_COMM_WORLD);
    EXPECT_EQ(count.threads, many);
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    EXPECT_EQ(count.warning.empty(), rank != 0) << "only world rank 0 warns";
}
