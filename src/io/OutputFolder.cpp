#include "io/OutputFolder.hpp"

#include "core/Errors.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace unilag::io
{

std::string outputFolderProblem(const std::string& dir)
{
    if (dir.empty())
        return "empty folder name";
    std::error_code ec;
    fs::path p = fs::absolute(dir, ec);
    if (ec)
        return ec.message();
    for (const fs::path& part : p) // exists() below takes a name too long for "absent", and the folder for creatable
        if (part.string().size() > 255)
            return "a name in the path is longer than 255 characters";
    if (p.string().size() >= 4096)
        return "the path is 4096 characters or longer";
    // The deepest existing ancestor (or the folder itself): it must be a folder we can create entries in.
    fs::path existing = p;
    while (!fs::exists(existing, ec) && existing.has_relative_path())
        existing = existing.parent_path();
    if (!fs::is_directory(existing, ec))
        return existing.string() + " is not a folder";
    // access() says yes to root everywhere: probe with an entry that is removed at once.
    const fs::path probe = existing / (".unilag-probe-" + std::to_string(::getpid()));
    if (::mkdir(probe.c_str(), 0700) != 0)
        return "cannot create folders in " + existing.string() + ": " + std::strerror(errno);
    ::rmdir(probe.c_str());
    return {};
}

namespace
{

//! unilag_NNNNNN.h5 or unilag_NNNNNN.xmf (at least six digits), the names XdmfWriter gives its dumps.
bool isDumpName(const std::string& name)
{
    const std::string base = "unilag_";
    if (name.compare(0, base.size(), base) != 0)
        return false;
    std::size_t i = base.size(), digits = 0;
    while (i < name.size() && name[i] >= '0' && name[i] <= '9')
        ++i, ++digits;
    const std::string ext = name.substr(i);
    return digits >= 6 && (ext == ".h5" || ext == ".xmf");
}

} // namespace

std::vector<std::string> removeRunOutputs(const std::string& dir)
{
    std::vector<fs::path> own;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    {
        const std::string name = it->path().filename().string();
        std::error_code e2;
        if ((isDumpName(name) || name == "unilag.xmf" || name == "summary.json" || name == "steps.csv" ||
             name == "scene.yaml" || name == "checkpoint.h5" || name == "balance.csv") &&
            it->is_regular_file(e2))
            own.push_back(it->path());
    }
    std::vector<std::string> removed;
    for (const auto& p : own)
        if (fs::remove(p, ec))
            removed.push_back(p.filename().string());
    return removed;
}

void finishOutput(std::ofstream& out, const std::string& file)
{
    if (out.is_open())
        out.close();
    else
        out.setstate(std::ios::failbit); // it never opened
    if (!out)
        throw OutputError("cannot write " + file);
}

} // namespace unilag::io
