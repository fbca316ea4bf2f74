/*! \file StudyArgs.hpp
 *  \brief Arguments and output files of the study executables (apps/tube_*_study.cpp): a malformed number, an
 *  unknown option or an output folder that cannot be written is one message and exit 2, before any work (they ran
 *  on with 0 cells, wrote nothing and exited 0, or crashed on an unchecked fopen).
 */
#pragma once

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

namespace unilag::study
{

[[noreturn]] inline void fail(const char* program, const std::string& message)
{
    std::fprintf(stderr, "%s: error: %s\n", program, message.c_str());
    std::exit(2);
}

//! The whole of text as an integer >= least, or fail naming the argument.
inline int integerArg(const char* program, const char* name, const char* text, int least)
{
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno != 0 || value < least || value > INT_MAX)
        fail(program, std::string(name) + " must be an integer >= " + std::to_string(least) + ", found '" + text + "'");
    return int(value);
}

//! The whole of text as a finite number > 0 (or >= 0 when zero is allowed), or fail naming the argument.
inline double positiveArg(const char* program, const char* name, const char* text, bool zeroAllowed = false)
{
    char* end = nullptr;
    const double value = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(value) || value < 0.0 || (value == 0.0 && !zeroAllowed))
        fail(program, std::string(name) + " must be a number " + (zeroAllowed ? ">= 0" : "> 0") + ", found '" + text +
                          "'");
    return value;
}

//! The output folder, created with its parents if needed; fail naming it if it cannot be.
inline std::string outputFolder(const char* program, const std::string& dir)
{
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir, ec))
        fail(program, "cannot create the output folder '" + dir + "'" + (ec ? ": " + ec.message() : std::string()));
    return dir;
}

//! path opened for writing, or fail naming it.
inline std::FILE* openOutput(const char* program, const std::string& path)
{
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f)
        fail(program, "cannot write " + path + ": " + std::strerror(errno));
    return f;
}

} // namespace unilag::study
