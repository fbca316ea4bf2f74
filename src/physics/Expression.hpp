/*! \file Expression.hpp
 *  \brief Scalar expressions of position (x, y, z, r = |x|) and time t, evaluated with muparser.
 */
#pragma once

#include <memory>
#include <string>

namespace unilag
{

class Expression
{
  public:
    //! Compiles text; throws std::invalid_argument with muparser's message if it does not parse.
    explicit Expression(const std::string& text);
    ~Expression();
    Expression(const Expression&) = delete;
    Expression& operator=(const Expression&) = delete;
    double operator()(double x, double y, double z, double t = 0.0);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace unilag
