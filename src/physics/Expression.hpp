/*! \file Expression.hpp
 *  \brief Scalar expressions of position (x, y, z, r = |x|) for initial conditions, evaluated with muparser.
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
    double operator()(double x, double y, double z);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace unilag
