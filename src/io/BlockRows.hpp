/*! \file BlockRows.hpp
 *  \brief Rows keyed by global id, moved by MPI between the ranks that own them and a block layout (rank r holds the
 *  global ids [r N / P, (r + 1) N / P) of N rows over P ranks): how a checkpoint is written and read without any
 *  rank holding a whole table (io/Checkpoint.hpp).
 */
#pragma once

#include <mpi.h>

#include <string>
#include <vector>

namespace unilag::io
{

//! Rows of one table on this rank: global ids and their values (ncomp per row, row-major).
struct CheckpointRows
{
    std::vector<long long> gid;
    std::vector<double> values;
    int ncomp = 0;
};

//! The block layout of a table of n rows over size ranks.
struct RowBlocks
{
    long long n = 0;
    int size = 1;
    long long first(int r) const { return n * r / size; }
    long long count(int r) const { return first(r + 1) - first(r); }
    int owner(long long gid) const; //!< the rank whose block holds gid, 0 <= gid < n
};

/*! Sends every rank's rows to the owners of their blocks; returns this rank's block, in global-id order. error (this
 *  rank's, "" if none): a global id out of range, repeated, or missing from the block. Collective. */
std::vector<double> rowsToBlocks(MPI_Comm comm, const RowBlocks& blocks, const CheckpointRows& rows,
                                 std::string& error);

/*! The rows of the global ids gid (ncomp columns, row-major), fetched from the ranks' blocks (block: this rank's).
 *  error: a global id out of range on this rank. Collective. */
std::vector<double> rowsFromBlocks(MPI_Comm comm, const RowBlocks& blocks, const std::vector<double>& block, int ncomp,
                                   const std::vector<long long>& gid, std::string& error);

//! Point-to-point transfer of n doubles, in pieces that fit an MPI count.
void sendDoubles(MPI_Comm comm, const double* data, std::size_t n, int dest);
void recvDoubles(MPI_Comm comm, double* data, std::size_t n, int source);

} // namespace unilag::io
