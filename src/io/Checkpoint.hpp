/*! \file Checkpoint.hpp
 *  \brief One HDF5 file of a run's persistent state (issue 14): named tables of rows keyed by global id (cells or
 *  nodes), so that it reads on any number of ranks, plus named lists of numbers and texts (the time loop's state,
 *  the scene's identity).
 *
 *  Memory: no rank holds a whole table. The rows travel by MPI to a block layout (rank r holds the global ids
 *  [r N / P, (r + 1) N / P) of a table of N rows); rank 0 streams the blocks to and from the file one rank at a time
 *  (serial HDF5, hyperslabs), and a reader's rows come from the blocks' owners. The file's layout is that of a
 *  single-rank write. It is written to "<path>.tmp" and renamed, so a crash mid-write never leaves a half checkpoint
 *  under the real name. A file that is missing, truncated, not a checkpoint, lacks a table or number, or whose text,
 *  list or table does not match its FNV-1a checksum (group "checksums", over the values in global order) is an
 *  InputError naming the file, on every rank alike.
 */
#pragma once

#include <mpi.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "io/BlockRows.hpp"

namespace unilag::io
{

class CheckpointWriter
{
  public:
    CheckpointWriter(MPI_Comm comm, std::string path) : comm_(comm), path_(std::move(path)) {}
    void text(const std::string& name, const std::string& v) { texts_[name] = v; }
    void numbers(const std::string& name, const std::vector<double>& v) { vectors_[name] = v; }
    //! A table of nGlobal rows; every rank gives its owned rows. Collective.
    void table(const std::string& name, long long nGlobal, const CheckpointRows& rows);
    //! Writes the file (temporary name, then rename). Collective; OutputError if it cannot.
    void commit();

  private:
    MPI_Comm comm_;
    std::string path_;
    std::map<std::string, std::string> texts_;
    std::map<std::string, std::vector<double>> vectors_;
    std::map<std::string, std::vector<double>> blocks_;       //!< this rank's block of each table, in global-id order
    std::map<std::string, std::pair<long long, int>> shapes_; //!< rows and columns of each table
};

class CheckpointReader
{
  public:
    /*! Opens the file on rank 0, broadcasts its texts and numbers, and hands each rank its block of every table.
     *  Collective; InputError if unreadable. */
    CheckpointReader(MPI_Comm comm, const std::string& path);
    std::string text(const std::string& name) const;
    const std::vector<double>& numbers(const std::string& name) const;
    bool hasNumbers(const std::string& name) const { return vectors_.count(name) > 0; }
    /*! The rows of the given global ids (ncomp columns, checked), row-major, fetched from their blocks' owners.
     *  Collective (every rank asks for the same tables in the same order); InputError if absent. */
    std::vector<double> rows(const std::string& name, const std::vector<long long>& gid, int ncomp) const;

  private:
    MPI_Comm comm_;
    std::string path_;
    std::map<std::string, std::string> texts_;
    std::map<std::string, std::vector<double>> vectors_;
    std::map<std::string, std::vector<double>> blocks_;
    std::map<std::string, std::pair<long long, int>> shapes_;
};

} // namespace unilag::io
