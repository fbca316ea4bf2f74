#include "physics/Exact.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "config/Scene.hpp"

namespace unilag
{

RadialProfile::RadialProfile(const std::string& csv)
{
    std::ifstream in(csv);
    if (!in)
        throw InputError(csv + ": cannot open the exact-solution table");
    std::string line;
    int densityColumn = -1;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#')
        {
            // the column names may sit in a comment line: "# position,density,..."
            if (densityColumn < 0 && line.find("position") != std::string::npos)
                line = line.substr(line.find("position"));
            else
                continue;
        }
        std::stringstream ss(line);
        std::string cell;
        std::vector<std::string> cols;
        while (std::getline(ss, cell, ','))
            cols.push_back(cell);
        if (densityColumn < 0)
        {
            auto it = std::find(cols.begin(), cols.end(), "density");
            if (cols.empty() || it == cols.end())
                throw InputError(csv + ": the header must name the columns 'position' and 'density'");
            densityColumn = int(it - cols.begin());
            continue;
        }
        if (int(cols.size()) <= densityColumn)
            throw InputError(csv + ": short row '" + line + "'");
        r_.push_back(std::stod(cols[0]));
        density_.push_back(std::stod(cols[densityColumn]));
    }
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
