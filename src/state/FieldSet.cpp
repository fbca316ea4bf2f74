#include "state/FieldSet.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/Mpi.hpp"

namespace unilag
{

Teuchos::RCP<const Map> FieldSet::overlapMap(const DistributedMesh& m, Entity e) const
{
    return e == Entity::Cell ? m.cellMapOverlap : m.nodeMapOverlap;
}

MV& FieldSet::add(const std::string& name, Entity entity, int ncomp, Lifetime lifetime)
{
    if (fields_.count(name))
        throw std::logic_error("FieldSet: field '" + name + "' added twice");
    Entry e{entity, lifetime, Teuchos::rcp(new MV(overlapMap(*mesh_, entity), ncomp))};
    order_.push_back(name);
    return *fields_.emplace(name, e).first->second.mv;
}

const FieldSet::Entry& FieldSet::entry(const std::string& name) const
{
    const auto it = fields_.find(name);
    if (it == fields_.end())
        throw std::logic_error("FieldSet: no field '" + name + "'");
    return it->second;
}

void FieldSet::swap(const std::string& a, const std::string& b)
{
    std::swap(fields_.at(a).mv, fields_.at(b).mv);
}

void FieldSet::halo(const std::string& name) const
{
    mpi::WaitTimer wait; // includes packing, which is small next to the wait for the slowest rank
    const Entry& e = entry(name);
    const bool cell = e.entity == Entity::Cell;
    auto owned = e.mv->offsetViewNonConst(cell ? mesh_->cellMap : mesh_->nodeMap, 0);
    e.mv->doImport(*owned, cell ? *mesh_->cellImporter : *mesh_->nodeImporter, Tpetra::INSERT);
}

void FieldSet::copy(const std::string& from, const std::string& to) const
{
    Tpetra::deep_copy(*entry(to).mv, *entry(from).mv);
}

void FieldSet::migrate(std::shared_ptr<const DistributedMesh> newMesh, const std::vector<std::string>& carry)
{
    auto moves = [&](const std::string& name, const Entry& e)
    { return e.lifetime == Lifetime::Persistent || std::find(carry.begin(), carry.end(), name) != carry.end(); };
    const Importer cells(mesh_->cellMap, newMesh->cellMap), nodes(mesh_->nodeMap, newMesh->nodeMap);
    for (auto& [name, e] : fields_)
    {
        const bool cell = e.entity == Entity::Cell;
        auto fresh = Teuchos::rcp(new MV(overlapMap(*newMesh, e.entity), e.mv->getNumVectors()));
        if (moves(name, e))
        {
            auto oldOwned = e.mv->offsetView(cell ? mesh_->cellMap : mesh_->nodeMap, 0);
            auto newOwned = fresh->offsetViewNonConst(cell ? newMesh->cellMap : newMesh->nodeMap, 0);
            newOwned->doImport(*oldOwned, cell ? cells : nodes, Tpetra::INSERT);
        }
        e.mv = fresh;
    }
    mesh_ = std::move(newMesh);
    for (const auto& name : order_)
        if (moves(name, fields_.at(name)))
            halo(name);
}

std::vector<std::string> FieldSet::names(Lifetime lifetime) const
{
    std::vector<std::string> out;
    for (const auto& name : order_)
        if (fields_.at(name).lifetime == lifetime)
            out.push_back(name);
    return out;
}

} // namespace unilag
