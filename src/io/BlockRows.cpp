#include "io/BlockRows.hpp"

#include <algorithm>
#include <cstddef>

namespace unilag::io
{
namespace
{

constexpr std::size_t maxCount = std::size_t(1) << 28; //!< doubles per message: an MPI count is an int

template <class T> MPI_Datatype mpiType();
template <> MPI_Datatype mpiType<double>()
{
    return MPI_DOUBLE;
}
template <> MPI_Datatype mpiType<long long>()
{
    return MPI_LONG_LONG;
}

/*! All-to-all of per-destination lists of rows of `width` values: send[r] goes to rank r. Returns what the ranks
 *  sent here, concatenated in rank order, and in count[s] how many rows came from rank s. Counts and offsets are in
 *  rows (an MPI datatype of one row): MPI's int then limits the rows a rank holds, as a local index does, not their
 *  values (27 columns of 80 M rows overflowed an int count of doubles). */
template <class T>
std::vector<T> exchange(MPI_Comm comm, const std::vector<std::vector<T>>& send, std::vector<int>& count, int width = 1)
{
    width = std::max(width, 1); // a table without columns sends no values: counted as rows of one
    const int size = int(send.size());
    std::vector<int> sendCount(size), sendOffset(size, 0), recvOffset(size, 0);
    std::vector<T> flat;
    for (int r = 0; r < size; ++r)
    {
        sendCount[r] = int(send[r].size() / std::size_t(width));
        sendOffset[r] = int(flat.size() / std::size_t(width));
        flat.insert(flat.end(), send[r].begin(), send[r].end());
    }
    count.assign(size, 0);
    MPI_Alltoall(sendCount.data(), 1, MPI_INT, count.data(), 1, MPI_INT, comm);
    for (int r = 1; r < size; ++r)
        recvOffset[r] = recvOffset[r - 1] + count[r - 1];
    std::vector<T> received((std::size_t(recvOffset[size - 1]) + std::size_t(count[size - 1])) * std::size_t(width));
    MPI_Datatype row;
    MPI_Type_contiguous(width, mpiType<T>(), &row);
    MPI_Type_commit(&row);
    MPI_Alltoallv(flat.data(), sendCount.data(), sendOffset.data(), row, received.data(), count.data(),
                  recvOffset.data(), row, comm);
    MPI_Type_free(&row);
    return received;
}

} // namespace

int RowBlocks::owner(long long gid) const
{
    int r = n > 0 ? int(std::min<long long>(gid * size / n, size - 1)) : 0;
    while (r + 1 < size && first(r + 1) <= gid)
        ++r;
    while (r > 0 && first(r) > gid)
        --r;
    return r;
}

std::vector<double> rowsToBlocks(MPI_Comm comm, const RowBlocks& blocks, const CheckpointRows& rows, std::string& error)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    const int nc = rows.ncomp;
    std::vector<std::vector<long long>> gids(std::size_t(blocks.size));
    std::vector<std::vector<double>> values(std::size_t(blocks.size));
    for (std::size_t i = 0; i < rows.gid.size(); ++i)
    {
        const long long g = rows.gid[i];
        if (g < 0 || g >= blocks.n)
        {
            error = "global id " + std::to_string(g) + " out of range";
            continue;
        }
        const int r = blocks.owner(g);
        gids[r].push_back(g);
        values[r].insert(values[r].end(), rows.values.begin() + long(i) * nc, rows.values.begin() + long(i + 1) * nc);
    }
    std::vector<int> count;
    const std::vector<long long> gid = exchange(comm, gids, count);
    const std::vector<double> value = exchange(comm, values, count, nc);
    const long long first = blocks.first(rank), n = blocks.count(rank);
    std::vector<double> block(std::size_t(n) * nc, 0.0);
    std::vector<char> filled(std::size_t(n), 0);
    for (std::size_t k = 0; k < gid.size(); ++k)
    {
        const std::size_t local = std::size_t(gid[k] - first);
        if (filled[local]++)
            error = "global id " + std::to_string(gid[k]) + " given twice";
        std::copy_n(value.begin() + long(k) * nc, nc, block.begin() + long(local) * nc);
    }
    const auto missing = std::find(filled.begin(), filled.end(), 0);
    if (error.empty() && missing != filled.end())
        error = "no row for global id " + std::to_string(first + (missing - filled.begin()));
    return block;
}

std::vector<double> rowsFromBlocks(MPI_Comm comm, const RowBlocks& blocks, const std::vector<double>& block, int ncomp,
                                   const std::vector<long long>& gid, std::string& error)
{
    int rank;
    MPI_Comm_rank(comm, &rank);
    std::vector<std::vector<long long>> asked(std::size_t(blocks.size));
    std::vector<std::vector<std::size_t>> where(std::size_t(blocks.size)); // positions in gid, per owner
    for (std::size_t i = 0; i < gid.size(); ++i)
    {
        if (gid[i] < 0 || gid[i] >= blocks.n)
        {
            error = "no row " + std::to_string(gid[i]);
            continue;
        }
        const int r = blocks.owner(gid[i]);
        asked[r].push_back(gid[i]);
        where[r].push_back(i);
    }
    std::vector<int> count;
    const std::vector<long long> wanted = exchange(comm, asked, count);
    std::vector<std::vector<double>> reply(std::size_t(blocks.size));
    const long long first = blocks.first(rank);
    std::size_t k = 0;
    for (int s = 0; s < blocks.size; ++s)
        for (int j = 0; j < count[s]; ++j, ++k)
        {
            const auto row = block.begin() + long(wanted[k] - first) * ncomp;
            reply[s].insert(reply[s].end(), row, row + ncomp);
        }
    const std::vector<double> values = exchange(comm, reply, count, ncomp);
    std::vector<double> out(gid.size() * std::size_t(ncomp), 0.0);
    k = 0;
    for (int r = 0; r < blocks.size; ++r)
        for (std::size_t i : where[r])
        {
            std::copy_n(values.begin() + long(k) * ncomp, ncomp, out.begin() + long(i) * ncomp);
            ++k;
        }
    return out;
}

void sendDoubles(MPI_Comm comm, const double* data, std::size_t n, int dest)
{
    for (std::size_t first = 0; first < n; first += maxCount)
        MPI_Send(data + first, int(std::min(n - first, maxCount)), MPI_DOUBLE, dest, 0, comm);
}

void recvDoubles(MPI_Comm comm, double* data, std::size_t n, int source)
{
    for (std::size_t first = 0; first < n; first += maxCount)
        MPI_Recv(data + first, int(std::min(n - first, maxCount)), MPI_DOUBLE, source, 0, comm, MPI_STATUS_IGNORE);
}

} // namespace unilag::io
