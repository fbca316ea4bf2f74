/*! \file GprCheckpoint.hpp
 *  \brief Checkpoint and restart of a GPR run (issue 14, README "Checkpoint and restart"): every persistent field
 *  (cells and nodes, by global id), the node velocities the next step's impedance lags, the time loop's state and
 *  the run's running totals, in one file (io/Checkpoint.hpp). A restart on any number of ranks continues bit for bit
 *  (the solver's results do not depend on the partition). Included by GprSystem.hpp.
 */
#pragma once

#include <charconv>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>

#include "io/Checkpoint.hpp"

namespace unilag
{

//! The sections of the scene a restart must keep: what the state's evolution depends on (not time, output, regions).
inline const char* const kRestartSections[] = {"materials", "boundaries", "scheme"};

//! The shortest text that reads back as v (1.4, not 1.3999999999999999).
inline std::string shortestText(double v)
{
    char buf[32];
    const auto end = std::to_chars(buf, buf + sizeof buf, v).ptr;
    return std::string(buf, end);
}

//! "key=value" lines of a scene section's leaves, depth first, numbers to all their digits.
inline void flattenSection(const Teuchos::ParameterList& list, const std::string& prefix, std::ostringstream& out)
{
    for (auto it = list.begin(); it != list.end(); ++it)
    {
        const std::string key = prefix + list.name(it);
        const Teuchos::ParameterEntry& e = list.entry(it);
        if (e.isList())
            flattenSection(Teuchos::getValue<Teuchos::ParameterList>(e), key + ".", out);
        else if (e.isType<double>())
            out << key << "=" << shortestText(Teuchos::getValue<double>(e)) << "\n";
        else if (e.isType<Teuchos::Array<double>>())
        {
            out << key << "=";
            for (double v : Teuchos::getValue<Teuchos::Array<double>>(e))
                out << shortestText(v) << " ";
            out << "\n";
        }
        else
            out << key << "=" << e.getAny(false) << "\n";
    }
}

//! A section of the resolved scene as flattenSection's lines ("" where the scene has no such section).
inline std::string sceneSection(const Teuchos::ParameterList& resolved, const std::string& section)
{
    if (!resolved.isSublist(section))
        return {};
    std::ostringstream out;
    flattenSection(resolved.sublist(section), section + ".", out);
    return out.str();
}

/*! The first key whose value differs between two sceneSection texts, as "KEY: 'A' in the checkpoint, 'B' in this
 *  scene" ("" if they hold the same keys and values, in whatever order). */
inline std::string sectionChange(const std::string& checkpoint, const std::string& scene)
{
    auto parse = [](const std::string& text)
    {
        std::map<std::string, std::string> kv;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);)
            kv[line.substr(0, line.find('='))] = line.substr(line.find('=') + 1);
        return kv;
    };
    const auto was = parse(checkpoint), now = parse(scene);
    std::map<std::string, std::string> keys = was;
    keys.insert(now.begin(), now.end());
    for (const auto& [key, unused] : keys)
    {
        const auto a = was.find(key), b = now.find(key);
        const std::string va = a == was.end() ? "(not given)" : "'" + a->second + "'";
        const std::string vb = b == now.end() ? "(not given)" : "'" + b->second + "'";
        if (va != vb)
            return key + ": " + va + " in the checkpoint, " + vb + " in this scene";
    }
    return {};
}

//! What identifies a run's checkpoint: a restart must match every line (scene, mesh, physics, scheme).
template <int D, class P> std::vector<std::pair<std::string, std::string>> checkpointIdentity(const GprModel<D, P>& md)
{
    const auto& dm = *md.mesh;
    return {{"title", md.scene.name},
            {"dimension", std::to_string(D)},
            {"cells", std::to_string(dm.nGlobalCells)},
            {"nodes", std::to_string(dm.nGlobalNodes)},
            {"physics", std::string(P::strain ? "strain" : "hydro") + (P::plastic ? "+plastic" : "") +
                            (P::heat ? "+heat" : "")},
            {"order", md.order2 ? "2" : "1"},
            {"integrator", md.scene.integrator == Integrator::Ars222 ? "ars222" : "midpoint"}};
}

//! The owned rows of a field with their global ids.
template <int D, class P> io::CheckpointRows ownedRows(const GprModel<D, P>& md, const std::string& name, bool node)
{
    const auto& dm = *md.mesh;
    auto v = md.fields[name].getLocalViewHost(Tpetra::Access::ReadOnly);
    io::CheckpointRows rows;
    rows.ncomp = int(v.extent(1));
    const LO n = node ? dm.nOwnedNodes : dm.nOwnedCells;
    for (LO i = 0; i < n; ++i)
    {
        rows.gid.push_back(node ? dm.nodeGid[i] : dm.cellGid[i]);
        for (int c = 0; c < rows.ncomp; ++c)
            rows.values.push_back(v(i, c));
    }
    return rows;
}

//! Fills the owned rows of a field from the checkpoint's table, then its ghosts. Collective.
template <int D, class P>
void restoreRows(GprModel<D, P>& md, const io::CheckpointReader& in, const std::string& name, bool node)
{
    const auto& dm = *md.mesh;
    auto v = md.fields[name].getLocalViewHost(Tpetra::Access::ReadWrite);
    const int ncomp = int(v.extent(1));
    const LO n = node ? dm.nOwnedNodes : dm.nOwnedCells;
    std::vector<long long> gid(static_cast<std::size_t>(n));
    for (LO i = 0; i < n; ++i)
        gid[std::size_t(i)] = node ? dm.nodeGid[i] : dm.cellGid[i];
    const std::vector<double> values = in.rows((node ? "node." : "cell.") + name, gid, ncomp);
    for (LO i = 0; i < n; ++i)
        for (int c = 0; c < ncomp; ++c)
            v(i, c) = values[std::size_t(i) * ncomp + c];
    md.fields.halo(name);
}

//! The fields a checkpoint holds: the persistent ones, and the lagged node velocities (scratch, but the next step's
//! impedance depends on them).
template <int D, class P> std::vector<std::pair<std::string, bool>> checkpointFields(const GprModel<D, P>& md,
                                                                                    const std::string& lagged)
{
    std::vector<std::pair<std::string, bool>> f;
    for (const std::string& name : md.fields.names(Lifetime::Persistent))
        f.emplace_back(name, md.fields.entity(name) == Entity::Node);
    f.emplace_back(lagged, true);
    return f;
}

} // namespace unilag
