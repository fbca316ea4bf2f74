#include "core/Mpi.hpp"

#include <ctime>
#include <vector>

#include <Teuchos_DefaultMpiComm.hpp>

namespace unilag::mpi
{
namespace
{
double waited = 0.0;
}

double cpuSeconds()
{
    timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double waitSeconds() { return waited; }

WaitTimer::~WaitTimer() { waited += cpuSeconds() - t0_; }

MPI_Comm rawComm(const Teuchos::RCP<const Teuchos::Comm<int>>& comm)
{
    auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm);
    return mpi.is_null() ? MPI_COMM_SELF : (*mpi->getRawMpiComm())();
}

int rank(MPI_Comm comm)
{
    int r;
    MPI_Comm_rank(comm, &r);
    return r;
}

int size(MPI_Comm comm)
{
    int s;
    MPI_Comm_size(comm, &s);
    return s;
}

double allMin(MPI_Comm comm, double v)
{
    WaitTimer wait;
    double r;
    MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MIN, comm);
    return r;
}

double allMax(MPI_Comm comm, double v)
{
    WaitTimer wait;
    double r;
    MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, comm);
    return r;
}

void allMax(MPI_Comm comm, double* v, int n)
{
    WaitTimer wait;
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_MAX, comm);
}

std::vector<double> allGather(MPI_Comm comm, const std::vector<double>& v)
{
    WaitTimer wait;
    std::vector<double> all(v.size() * std::size_t(size(comm)));
    MPI_Allgather(v.data(), int(v.size()), MPI_DOUBLE, all.data(), int(v.size()), MPI_DOUBLE, comm);
    return all;
}

void allSum(MPI_Comm comm, double* v, int n)
{
    WaitTimer wait;
    MPI_Allreduce(MPI_IN_PLACE, v, n, MPI_DOUBLE, MPI_SUM, comm);
}

long long exclusiveOffset(MPI_Comm comm, long long n)
{
    long long offset = 0;
    MPI_Exscan(&n, &offset, 1, MPI_LONG_LONG, MPI_SUM, comm);
    return rank(comm) == 0 ? 0 : offset; // MPI_Exscan leaves rank 0's result undefined
}

int argMinRank(MPI_Comm comm, double v)
{
    struct
    {
        double value;
        int rank;
    } mine{v, rank(comm)}, global;
    MPI_Allreduce(&mine, &global, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
    return global.rank;
}

std::string firstMessage(MPI_Comm comm, const std::string& local)
{
    WaitTimer wait;
    const int n = size(comm);
    const int mine = int(local.size());
    std::vector<int> lens(n);
    MPI_Allgather(&mine, 1, MPI_INT, lens.data(), 1, MPI_INT, comm);
    for (int p = 0; p < n; ++p)
        if (lens[p] > 0)
        {
            std::string msg = local;
            msg.resize(lens[p]);
            MPI_Bcast(msg.data(), lens[p], MPI_CHAR, p, comm);
            return msg;
        }
    return {};
}

} // namespace unilag::mpi
