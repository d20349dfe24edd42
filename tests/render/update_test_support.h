// What the renderer-update tests share: byte equality of two arrays, and the elements a diff touches (each once,
// in diff()'s order: kind, then id), which is what the document hands the renderer after an edit.
#pragma once

#include <cstring>
#include <vector>

#include "core/history.h"

namespace meshedit::testing {

template <class T, class A, class B>
bool same_bytes(const std::vector<T, A>& a, const std::vector<T, B>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline std::vector<ElementRef> changed_elements(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  std::vector<ElementRef> out;
  for (const FieldChange& c : diff(before, after)) {
    if (out.empty() || !(out.back() == c.element)) out.push_back(c.element);
  }
  return out;
}

}  // namespace meshedit::testing
