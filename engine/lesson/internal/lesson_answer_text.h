// What a student types into a lesson's answer box (answer{} in lesson_questions.h), read as numbers: "0.375", "3/8",
// "-1e-3", and points as "0.5, 1", "(0.5, 1, 0)", "0.5 1" or "{0.5; 1}".
//
// Invariants: a text is read whole or not at all: it gives exactly `components` finite numbers, separated by commas,
// semicolons or spaces and optionally wrapped in one pair of (), [] or {}; each number is a decimal (strtod's form, no
// hex, no inf or nan) or a fraction a/b of two decimals with b not 0. Anything else gives nullopt.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace meshedit {

std::optional<std::vector<double>> parse_answer_text(std::string_view text, size_t components);

// What to tell a student whose text could not be read: "Type a number, like 0.25 or 3/8." for 1 component, "Type a
// point as x, y, like 0.5, 1." for 2, "Type a point as x, y, z, like 0.5, 1, 0." for 3.
std::string answer_text_help(size_t components);

}  // namespace meshedit
