/*! \file Summary.hpp
 *  \brief summary.json of a run: an ordered JSON object written by rank 0, with the entries every solver reports
 *  (scene, status, sizes, steps, time shares) and whatever a solver adds.
 */
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/Timers.hpp"
#include "solver/TimeLoop.hpp"

namespace unilag
{

class Summary
{
  public:
    using Pairs = std::vector<std::pair<std::string, std::string>>;
    Summary& raw(const std::string& key, const std::string& json);
    Summary& number(const std::string& key, double v);
    Summary& integer(const std::string& key, long long v);
    Summary& text(const std::string& key, const std::string& v);   //!< quotes become apostrophes
    Summary& object(const std::string& key, const Pairs& members); //!< members' values are JSON already
    //! Each phase's share of the wall time.
    Summary& timeShares(const PhaseTimers& timers, double wall);
    void write(const std::string& file) const;

  private:
    Pairs entries_;
};

//! The entries every run reports: scene, title, status, dimension, sizes, ranks, threads, steps, retries.
Summary runSummary(const std::string& file, const std::string& title, const LoopResult& r, int dim, long long cells,
                   long long nodes, int ranks, int threads);

} // namespace unilag
