//! Threads per rank from the affinity masks of the node's ranks (ThreadCount.hpp).
#include "core/ThreadCount.hpp"

#include <sched.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace unilag
{

namespace
{

cpu_set_t affinityMask()
{
    cpu_set_t mask;
    CPU_ZERO(&mask);
    if (sched_getaffinity(0, sizeof(mask), &mask) != 0 || CPU_COUNT(&mask) == 0)
        CPU_SET(0, &mask); // unknown: one CPU, the safe side
    return mask;
}

//! The first number of OMP_NUM_THREADS ("4" or "4,2"), 0 when unset or not a positive number.
int ompNumThreads()
{
    const char* env = std::getenv("OMP_NUM_THREADS");
    if (env == nullptr)
        return 0;
    const long n = std::strtol(env, nullptr, 10);
    return n > 0 ? int(n) : 0;
}

} // namespace

ThreadCount threadsPerRank(int requested, MPI_Comm world)
{
    MPI_Comm node;
    MPI_Comm_split_type(world, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int nodeRanks = 1;
    MPI_Comm_size(node, &nodeRanks);

    // Every rank of the node sees every mask: ranks pinned to disjoint cores share none, unpinned ranks share all.
    const cpu_set_t mine = affinityMask();
    std::vector<cpu_set_t> masks(nodeRanks);
    MPI_Allgather(&mine, sizeof(cpu_set_t), MPI_BYTE, masks.data(), sizeof(cpu_set_t), MPI_BYTE, node);
    int sharers = 0;
    cpu_set_t nodeCpus;
    CPU_ZERO(&nodeCpus);
    for (cpu_set_t& m : masks)
    {
        cpu_set_t both;
        CPU_AND(&both, &m, &mine);
        sharers += CPU_COUNT(&both) > 0;
        CPU_OR(&nodeCpus, &nodeCpus, &m);
    }

    ThreadCount count;
    const int fromEnv = ompNumThreads();
    if (requested > 0)
        count.threads = requested;
    else if (fromEnv > 0)
        count.threads = fromEnv;
    else
        count.threads = std::max(1, CPU_COUNT(&mine) / std::max(1, sharers));

    int nodeThreads = 0, mostThreads = 0; // ranks alone may outnumber the cores: MPI runs that, OpenMP does not
    MPI_Allreduce(&count.threads, &nodeThreads, 1, MPI_INT, MPI_SUM, node);
    MPI_Allreduce(&count.threads, &mostThreads, 1, MPI_INT, MPI_MAX, node);
    const int nodeCores = CPU_COUNT(&nodeCpus);
    int worldRank = 0;
    MPI_Comm_rank(world, &worldRank);
    if (worldRank == 0 && mostThreads > 1 && nodeThreads > nodeCores)
        count.warning = std::to_string(nodeRanks) + " rank(s) of this node run " + std::to_string(nodeThreads) +
                        " threads on the " + std::to_string(nodeCores) +
                        " CPU(s) they may run on; threads that outnumber the CPUs spin at OpenMP barriers and run "
                        "many times slower (leave --threads and OMP_NUM_THREADS unset to share the CPUs, or give "
                        "each rank T CPUs: mpirun --map-by slot:PE=T)";
    MPI_Comm_free(&node);
    return count;
}

} // namespace unilag
