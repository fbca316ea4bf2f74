/*! \file Checkpoint.hpp
 *  \brief One HDF5 file of a run's persistent state (issue 14): named tables of rows keyed by global id (cells or
 *  nodes), so that it reads on any number of ranks, plus named lists of numbers and texts (the time loop's state,
 *  the scene's identity).
 *
 *  Rank 0 writes and reads the file; the rows travel by MPI (gathered by global id, broadcast back). It is written to
 *  "<path>.tmp" and renamed, so a crash mid-write never leaves a half checkpoint under the real name. A file that is
 *  missing, truncated, not a checkpoint, or lacks a table or number is an InputError naming the file.
 */
#pragma once

#include <mpi.h>

#include <map>
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
    std::map<std::string, std::vector<double>> tables_; //!< rank 0: rows in global-id order
    std::map<std::string, int> tableColumns_;
};

class CheckpointReader
{
  public:
    //! Opens and reads the whole file on rank 0 and broadcasts it. Collective; InputError if unreadable.
    CheckpointReader(MPI_Comm comm, const std::string& path);
    std::string text(const std::string& name) const;
    const std::vector<double>& numbers(const std::string& name) const;
    //! The rows of the given global ids (ncomp columns, checked), row-major. InputError if absent.
    std::vector<double> rows(const std::string& name, const std::vector<long long>& gid, int ncomp) const;

  private:
    std::string path_;
    std::map<std::string, std::string> texts_;
    std::map<std::string, std::vector<double>> vectors_;
    std::map<std::string, std::vector<double>> tables_;
    std::map<std::string, int> tableColumns_;
};

} // namespace unilag::io
