/*! \file CostFit.hpp
 *  \brief The load balance's cost model, fitted as the run goes (issue 14, docs/parallel.md 4): each rank's busy
 *  time over a check interval against its cost terms there (cell-steps, units of plastic work, ...),
 *
 *      busy_p = sum_k c_k term_{p,k},
 *
 *  by least squares over the ranks and the past checks (each older check weighted down by `forget`). The weights
 *  are w_k = c_k / c_0: what one unit of term k costs in cell-steps (w_0 = 1). The prior weights stand until the data
 *  determine the others: the ranks' term ratios must differ (else any split of the time fits), and every c_k come
 *  out non-negative with c_0 > 0.
 */
#pragma once

#include <vector>

namespace unilag
{

class CostFit
{
  public:
    //! prior: the weights to start from (prior[0] = 1); forget: the weight of a check one check older.
    explicit CostFit(std::vector<double> prior, double forget = 0.7);
    /*! One check: per rank, its busy seconds and its terms (terms[p] has one entry per weight). Refits the weights
     *  when the data determine them. */
    void add(const std::vector<double>& busy, const std::vector<std::vector<double>>& terms);
    const std::vector<double>& weights() const { return weights_; }
    //! Whether the weights now come from the data (not the prior).
    bool fitted() const { return fitted_; }

  private:
    std::vector<double> weights_;
    double forget_;
    std::vector<double> normal_; //!< sum of t t^T over the samples, decayed, row-major k x k
    std::vector<double> right_;  //!< sum of t busy, decayed
    bool fitted_ = false;
};

} // namespace unilag
