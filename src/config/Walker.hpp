/*! \file Walker.hpp
 *  \brief The validating walker of a YAML scene, shared by every scene kind (continuum, tube).
 *
 *  A ConfigNode wraps one section of a Teuchos ParameterList. Its typed getters record which keys were read;
 *  rejectUnknown() then turns every other key into an InputError naming the file, the key path and the closest
 *  known key. Option strings become enums here, once (option()), so no code downstream matches a string again.
 */
#pragma once

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "core/Errors.hpp"

namespace unilag::config
{

//! A scalar value: a constant or a muparser expression (of x, y, z, r for initial data, of t for boundary data).
struct Expr
{
    std::string text; //!< expression text ("" if constant)
    double value = 0.0;
    bool isConstant() const { return text.empty(); }
};

class ConfigNode
{
  public:
    ConfigNode(const std::string& file, const std::string& path, const Teuchos::ParameterList& list);

    [[noreturn]] void fail(const std::string& key, const std::string& what) const;
    //! A required key is absent: the error also names an unread key that looks like a misspelling of it.
    [[noreturn]] void missing(const std::string& key, const std::string& what) const;

    std::string join(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    bool has(const std::string& key) const { return list_.isParameter(key); }
    const std::string& file() const { return file_; }

    ConfigNode sub(const std::string& key, bool required = false);
    //! Names of all entries (for sections keyed by user names: materials, regions, boundaries).
    std::vector<std::string> keys() const;

    double number(const std::string& key, double def, bool required = false);
    double positive(const std::string& key, double def, bool required = false);
    double nonNegative(const std::string& key, double def);
    long integer(const std::string& key, long def, long lo, long hi);
    bool boolean(const std::string& key, bool def);
    std::string text(const std::string& key, const std::string& def, bool required = false);
    //! One of the allowed strings; an unknown one is an error listing them and the closest.
    std::string choice(const std::string& key, const std::string& def, const std::vector<std::string>& allowed,
                       bool required = false);
    //! choice() mapped to its enum value: names[i].first is the YAML spelling of names[i].second.
    template <class E>
    E option(const std::string& key, const std::string& def, const std::vector<std::pair<std::string, E>>& names,
             bool required = false)
    {
        std::vector<std::string> allowed;
        for (const auto& n : names)
            allowed.push_back(n.first);
        const std::string v = choice(key, def, allowed, required);
        return std::find_if(names.begin(), names.end(), [&](const auto& n) { return n.first == v; })->second;
    }
    //! A list of numbers of any length; a single number is a list of one (`--set key=0.3`).
    std::vector<double> numbers(const std::string& key, bool required = false);
    //! A list of 1 to 3 numbers.
    std::vector<double> vector(const std::string& key, bool required = false);
    //! A list of 1 to 3 constants or expressions of x, y, z, r.
    std::vector<Expr> expressions(const std::string& key);
    //! A constant or an expression (checked by compiling it).
    Expr expression(const std::string& key, bool required);

    //! Every key not read is an error, with the closest known key as a hint.
    void rejectUnknown() const;

  private:
    std::string file_, path_;
    const Teuchos::ParameterList& list_;
    std::set<std::string> used_;
};

//! A number for a message: the shortest of fixed and scientific (1e-14 stays readable, unlike std::to_string).
std::string num(double v);

/*! Refuses an output interval (key of node) that makes more than 100,000 dumps to endTime: each dump clips the step
 *  to its time, so a tiny interval fills the disk and stalls the run (a checkpoint every 1e-17 looped at t = 0).
 *  0 passes; what / zero: the name of what is written and what 0 means, for the message. */
void refuseTooManyDumps(const ConfigNode& node, const std::string& key, double interval, double endTime,
                        const std::string& what = "dumps",
                        const std::string& zero = "writes the first and last states only");

//! p resolved against the scene's folder dir (absolute paths stay as they are).
std::string resolvePath(const std::string& dir, const std::string& p);

/*! Why the input file `path` cannot be read ("file not found", "not a regular file": a folder, or a FIFO that would
 *  block the reader for ever; or the system's reason, e.g. a name too long), or "" if it is a regular file. */
std::string inputFileProblem(const std::string& path);

/*! \brief Parse a YAML scene file whose top-level key must be `top`, then apply `--set` overrides
 *  ("a.b.c=value"; the value's type follows the entry it replaces, else is inferred). Throws InputError. */
Teuchos::RCP<Teuchos::ParameterList> readYaml(const std::string& file, const std::string& top,
                                              const std::vector<std::string>& overrides);

} // namespace unilag::config
