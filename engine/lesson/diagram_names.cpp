// diagram_legend (see diagram_names.h).
#include "lesson/internal/diagram_names.h"

#include <algorithm>
#include <cctype>

namespace meshedit {
namespace {

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Where `id` first stands in `text` as a whole word, or npos.
size_t first_word(const std::string& text, const std::string& id) {
  for (size_t at = text.find(id); at != std::string::npos; at = text.find(id, at + 1)) {
    const bool starts = at == 0 || !is_word_char(text[at - 1]);
    const size_t end = at + id.size();
    const bool ends = end == text.size() || !is_word_char(text[end]);
    if (starts && ends) return at;
  }
  return std::string::npos;
}

}  // namespace

std::string diagram_legend(const std::string& text, const DiagramNames& names) {
  std::vector<std::pair<size_t, const std::pair<std::string, std::string>*>> found;
  for (const auto& entry : names) {
    if (entry.first == entry.second) continue;
    const size_t at = first_word(text, entry.first);
    const bool seen =
        std::any_of(found.begin(), found.end(), [&](const auto& f) { return f.second->first == entry.first; });
    if (at != std::string::npos && !seen) found.emplace_back(at, &entry);
  }
  if (found.empty()) return "";
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string legend = "(the diagram's labels: ";
  for (size_t i = 0; i < found.size(); ++i) {
    legend += (i == 0 ? "" : ", ") + found[i].second->first + " is labelled " + found[i].second->second;
  }
  return legend + ")";
}

}  // namespace meshedit
