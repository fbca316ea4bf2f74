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

/*! "shock speed 1.7561 (exact 1.7522)" for the one-line summaries, or "no shock" where the run has none (a double
 *  rarefaction: the fitted speed is not finite). label names the reference ("exact", "rigid exact"). */
inline std::string shockSpeedText(double speed, double reference, const char* label = "exact")
{
    if (!std::isfinite(speed))
        return "no shock";
    std::ostringstream os;
    os << std::setprecision(5) << "shock speed " << speed;
    if (std::isfinite(reference))
        os << " (" << label << " " << reference << ")";
    return os.str();
}

} // namespace unilag
