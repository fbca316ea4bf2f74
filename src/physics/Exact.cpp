#include "physics/Exact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "config/Scene.hpp"

namespace unilag
{

namespace
{

std::vector<std::string> split(const std::string& line)
{
    std::vector<std::string> cols;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ','))
    {
        const auto a = cell.find_first_not_of(" \t\r"), b = cell.find_last_not_of(" \t\r");
        cols.push_back(a == std::string::npos ? std::string() : cell.substr(a, b - a + 1));
    }
    return cols;
}

//! A finite number filling the whole field, or false.
bool parseNumber(const std::string& text, double& v)
{
    if (text.empty())
        return false;
    char* end = nullptr;
    v = std::strtod(text.c_str(), &end);
    return *end == '\0' && std::isfinite(v);
}

} // namespace

RadialProfile::RadialProfile(const std::string& csv)
{
    std::ifstream in(csv);
    if (!in)
        throw InputError(csv + ": cannot open the exact-solution table");
    auto fail = [&](int line, const std::string& what) {
        throw InputError(csv + " line " + std::to_string(line) + ": " + what);
    };
    std::string line;
    int lineNo = 0, positionColumn = -1, densityColumn = -1;
    std::size_t width = 0;
    std::string lastPosition;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
        if (line[0] == '#')
        {
            // the column names may sit in a comment line: "# position,density,..."
            if (densityColumn < 0 && line.find("position") != std::string::npos)
                line = line.substr(line.find("position"));
            else
                continue;
        }
        const std::vector<std::string> cols = split(line);
        if (densityColumn < 0)
        {
            const auto p = std::find(cols.begin(), cols.end(), "position");
            const auto d = std::find(cols.begin(), cols.end(), "density");
            if (p == cols.end() || d == cols.end())
                fail(lineNo, "the header '" + line + "' must name the columns 'position' and 'density'");
            positionColumn = int(p - cols.begin());
            densityColumn = int(d - cols.begin());
            width = cols.size();
            continue;
        }
        if (cols.size() != width)
            fail(lineNo, "expected " + std::to_string(width) + " comma-separated columns as in the header, found " +
                             std::to_string(cols.size()) + ": '" + line + "'");
        double r, rho;
        if (!parseNumber(cols[positionColumn], r))
            fail(lineNo, "position '" + cols[positionColumn] + "' is not a finite number");
        if (!parseNumber(cols[densityColumn], rho))
            fail(lineNo, "density '" + cols[densityColumn] + "' is not a finite number");
        if (!r_.empty() && !(r > r_.back()))
            fail(lineNo, "position " + cols[positionColumn] + " does not increase (the row before has " + lastPosition +
                             "): the table must be sorted by position");
        lastPosition = cols[positionColumn];
        r_.push_back(r);
        density_.push_back(rho);
    }
    if (densityColumn < 0)
        throw InputError(csv + ": no header line naming the columns 'position' and 'density'");
    if (r_.size() < 2)
        throw InputError(csv + ": fewer than two rows");
}

double RadialProfile::interpolate(const std::vector<double>& f, double r) const
{
    if (r <= r_.front())
        return f.front();
    if (r >= r_.back())
        return f.back();
    const auto it = std::upper_bound(r_.begin(), r_.end(), r);
    const std::size_t j = std::size_t(it - r_.begin());
    const double w = (r - r_[j - 1]) / (r_[j] - r_[j - 1]);
    return (1.0 - w) * f[j - 1] + w * f[j];
}

} // namespace unilag
