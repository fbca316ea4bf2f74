/*! \file Format.hpp
 *  \brief Numbers in messages and JSON: ten significant digits, and null for a value that is not finite.
 */
#pragma once

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace unilag
{

inline std::string jsonNumber(double v)
{
    if (!std::isfinite(v))
        return "null";
    std::ostringstream os;
    os << std::setprecision(10) << v;
    return os.str();
}

} // namespace unilag
