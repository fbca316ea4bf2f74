#include "solver/CostFit.hpp"

#include <cmath>
#include <utility>

namespace unilag
{
namespace
{

/*! Solves A x = b (k x k, symmetric positive semi-definite) by Gaussian elimination on the system scaled to a unit
 *  diagonal; false where it is too near singular to trust (a scaled pivot falls below 1e-2: the terms'
 *  directions over the samples are nearly dependent). */
bool solveScaled(std::vector<double> a, std::vector<double> b, std::vector<double>& x)
{
    const std::size_t k = b.size();
    std::vector<double> s(k);
    for (std::size_t i = 0; i < k; ++i)
    {
        if (!(a[i * k + i] > 0.0))
            return false;
        s[i] = 1.0 / std::sqrt(a[i * k + i]);
    }
    for (std::size_t i = 0; i < k; ++i)
    {
        b[i] *= s[i];
        for (std::size_t j = 0; j < k; ++j)
            a[i * k + j] *= s[i] * s[j];
    }
    for (std::size_t c = 0; c < k; ++c)
    {
        if (!(a[c * k + c] > 1e-2))
            return false;
        for (std::size_t r = c + 1; r < k; ++r)
        {
            const double f = a[r * k + c] / a[c * k + c];
            for (std::size_t j = c; j < k; ++j)
                a[r * k + j] -= f * a[c * k + j];
            b[r] -= f * b[c];
        }
    }
    x.assign(k, 0.0);
    for (std::size_t c = k; c-- > 0;)
    {
        double v = b[c];
        for (std::size_t j = c + 1; j < k; ++j)
            v -= a[c * k + j] * x[j];
        x[c] = v / a[c * k + c];
    }
    for (std::size_t i = 0; i < k; ++i)
        x[i] *= s[i];
    return true;
}

} // namespace

CostFit::CostFit(std::vector<double> prior, double forget)
    : weights_(std::move(prior)), forget_(forget), normal_(weights_.size() * weights_.size(), 0.0),
      right_(weights_.size(), 0.0)
{
}

void CostFit::add(const std::vector<double>& busy, const std::vector<std::vector<double>>& terms)
{
    const std::size_t k = weights_.size();
    for (double& v : normal_)
        v *= forget_;
    for (double& v : right_)
        v *= forget_;
    for (std::size_t p = 0; p < busy.size(); ++p)
        for (std::size_t i = 0; i < k; ++i)
        {
            right_[i] += terms[p][i] * busy[p];
            for (std::size_t j = 0; j < k; ++j)
                normal_[i * k + j] += terms[p][i] * terms[p][j];
        }
    std::vector<double> c;
    if (k < 2 || !solveScaled(normal_, right_, c) || !(c[0] > 0.0))
        return;
    for (double v : c)
        if (!(v >= 0.0))
            return;
    for (std::size_t i = 0; i < k; ++i)
        weights_[i] = c[i] / c[0];
    fitted_ = true;
}

} // namespace unilag
