// The one id formatter and its parser (see ids.h for the printed forms).
#include "core/ids.h"

#include <charconv>

namespace meshedit {

const char* kind_name(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return "vertex";
    case ElementKind::Halfedge: return "halfedge";
    case ElementKind::Edge: return "edge";
    case ElementKind::Face: return "face";
    case ElementKind::Boundary: return "boundary";
  }
  return "element";
}

char kind_prefix(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return 'v';
    case ElementKind::Halfedge: return 'h';
    case ElementKind::Edge: return 'e';
    case ElementKind::Face: return 'f';
    case ElementKind::Boundary: return 'b';
  }
  return '?';
}

std::string format_id(ElementRef element) {
  if (!element.valid()) return "-";
  return kind_prefix(element.kind) + std::to_string(element.index);
}

std::optional<ElementRef> parse_element(std::string_view text) {
  if (text.size() < 2) return std::nullopt;
  ElementKind kind;
  switch (text[0]) {
    case 'v': kind = ElementKind::Vertex; break;
    case 'h': kind = ElementKind::Halfedge; break;
    case 'e': kind = ElementKind::Edge; break;
    case 'f': kind = ElementKind::Face; break;
    case 'b': kind = ElementKind::Boundary; break;
    default: return std::nullopt;
  }
  uint32_t index = 0;
  const char* first = text.data() + 1;
  const char* last = text.data() + text.size();
  auto [end, error] = std::from_chars(first, last, index);
  if (error != std::errc() || end != last || index == kInvalidIndex) return std::nullopt;
  if (kind == ElementKind::Boundary && (index & FaceId::kBoundaryBit)) return std::nullopt;
  return ElementRef(kind, index);
}

}  // namespace meshedit
