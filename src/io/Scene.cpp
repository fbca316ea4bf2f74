#include "io/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>

#include <Teuchos_YamlParameterListHelpers.hpp>

#include "physics/Expression.hpp"

namespace unilag
{
namespace
{

namespace fs = std::filesystem;
using Teuchos::ParameterList;

std::size_t editDistance(const std::string& a, const std::string& b)
{
    std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
    {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j)
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

//! A number for a message: shortest of fixed and scientific (1e-14 stays readable, unlike std::to_string).
std::string num(double v)
{
    std::ostringstream os;
    os << v;
    return os.str();
}

bool parseNumber(const std::string& s, double& out)
{
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return !s.empty() && end && *end == '\0';
}

//! Walks one sublist: typed getters that record which keys were used, then rejects the rest.
class Node
{
  public:
    Node(const std::string& file, const std::string& path, const ParameterList& list)
        : file_(file), path_(path), list_(list)
    {
    }

    [[noreturn]] void fail(const std::string& key, const std::string& what) const
    {
        throw InputError(file_ + ": key '" + join(key) + "': " + what);
    }
    //! A required key is absent: the error also names a key present but not read that looks like a misspelling.
    [[noreturn]] void missing(const std::string& key, const std::string& what) const
    {
        std::string best;
        std::size_t bestD = 3;
        for (auto it = list_.begin(); it != list_.end(); ++it)
        {
            const std::string& k = list_.name(it);
            const std::size_t d = editDistance(k, key);
            if (!used_.count(k) && d < bestD)
            {
                bestD = d;
                best = k;
            }
        }
        const std::string hint = best.empty() ? "" : "; found '" + join(best) + "': did you mean '" + join(key) + "'?";
        fail(key, "missing " + what + hint);
    }

    std::string join(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
    bool has(const std::string& key) const { return list_.isParameter(key); }

    Node sub(const std::string& key, bool required = false)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
        {
            if (required)
                missing(key, "(a section is required here)");
            return Node(file_, join(key), empty_);
        }
        if (!list_.isSublist(key))
            fail(key, "expected a section of keys, found a value");
        return Node(file_, join(key), list_.sublist(key));
    }

    //! Names of all entries (for sections keyed by user names: materials, regions, boundaries).
    std::vector<std::string> keys() const
    {
        std::vector<std::string> k;
        for (auto it = list_.begin(); it != list_.end(); ++it)
            k.push_back(list_.name(it));
        return k;
    }

    double number(const std::string& key, double def, bool required = false)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
        {
            if (required)
                missing(key, "(a number is required)");
            return def;
        }
        const auto& e = list_.getEntry(key);
        if (e.isType<double>())
            return e.getValue<double>(nullptr);
        if (e.isType<int>())
            return e.getValue<int>(nullptr);
        if (e.isType<long long>())
            return double(e.getValue<long long>(nullptr));
        double v;
        if (e.isType<std::string>() && parseNumber(e.getValue<std::string>(nullptr), v))
            return v;
        fail(key, "expected a number, found '" + e.getAny(false).typeName() + "' " + toString(e));
    }

    double positive(const std::string& key, double def, bool required = false)
    {
        const double v = number(key, def, required);
        if (!(v > 0.0) || !std::isfinite(v))
            fail(key, "must be a positive number, found " + num(v));
        return v;
    }

    double nonNegative(const std::string& key, double def)
    {
        const double v = number(key, def);
        if (!(v >= 0.0) || !std::isfinite(v))
            fail(key, "must be a non-negative number, found " + num(v));
        return v;
    }

    long integer(const std::string& key, long def, long lo, long hi)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
            return def;
        const auto& e = list_.getEntry(key);
        long v;
        if (e.isType<int>())
            v = e.getValue<int>(nullptr);
        else if (e.isType<long long>())
            v = long(e.getValue<long long>(nullptr));
        else
            fail(key, "expected an integer, found " + toString(e));
        if (v < lo || v > hi)
            fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + std::to_string(v));
        return v;
    }

    bool boolean(const std::string& key, bool def)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
            return def;
        const auto& e = list_.getEntry(key);
        if (e.isType<bool>())
            return e.getValue<bool>(nullptr);
        fail(key, "expected true or false, found " + toString(e));
    }

    std::string text(const std::string& key, const std::string& def, bool required = false)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
        {
            if (required)
                missing(key, "(a string is required)");
            return def;
        }
        const auto& e = list_.getEntry(key);
        if (!e.isType<std::string>())
            fail(key, "expected a string, found " + toString(e));
        return e.getValue<std::string>(nullptr);
    }

    std::string choice(const std::string& key, const std::string& def, const std::vector<std::string>& allowed,
                       bool required = false)
    {
        const std::string v = text(key, def, required);
        if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
        {
            std::string list;
            for (const auto& a : allowed)
                list += (list.empty() ? "" : ", ") + a;
            std::string best;
            std::size_t bestD = std::max<std::size_t>(3, v.size() / 3 + 1);
            for (const auto& a : allowed)
            {
                const std::size_t d = editDistance(v, a);
                if (d < bestD)
                {
                    bestD = d;
                    best = a;
                }
            }
            fail(key, "'" + v + "' is not one of: " + list + (best.empty() ? "" : " (did you mean '" + best + "'?)"));
        }
        return v;
    }

    //! A list of 1 to 3 numbers.
    std::vector<double> vector(const std::string& key, bool required = false)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
        {
            if (required)
                missing(key, "(a list like [0.0, 0.0] is required)");
            return {};
        }
        const auto& e = list_.getEntry(key);
        std::vector<double> v;
        if (e.isType<Teuchos::Array<double>>())
            for (double d : e.getValue<Teuchos::Array<double>>(nullptr))
                v.push_back(d);
        else if (e.isType<Teuchos::Array<int>>())
            for (int d : e.getValue<Teuchos::Array<int>>(nullptr))
                v.push_back(d);
        else if (e.isType<Teuchos::Array<std::string>>())
            for (const auto& s : e.getValue<Teuchos::Array<std::string>>(nullptr))
            {
                double d;
                if (!parseNumber(s, d))
                    fail(key, "'" + s + "' is not a number");
                v.push_back(d);
            }
        else
            fail(key, "expected a list of numbers like [0.0, 0.0], found " + toString(e));
        if (v.empty() || v.size() > 3)
            fail(key, "expected 1 to 3 numbers, found " + std::to_string(v.size()));
        return v;
    }

    //! A list of 1 to 3 constants or expressions of x, y, z, r.
    std::vector<Expr> expressions(const std::string& key)
    {
        std::vector<Expr> out;
        const auto& e = list_.getEntry(key);
        if (!e.isType<Teuchos::Array<std::string>>())
        {
            for (double d : vector(key))
                out.push_back(Expr{"", d});
            return out;
        }
        used_.insert(key);
        for (const auto& item : e.getValue<Teuchos::Array<std::string>>(nullptr))
        {
            Expr x;
            if (!parseNumber(item, x.value))
            {
                x.text = item;
                try
                {
                    Expression compiled(item);
                    x.value = compiled(0.0, 0.0, 0.0);
                }
                catch (const std::exception& err)
                {
                    fail(key, err.what());
                }
            }
            out.push_back(x);
        }
        if (out.empty() || out.size() > 3)
            fail(key, "expected 1 to 3 components, found " + std::to_string(out.size()));
        return out;
    }

    //! A constant or an expression of x, y, z, r (checked by compiling it).
    Expr expression(const std::string& key, bool required)
    {
        used_.insert(key);
        if (!list_.isParameter(key))
        {
            if (required)
                missing(key, "(a number or an expression of x, y, z, r is required)");
            return {};
        }
        const auto& e = list_.getEntry(key);
        Expr x;
        if (e.isType<std::string>())
        {
            x.text = e.getValue<std::string>(nullptr);
            try
            {
                Expression compiled(x.text);
                x.value = compiled(0.0, 0.0, 0.0);
            }
            catch (const std::exception& err)
            {
                fail(key, err.what());
            }
            return x;
        }
        x.value = number(key, 0.0);
        if (!std::isfinite(x.value))
            fail(key, "must be finite");
        return x;
    }

    //! Every key not read is an error, with the closest known key as a hint.
    void rejectUnknown() const
    {
        for (auto it = list_.begin(); it != list_.end(); ++it)
        {
            const std::string& k = list_.name(it);
            if (used_.count(k))
                continue;
            std::string best;
            std::size_t bestD = 4;
            for (const auto& u : used_)
            {
                const std::size_t d = editDistance(k, u);
                if (d < bestD)
                {
                    bestD = d;
                    best = u;
                }
            }
            fail(k, "unknown key" + (best.empty() ? std::string() : " (did you mean '" + join(best) + "'?)"));
        }
    }

  private:
    static std::string toString(const Teuchos::ParameterEntry& e)
    {
        std::ostringstream os;
        os << "'" << e.getAny(false) << "'";
        return os.str();
    }

    std::string file_, path_;
    const ParameterList& list_;
    std::set<std::string> used_;
    static const ParameterList empty_;
};

const ParameterList Node::empty_;

std::string resolve(const std::string& dir, const std::string& p)
{
    if (p.empty())
        return p;
    const fs::path path(p);
    return (path.is_absolute() ? path : fs::path(dir) / path).lexically_normal().string();
}

//! Apply one "a.b.c=value" override; the value's type follows the entry it replaces, else is inferred.
void applyOverride(ParameterList& root, const std::string& file, const std::string& assignment)
{
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(file + ": --set '" + assignment + "': expected key.path=value");
    const std::string path = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    ParameterList* list = &root;
    std::size_t start = 0, dot;
    while ((dot = path.find('.', start)) != std::string::npos)
    {
        const std::string part = path.substr(start, dot - start);
        if (list->isParameter(part) && !list->isSublist(part))
            throw InputError(file + ": --set '" + path + "': '" + part + "' is a value, not a section");
        list = &list->sublist(part);
        start = dot + 1;
    }
    const std::string key = path.substr(start);
    double d;
    if (list->isType<std::string>(key) || (!parseNumber(value, d) && value != "true" && value != "false" &&
                                             (value.empty() || value.front() != '[')))
        list->set(key, value);
    else if (value == "true" || value == "false")
        list->set(key, value == "true");
    else if (!value.empty() && value.front() == '[')
    {
        Teuchos::Array<double> arr;
        std::string body = value.substr(1, value.find(']') == std::string::npos ? std::string::npos : value.find(']') - 1);
        std::stringstream ss(body);
        std::string item;
        while (std::getline(ss, item, ','))
        {
            item.erase(0, item.find_first_not_of(' '));
            item.erase(item.find_last_not_of(' ') + 1);
            if (!parseNumber(item, d))
                throw InputError(file + ": --set '" + path + "': '" + item + "' is not a number");
            arr.push_back(d);
        }
        list->set(key, arr);
    }
    else if (list->isType<int>(key) || (!list->isParameter(key) && value.find_first_of(".eE") == std::string::npos))
        list->set(key, int(std::lround(d)));
    else
        list->set(key, d);
}

//! Strain relaxation laws (gpr.md 1.4) and the keys of strain_relaxation each one takes besides 'law'.
const std::vector<std::pair<std::string, std::vector<std::string>>> kStrainLaws = {
    {"fluid", {}}, {"viscous", {"viscosity"}}, {"elastic", {}}, {"constant", {"tau1"}},
    {"plastic", {"tau10", "yield_stress", "exponent"}}};

/*! \brief strain_relaxation of a material (gpr.md 1.4): the law, its parameters and tau1.
 *  Needs spec.rho0 and spec.shearSpeed. */
void readStrainRelaxation(Node& m, MaterialSpec& spec)
{
    const bool given = m.has("strain_relaxation");
    Node st = m.sub("strain_relaxation");
    std::vector<std::string> laws;
    for (const auto& law : kStrainLaws)
        laws.push_back(law.first);
    spec.strainLaw = st.choice("law", "fluid", laws, given);
    // a parameter of another law is a mistake (e.g. viscosity with law plastic), not an unknown key
    for (const auto& [law, keys] : kStrainLaws)
        for (const auto& k : keys)
            if (law != spec.strainLaw && st.has(k))
                st.fail(k, "belongs to law '" + law + "', not to law '" + spec.strainLaw + "' (key '" +
                               st.join("law") + "')");

    if (spec.strainLaw == "fluid")
    {
        if (spec.shearSpeed != 0.0)
            m.fail("shear_sound_speed",
                   "an ideal fluid (strain_relaxation law 'fluid', the default) has no shear stiffness, found " +
                       num(spec.shearSpeed) +
                       "; for the hydrodynamic limit of GPR give 'strain_relaxation: {law: constant, tau1: 1e-14}'");
        spec.tau1 = 0.0;
    }
    else if (!(spec.shearSpeed > 0.0))
        m.fail("shear_sound_speed", "strain relaxation law '" + spec.strainLaw + "' needs a shear sound speed > 0, found " +
                                        num(spec.shearSpeed));

    if (spec.strainLaw == "viscous")
    {
        spec.viscosity = st.positive("viscosity", 0.0, true);
        spec.tau1 = 6.0 * spec.viscosity / (spec.rho0 * spec.shearSpeed * spec.shearSpeed); // gpr.md 1.4
    }
    else if (spec.strainLaw == "elastic")
        spec.tau1 = std::numeric_limits<double>::infinity();
    else if (spec.strainLaw == "constant")
        spec.tau1 = st.positive("tau1", 0.0, true);
    else if (spec.strainLaw == "plastic")
    {
        spec.tau10 = st.positive("tau10", 0.0, true);
        spec.yieldStress = st.positive("yield_stress", 0.0, true);
        spec.exponent = st.positive("exponent", 0.0, true);
    }
    st.rejectUnknown();
}

//! heat_conduction of a material (gpr.md 1.2, 1.4): alpha, theta0 and one of kappa, tau2. Needs spec.rho0.
void readHeatConduction(Node& m, MaterialSpec& spec)
{
    spec.heatConduction = m.has("heat_conduction");
    Node h = m.sub("heat_conduction");
    if (!spec.heatConduction)
        return;
    spec.alpha = h.positive("alpha", 0.0, true);
    spec.theta0 = h.positive("reference_temperature", 0.0, true);
    const bool kappa = h.has("kappa"), tau2 = h.has("tau2");
    if (kappa == tau2)
        h.fail("kappa", std::string(kappa ? "given together with 'tau2'" : "missing") +
                            ": give exactly one of 'kappa' (Fourier conductivity) and 'tau2' (relaxation time)");
    // kappa = tau2 alpha^2 theta0 / rho0 (gpr.md 1.2)
    const double scale = spec.alpha * spec.alpha * spec.theta0 / spec.rho0;
    if (kappa)
    {
        spec.kappa = h.positive("kappa", 0.0, true);
        spec.tau2 = spec.kappa / scale;
    }
    else
    {
        spec.tau2 = h.positive("tau2", 0.0, true);
        spec.kappa = spec.tau2 * scale;
    }
    if (!(spec.tau2 > 0.0) || !std::isfinite(spec.tau2) || !(spec.kappa > 0.0) || !std::isfinite(spec.kappa))
        h.fail(kappa ? "kappa" : "tau2", "gives kappa = " + num(spec.kappa) + " and tau2 = " + num(spec.tau2) +
                                             ", both must be positive and finite");
    h.rejectUnknown();
}

//! One entry of 'materials'.
MaterialSpec readMaterial(Node& m)
{
    MaterialSpec spec;
    spec.eos = m.choice("eos", "", {"ideal_gas", "mie_gruneisen", "neo_hookean"}, true);
    spec.cv = m.positive("cv", 1.0);
    if (spec.eos == "ideal_gas")
    {
        spec.gamma = m.number("gamma", 1.4);
        if (!(spec.gamma > 1.0) || !std::isfinite(spec.gamma))
            m.fail("gamma", "an ideal gas needs gamma > 1, found " + num(spec.gamma));
        spec.rho0 = m.positive("rho0", 1.0);
    }
    else if (spec.eos == "mie_gruneisen")
    {
        spec.rho0 = m.positive("rho0", 0.0, true);
        spec.c0 = m.positive("c0", 0.0, true);
        spec.Gamma0 = m.positive("Gamma0", 0.0, true);
        spec.s = m.nonNegative("s", 0.0);
    }
    else
    {
        spec.rho0 = m.positive("rho0", 0.0, true);
        spec.csh = m.positive("csh", 0.0, true);
    }
    spec.shearSpeed = m.nonNegative("shear_sound_speed", 0.0);
    readStrainRelaxation(m, spec);
    readHeatConduction(m, spec);
    m.rejectUnknown();
    return spec;
}

} // namespace

Scene readScene(const std::string& file, const std::vector<std::string>& overrides)
{
    if (!fs::exists(file))
        throw InputError(file + ": scene file not found");
    Teuchos::RCP<ParameterList> top;
    try
    {
        top = Teuchos::getParametersFromYamlFile(file);
    }
    catch (const std::exception& e)
    {
        std::string msg = e.what();
        // keep the parser's first line: it names the line and column
        const auto nl = msg.find('\n', msg.find_first_not_of('\n'));
        throw InputError(file + ": malformed YAML: " + msg.substr(0, nl));
    }
    if (top->name() != "unilag")
        throw InputError(file + ": the top-level key must be 'unilag:', found '" + top->name() + "'");
    for (const auto& o : overrides)
        applyOverride(*top, file, o);

    Scene s;
    s.file = file;
    s.directory = fs::path(file).parent_path().string();
    if (s.directory.empty())
        s.directory = ".";
    s.name = fs::path(file).stem().string();
    Node root(file, "", *top);
    s.name = root.text("title", s.name);

    {
        Node mesh = root.sub("mesh", true);
        s.geometry = resolve(s.directory, mesh.text("geometry", ""));
        s.meshFile = resolve(s.directory, mesh.text("file", ""));
        if (s.geometry.empty() == s.meshFile.empty())
            mesh.fail("geometry", "give exactly one of 'geometry' (a .geo to mesh) and 'file' (a .msh to read)");
        if (!s.geometry.empty())
        {
            s.meshSize = mesh.positive("size", 0.0, true);
            if (!fs::exists(s.geometry))
                mesh.fail("geometry", "file not found: " + s.geometry);
        }
        else if (!fs::exists(s.meshFile))
            mesh.fail("file", "file not found: " + s.meshFile);
        mesh.rejectUnknown();
    }
    {
        Node mats = root.sub("materials", true);
        for (const auto& name : mats.keys())
        {
            Node m = mats.sub(name);
            const MaterialSpec spec = readMaterial(m);
            s.materials[name] = spec;
        }
        if (s.materials.empty())
            root.fail("materials", "at least one material is required");
    }
    {
        Node regions = root.sub("regions", true);
        for (const auto& name : regions.keys())
        {
            Node r = regions.sub(name);
            RegionSpec spec;
            spec.material = r.text("material", "", true);
            if (!s.materials.count(spec.material))
                r.fail("material", "unknown material '" + spec.material + "' (not in 'materials')");
            spec.density = r.expression("density", true);
            if (spec.density.isConstant() && !(spec.density.value > 0.0))
                r.fail("density", "must be positive, found " + num(spec.density.value));
            const bool p = r.has("pressure"), e = r.has("specific_internal_energy");
            if (p == e)
                r.fail("pressure", "give exactly one of 'pressure' and 'specific_internal_energy'");
            spec.hasPressure = p;
            if (p)
                spec.pressure = r.expression("pressure", true);
            else
                spec.internalEnergy = r.expression("specific_internal_energy", true);
            const Expr& th = p ? spec.pressure : spec.internalEnergy;
            if (th.isConstant() && !(th.value >= 0.0))
                r.fail(p ? "pressure" : "specific_internal_energy", "must be non-negative");
            if (r.has("velocity"))
            {
                auto v = r.expressions("velocity");
                spec.velocityComponents = int(v.size());
                for (std::size_t d = 0; d < v.size(); ++d)
                    spec.velocity[d] = v[d];
            }
            r.rejectUnknown();
            s.regions[name] = spec;
        }
        if (s.regions.empty())
            root.fail("regions", "at least one region (a gmsh physical group of cells) is required");
    }
    {
        Node bcs = root.sub("boundaries", true);
        for (const auto& name : bcs.keys())
        {
            Node b = bcs.sub(name);
            BoundarySpec spec;
            spec.type =
                b.choice("type", "", {"free", "slip_wall", "symmetry", "velocity", "pressure", "traction"}, true);
            // the value key of each type is its name; a value key of another type is a mistake
            for (const char* other : {"velocity", "pressure", "traction"})
                if (spec.type != other && b.has(other))
                    b.fail(other, std::string("only a boundary of type '") + other + "' takes '" + other +
                                      "', this one is '" + spec.type + "'");
            if (spec.type == "velocity")
            {
                auto v = b.vector("velocity", true);
                for (std::size_t d = 0; d < v.size(); ++d)
                    spec.velocity[d] = v[d];
            }
            if (spec.type == "pressure")
                spec.pressure = b.expression("pressure", true);
            if (spec.type == "traction")
            {
                auto v = b.vector("traction", true);
                if (v.size() < 2)
                    b.fail("traction", "expected a traction vector of 2 or 3 numbers, found " + std::to_string(v.size()));
                for (std::size_t d = 0; d < v.size(); ++d)
                    if (!std::isfinite(v[d]))
                        b.fail("traction", "must be finite");
                for (std::size_t d = 0; d < v.size(); ++d)
                    spec.traction[d] = v[d];
            }
            spec.thermal = b.choice("thermal", "adiabatic", {"adiabatic", "isothermal"});
            if (spec.thermal == "isothermal")
                spec.temperature = b.positive("temperature", 0.0, true);
            else if (b.has("temperature"))
                b.fail("temperature", "only an isothermal boundary takes a temperature (give 'thermal: isothermal')");
            b.rejectUnknown();
            s.boundaries[name] = spec;
        }
    }
    if (root.has("energy_deposit"))
    {
        Node dep = root.sub("energy_deposit");
        s.hasDeposit = true;
        auto pos = dep.vector("position", true);
        for (std::size_t d = 0; d < pos.size(); ++d)
            s.depositPosition[d] = pos[d];
        s.depositEnergy = dep.positive("energy", 0.0, true);
        dep.rejectUnknown();
    }
    {
        Node t = root.sub("time", true);
        s.endTime = t.positive("end", 0.0, true);
        s.cfl = t.positive("cfl", s.cfl);
        if (s.cfl > 1.0)
            t.fail("cfl", "must be in (0, 1], found " + num(s.cfl));
        s.maxVolumeChange = t.positive("max_volume_change", s.maxVolumeChange);
        s.initialTimeStep = t.nonNegative("initial_dt", 0.0);
        s.maxGrowth = t.positive("max_growth", s.maxGrowth);
        if (s.maxGrowth < 1.0)
            t.fail("max_growth", "must be >= 1");
        s.maxSteps = t.integer("max_steps", s.maxSteps, 1, 2000000000L);
        s.maxRetries = int(t.integer("max_retries", s.maxRetries, 0, 60));
        t.rejectUnknown();
    }
    {
        Node sch = root.sub("scheme");
        s.picardTolerance = sch.positive("picard_tolerance", s.picardTolerance);
        s.picardMaxIterations = int(sch.integer("picard_max_iterations", s.picardMaxIterations, 1, 1000000));
        s.order = int(sch.integer("order", s.order, 1, 2));
        s.limiter = sch.choice("limiter", s.limiter, {"barth_jespersen", "vertex_based", "none"});
        sch.rejectUnknown();
    }
    {
        Node o = root.sub("output");
        s.outputDirectory = o.text("directory", "output/" + s.name);
        if (s.outputDirectory.empty())
            o.fail("directory", "must not be empty");
        s.outputInterval = o.nonNegative("interval", 0.0);
        s.writeOutput = o.boolean("enabled", true);
        o.rejectUnknown();
    }
    if (root.has("exact"))
    {
        Node x = root.sub("exact");
        s.exactSolution = x.choice("solution", "none", {"none", "sedov"});
        const bool sedov = s.exactSolution == "sedov";
        s.exactTable = resolve(s.directory, x.text("table", "", sedov));
        if (sedov && !fs::exists(s.exactTable))
            x.fail("table", "file not found: " + s.exactTable);
        s.exactShockRadius = x.positive("shock_radius", 1.0, sedov);
        s.exactTime = x.positive("time", 1.0);
        if (x.has("boundary_radius"))
        {
            Node radii = x.sub("boundary_radius");
            for (const auto& group : radii.keys())
                s.boundaryRadius[group] = radii.positive(group, 0.0, true);
            radii.rejectUnknown();
        }
        s.radiusTolerance = x.nonNegative("radius_tolerance", 0.0);
        s.maxL1Density = x.nonNegative("max_l1_density", 0.0);
        s.shockRadiusTolerance = x.nonNegative("shock_radius_tolerance", 0.0);
        x.rejectUnknown();
    }
    root.rejectUnknown();
    s.resolved = *top;
    return s;
}

void writeScene(const Scene& scene, const std::string& file)
{
    Teuchos::writeParameterListToYamlFile(scene.resolved, file);
}

} // namespace unilag
