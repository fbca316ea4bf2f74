/*! \file FieldSet.hpp
 *  \brief The solver's state as one object: named Tpetra MultiVectors on the overlapping cell or node map, each
 *  marked persistent (part of the state: migrated on repartitioning, written to checkpoints) or scratch (derived
 *  or per-step work space: reallocated, never moved).
 *
 *  Rows are local entities, owned first, then ghosts (DistributedMesh); columns are components. halo() fills the
 *  ghost rows from their owners with one Tpetra Import (Cabana's gather). The kernels take the LayoutLeft device
 *  views (field(name).getLocalViewDevice(...)) without copies.
 */
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>

#include "core/Types.hpp"
#include "mesh/DistributedMesh.hpp"

namespace unilag
{

enum class Entity
{
    Cell,
    Node
};

enum class Lifetime
{
    Persistent, //!< state: migrated, checkpointed
    Scratch     //!< derived or work space: reallocated on a new mesh
};

class FieldSet
{
  public:
    explicit FieldSet(std::shared_ptr<const DistributedMesh> mesh) : mesh_(std::move(mesh)) {}

    //! Adds a field of ncomp columns on the local (owned + ghost) entities; returns it.
    MV& add(const std::string& name, Entity entity, int ncomp, Lifetime lifetime);
    bool has(const std::string& name) const { return fields_.count(name) > 0; }
    Entity entity(const std::string& name) const { return entry(name).entity; }
    MV& operator[](const std::string& name) const { return *entry(name).mv; }
    //! Exchanges the storage of two fields of the same shape (the new state becomes the state).
    void swap(const std::string& a, const std::string& b);
    //! Fills the ghost rows of a field from their owners. Collective.
    void halo(const std::string& name) const;
    //! Copies every column and row of a field into another of the same shape.
    void copy(const std::string& from, const std::string& to) const;

    /*! \brief Moves the fields onto a new distribution of the same global mesh: persistent fields, and the scratch
     *  fields named in carry (a lagged value the next step reads), are imported by global id (owned rows, then the
     *  halo); the other scratch fields are reallocated. Collective. */
    void migrate(std::shared_ptr<const DistributedMesh> newMesh, const std::vector<std::string>& carry = {});

    //! Names of the fields of one lifetime, in the order they were added.
    std::vector<std::string> names(Lifetime lifetime) const;
    const DistributedMesh& mesh() const { return *mesh_; }

  private:
    struct Entry
    {
        Entity entity;
        Lifetime lifetime;
        Teuchos::RCP<MV> mv;
    };
    const Entry& entry(const std::string& name) const;
    Teuchos::RCP<const Map> overlapMap(const DistributedMesh& m, Entity e) const;

    std::shared_ptr<const DistributedMesh> mesh_;
    std::map<std::string, Entry> fields_;
    std::vector<std::string> order_;
};

} // namespace unilag
