/*! \file
 *  \brief The words Teuchos' YAML reader would turn into numbers inside a list. */
#pragma once

#include <string>

namespace unilag::config
{

/*! Throws InputError naming the line if a list of the YAML text `text` (of `file`) holds an unquoted true / false /
 *  yes / no: Teuchos 13.2 types a list by its numbers and then reads every item as one, so [true, 0.0] became
 *  [0, 0] silently. Flow lists ([a, b]) and block lists ("- a") are scanned; quoted items and comments are not. */
void rejectWordsInLists(const std::string& file, const std::string& text);

} // namespace unilag::config
