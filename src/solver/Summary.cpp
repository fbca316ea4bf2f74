#include "solver/Summary.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "core/Format.hpp"
#include "io/OutputFolder.hpp"

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
    io::finishOutput(out, file);
}

namespace
{

/*! The load-balance checks (max / mean of the ranks' busy times per window: mean, max, the last; the cost model's
 *  prediction for the same partitions, mean) and each repartition: step, time, imbalance before and after, cells
 *  moved, seconds. */
std::string loadBalanceJson(const LoopResult& r)
{
    double sum = 0.0, worst = 0.0, model = 0.0, spread = 0.0;
    for (const BalanceCheck& c : r.balanceChecks)
    {
        sum += c.imbalance;
        worst = std::max(worst, c.imbalance);
        model += c.modelImbalance;
        spread += c.speedSpread;
    }
    std::ostringstream os;
    os << "{\"checks\": " << r.balanceChecks.size()
       << ", \"imbalance_mean\": " << jsonNumber(sum / double(r.balanceChecks.size()))
       << ", \"imbalance_max\": " << jsonNumber(worst)
       << ", \"imbalance_last\": " << jsonNumber(r.balanceChecks.back().imbalance)
       << ", \"model_imbalance_mean\": " << jsonNumber(model / double(r.balanceChecks.size()))
       << ", \"work_cost_last\": " << jsonNumber(r.balanceChecks.back().workCost)
       << ", \"speed_spread_mean\": " << jsonNumber(spread / double(r.balanceChecks.size()))
       << ", \"repartitions\": [";
    for (std::size_t k = 0; k < r.repartitions.size(); ++k)
    {
        const RepartitionEvent& e = r.repartitions[k];
        os << (k ? ", " : "") << "{\"step\": " << e.step << ", \"t\": " << jsonNumber(e.t)
           << ", \"imbalance_before\": " << jsonNumber(e.before) << ", \"imbalance_after\": " << jsonNumber(e.after)
           << ", \"cells_moved\": " << e.cellsMoved << ", \"seconds\": " << jsonNumber(e.seconds) << "}";
    }
    os << "]}";
    return os.str();
}

} // namespace

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
    if (!r.balanceChecks.empty())
        s.raw("load_balance", loadBalanceJson(r));
    return s;
}

} // namespace unilag
