/*! \file
 *  \brief What Teuchos' YAML reader would take silently: words it turns into numbers inside a list, top-level keys
 *  beside the scene's section. */
#pragma once

#include <string>

namespace unilag::config
{

/*! Throws InputError naming the line if a list of the YAML text `text` (of `file`) holds an unquoted true / false /
 *  yes / no: Teuchos 13.2 types a list by its numbers and then reads every item as one, so [true, 0.0] became
 *  [0, 0] silently. Flow lists ([a, b]) and block lists ("- a") are scanned; quoted items and comments are not. */
void rejectWordsInLists(const std::string& file, const std::string& text);

/*! Throws InputError naming the line if the YAML text `text` (of `file`) has a top-level key other than `top`:
 *  Teuchos keeps the one section and drops a scalar beside it ("other: 1" before "unilag:") without a word. */
void rejectOtherTopLevelKeys(const std::string& file, const std::string& text, const std::string& top);

} // namespace unilag::config
