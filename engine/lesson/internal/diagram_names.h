// The names a lesson's diagram gives the elements on screen (lesson 4's h0..h9, a..d, e, f0, f1), set beside the
// storage ids a diagnosis speaks in: your_turn{ ..., names = {a = v2, h0 = "h3", ...} } makes a wrong verdict end
// with "(the diagram's labels: h3 is labelled h0, v2 is labelled a)", so the student reads the checker's and the
// grader's words and the names the lesson drew.
//
// Invariants:
// - The legend names only ids that stand in the text as whole words ("h3", not the "h3" of "h37"), each once, in
//   the order they first appear; an id whose diagram name is the id itself is left out. No such id: no legend.
// - The diagnosis itself is never changed, so it stays word for word the Exercises tab's and the grader's.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace meshedit {

// Diagram names by storage id: {"h3", "h0"} says the diagram calls h3 "h0".
using DiagramNames = std::vector<std::pair<std::string, std::string>>;

// "(the diagram's labels: h3 is labelled h0, v2 is labelled a)" for the ids of `names` that `text` mentions, or "".
std::string diagram_legend(const std::string& text, const DiagramNames& names);

}  // namespace meshedit
