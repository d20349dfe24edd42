// The write-up as files: index.html, one self-contained page (its pictures inside as data: addresses, so it uploads
// anywhere), and writeup.md with the pictures beside it in figures/ (for a course that takes Markdown).
//
// Invariants:
// - Both files hold the same parts, figures, captions, numbers, tables, problems and questions, in the same order.
// - Under each part's questions is an empty place for the student's explanation, marked as theirs to write; nothing
//   here writes an explanation for them.
// - A picture that could not be drawn (its `png` is empty) is a marked gap that says so, never a missing image link.
// - Text from the student's code (an error message) is escaped in the page and in the Markdown.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "writeup/writeup.h"

namespace meshedit {

struct WriteupFiles {
  std::string html;                                         // index.html
  std::string markdown;                                     // writeup.md
  std::vector<std::pair<std::string, std::string>> images;  // "figures/4.1-b.png" and its bytes
};

WriteupFiles writeup_files(const Writeup& writeup);

// Writes the files into `folder` (made when missing); "" when every file was written, else what was not.
std::string write_writeup_files(const WriteupFiles& files, const std::filesystem::path& folder);

}  // namespace meshedit
