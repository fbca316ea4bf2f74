#include "solver/Summary.hpp"

#include <algorithm>
#include <fstream>

#include "core/Format.hpp"

namespace unilag
{

Summary& Summary::raw(const std::string& key, const std::string& json)
{
    entries_.emplace_back(key, json);
    return *this;
}

Summary& Summary::number(const std::string& key, double v)
{
    return raw(key, jsonNumber(v));
}

Summary& Summary::integer(const std::string& key, long long v)
{
    return raw(key, std::to_string(v));
}

Summary& Summary::text(const std::string& key, const std::string& v)
{
    std::string s = v;
    std::replace(s.begin(), s.end(), '"', '\'');
    return raw(key, "\"" + s + "\"");
}

Summary& Summary::object(const std::string& key, const Pairs& members)
{
    std::string json = "{";
    for (std::size_t i = 0; i < members.size(); ++i)
        json += (i ? ", \"" : "\"") + members[i].first + "\": " + members[i].second;
    return raw(key, json + "}");
}

Summary& Summary::timeShares(const PhaseTimers& timers, double wall)
{
    Pairs shares;
    for (int p = 0; p < int(Phase::Count); ++p)
        shares.emplace_back(phaseName(Phase(p)), jsonNumber(timers.seconds[p] / wall));
    return object("time_share", shares);
}

void Summary::write(const std::string& file) const
{
    std::ofstream out(file);
    out << "{\n";
    for (std::size_t i = 0; i < entries_.size(); ++i)
        out << "  \"" << entries_[i].first << "\": " << entries_[i].second << (i + 1 < entries_.size() ? ",\n" : "\n");
    out << "}\n";
}

Summary runSummary(const std::string& file, const std::string& title, const LoopResult& r, int dim, long long cells,
                   long long nodes, int ranks, int threads)
{
    Summary s;
    s.text("scene", file).text("title", title).text("status", !r.failure.empty() ? "unstable"
                                : r.signal != 0 ? "interrupted"
                                : r.stepCapped  ? "max_steps"
                                                : "completed");
    s.integer("dimension", dim).integer("cells", cells).integer("nodes", nodes);
    s.integer("ranks", ranks)
        .integer("threads", threads)
        .integer("steps", r.state.steps)
        .integer("retries", r.state.retries);
    return s;
}

} // namespace unilag
