// A Lua file's bytes as Lua is given them, and what to tell a student whose file is not UTF-8 text. Every student file
// goes through here, whoever reads it (the window, the page's worker, the grader), so each says the same thing.
//
// Invariants:
// - lua_source_text does what lua.c does to a file before loading it: a UTF-8 byte order mark is dropped, and a first
//   line starting with '#' (a shebang) becomes a comment; nothing else changes, so line numbers stay the file's.
// - encoding_note is "" for UTF-8 text (ASCII included); otherwise one sentence naming the file, what it looks like
//   (UTF-16, or the first byte that is not UTF-8 and its line) and what to do: save it as UTF-8. Lua itself reads any
//   bytes in strings and comments, so a file that is not UTF-8 still loads; the note is added to an error it gets.
#pragma once

#include <string>
#include <string_view>

namespace meshedit {

std::string lua_source_text(std::string bytes);
std::string encoding_note(std::string_view text, const std::string& name);
// `error` with encoding_note's sentence after it in brackets, when there is one.
std::string with_encoding_note(const std::string& error, std::string_view text, const std::string& name);

}  // namespace meshedit
