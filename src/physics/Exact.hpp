/*! \file Exact.hpp
 *  \brief Exact radial profiles (Sedov, Kidder) tabulated as CSV, interpolated linearly.
 */
#pragma once

#include <string>
#include <vector>

namespace unilag
{

//! A radial profile: '#' comment lines, a header line naming the columns, then rows (position first).
class RadialProfile
{
  public:
    explicit RadialProfile(const std::string& csv); //!< throws InputError if unreadable
    double density(double r) const { return interpolate(density_, r); }
    double ambientDensity() const { return density_.back(); }
    double lastPosition() const { return r_.back(); } //!< beyond it, the last row's density (constant)

  private:
    double interpolate(const std::vector<double>& f, double r) const;
    std::vector<double> r_, density_;
};

} // namespace unilag
