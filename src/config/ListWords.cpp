#include "config/ListWords.hpp"

#include <cctype>

#include "core/Errors.hpp"

namespace unilag::config
{
namespace
{

std::string trimmedLower(const std::string& s, std::string& trimmed)
{
    const auto b = s.find_first_not_of(" \t\r");
    trimmed = b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
    std::string lower;
    for (char c : trimmed)
        lower.push_back(char(std::tolower(static_cast<unsigned char>(c))));
    return lower;
}

void checkItem(const std::string& file, int line, const std::string& item)
{
    std::string trimmed;
    const std::string w = trimmedLower(item, trimmed);
    if (w == "true" || w == "false" || w == "yes" || w == "no")
        throw InputError(file + ": line " + std::to_string(line) + ": '" + trimmed +
                         "' in a list: lists hold numbers or names, not true / false (the YAML reader would take "
                         "it as 0)");
}

} // namespace

void rejectWordsInLists(const std::string& file, const std::string& text)
{
    int depth = 0, line = 1;
    bool lineStart = true; // only blanks so far on this line
    char quote = 0;
    std::string item;
    for (std::size_t i = 0; i < text.size(); ++i)
    {
        const char c = text[i];
        if (quote) // a quoted scalar is a string, whatever it says (outside a list, it ends with its line)
        {
            quote = c == quote || (c == '\n' && depth == 0) ? 0 : quote;
            line += c == '\n';
            lineStart = c == '\n';
            continue;
        }
        if (c == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(text[i - 1]))))
        {
            while (i + 1 < text.size() && text[i + 1] != '\n')
                ++i;
            continue;
        }
        if (depth == 0 && lineStart && c == '-' && i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\t'))
        {
            const std::size_t end = text.find_first_of("#\n", i + 1);
            checkItem(file, line, text.substr(i + 1, end == std::string::npos ? std::string::npos : end - i - 1));
        }
        if (c == '\n')
            ++line;
        lineStart = c == '\n' || (lineStart && (c == ' ' || c == '\t'));
        const bool itemStart = depth > 0 ? item.find_first_not_of(" \t\r\n") == std::string::npos
                                         : i == 0 || std::isspace(static_cast<unsigned char>(text[i - 1])) ||
                                               text[i - 1] == ':';
        if ((c == '"' || c == '\'') && itemStart)
            quote = c;
        else if (c == '[')
            ++depth, item.clear();
        else if (depth > 0 && (c == ',' || c == ']'))
        {
            checkItem(file, line, item);
            item.clear();
            depth -= c == ']';
        }
        else if (depth > 0)
            item.push_back(c == '\n' ? ' ' : c);
    }
}

void rejectOtherTopLevelKeys(const std::string& file, const std::string& text, const std::string& top)
{
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) // the reader's "Unexpected character code -17" names no cause
        throw InputError(file + ": starts with a UTF-8 byte-order mark: save it without one");
    std::size_t begin = 0;
    for (int line = 1; begin < text.size(); ++line)
    {
        std::size_t end = text.find('\n', begin);
        end = end == std::string::npos ? text.size() : end;
        const std::string l = text.substr(begin, end - begin);
        begin = end + 1;
        // a key at column 0: not indented, a comment, a list item, a directive, a document marker or a flow map
        if (l.empty() || std::string(" \t\r#-%.{}[]").find(l[0]) != std::string::npos)
            continue;
        const std::size_t colon = l.find(':');
        if (colon == std::string::npos)
            continue; // not a key: the YAML reader says what it is
        std::string key = l.substr(0, colon);
        key.erase(key.find_last_not_of(" \t") + 1);
        if (key.size() >= 2 && (key[0] == '"' || key[0] == '\'') && key.back() == key[0])
            key = key.substr(1, key.size() - 2);
        if (key != top)
            throw InputError(file + ": line " + std::to_string(line) + ": unknown top-level key '" + key +
                             "': a scene holds one section, '" + top + ":'");
        // 'unilag: ~' or 'unilag: 1': the reader's assertion named no line
        std::string value = l.substr(colon + 1);
        value.erase(0, value.find_first_not_of(" \t\r"));
        value.erase(value.find_last_not_of(" \t\r") + 1);
        if (!value.empty() && value[0] != '#' && value[0] != '{')
            throw InputError(file + ": line " + std::to_string(line) + ": '" + top + ":' holds the value '" +
                             value.substr(0, 40) + "', not a section of keys");
    }
}

} // namespace unilag::config
