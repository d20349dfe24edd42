// The words of a repair report (mesh_repair.h): the one-line summary and lists of numbers.
#include <algorithm>
#include <string>
#include <vector>

#include "core/mesh_repair.h"

namespace meshedit {
namespace {

std::string count(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::string number_list(std::vector<size_t> numbers) {
  std::sort(numbers.begin(), numbers.end());
  numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  std::string text;
  for (size_t i = 0; i < numbers.size();) {
    size_t j = i;
    while (j + 1 < numbers.size() && numbers[j + 1] == numbers[j] + 1) ++j;
    if (!text.empty()) text += ", ";
    if (j - i >= 2) {
      text += std::to_string(numbers[i]) + ".." + std::to_string(numbers[j]);
      i = j + 1;
    } else {
      text += std::to_string(numbers[i]);
      ++i;
    }
  }
  return text;
}

std::string RepairReport::summary() const {
  if (empty()) return "nothing to repair";
  std::vector<std::string> parts;
  if (split_vertices) parts.push_back(count(split_vertices, "bow-tie vertex split", "bow-tie vertices split"));
  if (detached_faces) {
    parts.push_back(
        count(detached_faces, "face detached from an edge of 3+ faces", "faces detached from edges of 3+ faces"));
  }
  if (dropped_repeated_faces) {
    parts.push_back(count(dropped_repeated_faces, "repeated face dropped", "repeated faces dropped"));
  }
  if (dropped_bad_faces) {
    parts.push_back(count(dropped_bad_faces, "degenerate face dropped", "degenerate faces dropped"));
  }
  if (reversed_faces) parts.push_back(count(reversed_faces, "face reversed", "faces reversed"));
  if (cut_edges)
    parts.push_back(count(cut_edges, "edge cut where its faces disagree", "edges cut where faces disagree"));
  if (dropped_vertices) parts.push_back(count(dropped_vertices, "unused vertex dropped", "unused vertices dropped"));
  std::string text = "repaired: ";
  for (size_t i = 0; i < parts.size(); ++i) text += (i ? ", " : "") + parts[i];
  return text;
}

}  // namespace meshedit
