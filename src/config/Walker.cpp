#include "config/Walker.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <Teuchos_YamlParameterListHelpers.hpp>

#include "config/ListWords.hpp"
#include "physics/Expression.hpp"

namespace unilag::config
{
namespace
{

namespace fs = std::filesystem;

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

bool parseNumber(const std::string& s, double& out)
{
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return !s.empty() && end && *end == '\0';
}

//! An entry as the scene wrote it, on one line (error messages are one line): a value, a list or a section.
std::string entryText(const Teuchos::ParameterEntry& e)
{
    if (e.isList())
        return "a section of keys";
    if (e.isTwoDArray()) // [[1]]: Teuchos prints it as 1x1:{1}
        return "a list of lists";
    if (e.isType<bool>())
        return e.getValue<bool>(nullptr) ? "'true'" : "'false'";
    std::ostringstream os;
    if (e.isType<Teuchos::Array<double>>()) // as written, not at Teuchos' 17 digits
    {
        const auto& a = e.getValue<Teuchos::Array<double>>(nullptr);
        os << "{";
        for (decltype(a.size()) k = 0; k < a.size(); ++k)
            os << (k ? ", " : "") << a[k];
        os << "}";
    }
    else
        os << e.getAny(false);
    std::string text = os.str();
    for (char& c : text)
        if (c == '\n' || c == '\r')
            c = ' ';
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    if (e.isArray() && text.size() >= 2) // Teuchos prints arrays as {1, 2}; the scene wrote [1, 2]
        return "a list [" + text.substr(1, text.size() - 2) + "]";
    return "'" + text + "'";
}

const Teuchos::ParameterList& emptyList()
{
    static const Teuchos::ParameterList empty;
    return empty;
}

/*! The list of a --set value "[a, b, c]": numbers if every item is one, else text items (quotes removed), as the
 *  YAML parser gives a list that mixes expressions and numbers (velocity: ["x < 0 ? -2 : 2", 0]). */
Teuchos::ParameterEntry listValue(const std::string& value)
{
    const auto close = value.rfind(']');
    const std::string body = value.substr(1, close == std::string::npos || close == 0 ? std::string::npos : close - 1);
    if (body.find_first_not_of(' ') == std::string::npos)
        return Teuchos::ParameterEntry(Teuchos::Array<double>()); // [] (refused by the reader, naming the key)
    std::vector<std::string> parts(1); // split at the commas outside quotes and parentheses: max(r, 1e-12) is one
    int depth = 0;
    char quote = 0;
    for (char ch : body)
    {
        if (quote)
            quote = ch == quote ? 0 : quote;
        else if (ch == '"' || ch == '\'')
            quote = ch;
        else if (ch == '(')
            ++depth;
        else if (ch == ')')
            --depth;
        else if (ch == ',' && depth == 0)
        {
            parts.emplace_back();
            continue;
        }
        parts.back() += ch;
    }
    Teuchos::Array<std::string> items;
    Teuchos::Array<double> numbers;
    bool allNumbers = true;
    for (std::string item : parts)
    {
        item.erase(0, item.find_first_not_of(' '));
        item.erase(item.find_last_not_of(' ') + 1);
        if (item.size() >= 2 && (item.front() == '"' || item.front() == '\'') && item.back() == item.front())
            item = item.substr(1, item.size() - 2);
        double d;
        allNumbers = allNumbers && parseNumber(item, d);
        numbers.push_back(allNumbers ? d : 0.0);
        items.push_back(item);
    }
    return allNumbers ? Teuchos::ParameterEntry(numbers) : Teuchos::ParameterEntry(items);
}

//! Apply one "a.b.c=value" override; a text entry stays text, a number is an integer only if written as one.
void applyOverride(Teuchos::ParameterList& root, const std::string& file, const std::string& assignment)
{
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw InputError(file + ": --set '" + assignment + "': expected key.path=value");
    const std::string path = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    Teuchos::ParameterList* list = &root;
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
    if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') && value.back() == value.front())
    {
        list->set(key, value.substr(1, value.size() - 2)); // a quoted scalar is a string, as in the file
        return;
    }
    double d;
    if (list->isType<std::string>(key) ||
        (!parseNumber(value, d) && value != "true" && value != "false" && (value.empty() || value.front() != '[')))
        list->set(key, value);
    else if (value == "true" || value == "false")
        list->set(key, value == "true");
    else if (!value.empty() && value.front() == '[')
        list->setEntry(key, listValue(value));
    else if (value.find_first_of(".eE") == std::string::npos && std::abs(d) <= 2147483647.0 && d == std::trunc(d))
        list->set(key, int(d));
    else // typed by the value, not the entry it replaces: 0.002 over `interval: 0` must not become 0
        list->set(key, d);
}

/*! The parser's "error: Parser failure at line N column M of FILE" with line N's text instead of the file name
 *  (-.inf or [] in a scene gave only the position); any other message as it is. */
std::string withLineText(const std::string& message, const std::string& text)
{
    long line = 0, column = 0;
    const auto at = message.find("Parser failure at line ");
    if (at == std::string::npos ||
        std::sscanf(message.c_str() + at, "Parser failure at line %ld column %ld", &line, &column) != 2 || line < 1)
        return message;
    std::size_t begin = 0;
    for (long k = 1; k < line; ++k)
    {
        begin = text.find('\n', begin);
        if (begin == std::string::npos)
            return message;
        ++begin;
    }
    std::string l = text.substr(begin, text.find('\n', begin) - begin);
    l.erase(l.find_last_not_of(" \t\r") + 1);
    l.erase(0, l.find_first_not_of(" \t"));
    return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": the YAML reader cannot parse '" +
           printable(l, 80) + "'";
}

} // namespace

std::string num(double v)
{
    std::ostringstream os;
    os << v;
    return os.str();
}

void refuseTooManyDumps(const ConfigNode& node, const std::string& key, double interval, double endTime,
                        const std::string& what, const std::string& zero)
{
    constexpr double maxDumps = 1e5;
    if (interval > 0.0 && endTime / interval > maxDumps)
        node.fail(key, num(interval) + " makes " + num(std::floor(endTime / interval)) + " " + what +
                           " to the end time " + num(endTime) + ": at most 100000 (0 " + zero + ")");
}

std::string resolvePath(const std::string& dir, const std::string& p)
{
    if (p.empty())
        return p;
    const fs::path path(p);
    return (path.is_absolute() ? path : fs::path(dir) / path).lexically_normal().string();
}

std::string inputFileProblem(const std::string& path)
{
    std::error_code ec; // the throwing overloads stopped a 300-character name with an internal error
    const fs::file_status st = fs::status(path, ec);
    if (st.type() == fs::file_type::not_found)
        return "file not found";
    if (ec)
        return ec.message();
    return fs::is_regular_file(st) ? "" : "not a regular file";
}

Teuchos::RCP<Teuchos::ParameterList> readYaml(const std::string& file, const std::string& top,
                                              const std::vector<std::string>& overrides)
{
    const std::string problem = inputFileProblem(file);
    if (problem == "file not found")
        throw InputError(file + ": scene file not found");
    if (!problem.empty())
        throw InputError(file + ": " + problem);
    std::ifstream in(file);
    const std::string text(std::istreambuf_iterator<char>(in), {});
    rejectWordsInLists(file, text);
    rejectOtherTopLevelKeys(file, text, top);
    Teuchos::RCP<Teuchos::ParameterList> list;
    try
    {
        list = Teuchos::getParametersFromYamlFile(file);
    }
    catch (const std::exception& e)
    {
        std::string msg = e.what();
        // keep the parser's first line: it names the line and column; a Teuchos assertion's first line is its own
        // source path (a list or section inside a list, a list as the top-level entry), which tells a user nothing
        const auto nl = msg.find('\n', msg.find_first_not_of('\n'));
        std::string first = msg.substr(0, nl);
        if (first.find(".hpp:") != std::string::npos || first.find(".cpp:") != std::string::npos)
            first = "a list or section where a single value belongs (inside a list such as [0.0, [1]], or as the "
                    "top-level entry); the YAML reader does not say which line";
        throw InputError(file + ": malformed YAML: " + withLineText(first, text));
    }
    if (list->name() != top)
        throw InputError(file + ": the top-level key must be '" + top + ":', found '" + list->name() + "'");
    for (const auto& o : overrides)
        applyOverride(*list, file, o);
    return list;
}

ConfigNode::ConfigNode(const std::string& file, const std::string& path, const Teuchos::ParameterList& list)
    : file_(file), path_(path), list_(list)
{
}

void ConfigNode::fail(const std::string& key, const std::string& what) const
{
    throw InputError(file_ + ": key '" + join(key) + "': " + what);
}
//! A required key is absent: the error also names a key present but not read that looks like a misspelling.
void ConfigNode::missing(const std::string& key, const std::string& what) const
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

ConfigNode ConfigNode::sub(const std::string& key, bool required)
{
    used_.insert(key);
    if (!list_.isParameter(key))
    {
        if (required)
            missing(key, "(a section is required here)");
        return ConfigNode(file_, join(key), emptyList());
    }
    if (!list_.isSublist(key))
        fail(key, "expected a section of keys, found a value");
    return ConfigNode(file_, join(key), list_.sublist(key));
}

//! Names of all entries (for sections keyed by user names: materials, regions, boundaries).
std::vector<std::string> ConfigNode::keys() const
{
    std::vector<std::string> k;
    for (auto it = list_.begin(); it != list_.end(); ++it)
        k.push_back(list_.name(it));
    return k;
}

double ConfigNode::number(const std::string& key, double def, bool required)
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
    fail(key, "expected a number, found " + entryText(e));
}

double ConfigNode::positive(const std::string& key, double def, bool required)
{
    const double v = number(key, def, required);
    if (!(v > 0.0) || !std::isfinite(v))
        fail(key, "must be a positive number, found " + num(v));
    return v;
}

double ConfigNode::nonNegative(const std::string& key, double def)
{
    const double v = number(key, def);
    if (!(v >= 0.0) || !std::isfinite(v))
        fail(key, "must be a non-negative number, found " + num(v));
    return v;
}

long ConfigNode::integer(const std::string& key, long def, long lo, long hi)
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
    else if (e.isType<double>() && std::abs(e.getValue<double>(nullptr)) < 1e18 &&
             e.getValue<double>(nullptr) == std::trunc(e.getValue<double>(nullptr)))
        v = long(e.getValue<double>(nullptr)); // 2.0 or 1e5 written for an integer
    else
        fail(key, "expected an integer, found " + entryText(e));
    if (v < lo || v > hi)
        fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], found " + std::to_string(v));
    return v;
}

bool ConfigNode::boolean(const std::string& key, bool def)
{
    used_.insert(key);
    if (!list_.isParameter(key))
        return def;
    const auto& e = list_.getEntry(key);
    if (e.isType<bool>())
        return e.getValue<bool>(nullptr);
    fail(key, "expected true or false, found " + entryText(e));
}

std::string ConfigNode::text(const std::string& key, const std::string& def, bool required)
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
        fail(key, "expected a string, found " + entryText(e));
    return e.getValue<std::string>(nullptr);
}

std::string ConfigNode::choice(const std::string& key, const std::string& def, const std::vector<std::string>& allowed,
                               bool required)
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

//! A list of numbers of any length (a single number is a list of one).
std::vector<double> ConfigNode::numbers(const std::string& key, bool required)
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
    else if (e.isType<double>() || e.isType<int>())
        v.push_back(number(key, 0.0));
    else
        fail(key, "expected a list of numbers like [0.0, 0.0], found " + entryText(e));
    if (v.empty())
        fail(key, "expected at least one number, found an empty list");
    return v;
}

//! A list of 1 to 3 numbers.
std::vector<double> ConfigNode::vector(const std::string& key, bool required)
{
    if (has(key))
    {
        const auto& e = list_.getEntry(key);
        if (e.isType<double>() || e.isType<int>())
            fail(key, "expected a list of numbers like [0.0, 0.0], found " + entryText(e));
    }
    std::vector<double> v = numbers(key, required);
    if (has(key) && v.size() > 3)
        fail(key, "expected 1 to 3 numbers, found " + std::to_string(v.size()));
    return v;
}

//! A list of 1 to 3 constants or expressions of x, y, z, r.
std::vector<Expr> ConfigNode::expressions(const std::string& key)
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
Expr ConfigNode::expression(const std::string& key, bool required)
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
void ConfigNode::rejectUnknown() const
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

} // namespace unilag::config
