// Pick id encoding and the choice of one element near the cursor (see pick_id.h).
#include "render/pick_id.h"

namespace meshedit {
namespace {

// The kind codes; their order is also the picking priority (higher wins).
constexpr uint32_t kFaceCode = 1, kEdgeCode = 2, kHalfedgeCode = 3, kVertexCode = 4;

uint32_t kind_code(ElementKind kind) {
  switch (kind) {
    case ElementKind::Vertex: return kVertexCode;
    case ElementKind::Halfedge: return kHalfedgeCode;
    case ElementKind::Edge: return kEdgeCode;
    case ElementKind::Face: return kFaceCode;
    case ElementKind::Boundary: break;
  }
  return 0;
}

}  // namespace

uint32_t pick_kind_bits(ElementKind kind) { return kind_code(kind) << kPickIndexBits; }

uint32_t encode_pick_id(ElementRef element) {
  if (!element.valid() || element.index > kPickIndexMask) return 0;
  return pick_kind_bits(element.kind) | element.index;  // Boundary: kind bits 0 -> whole id 0
}

ElementRef decode_pick_id(uint32_t id) {
  const uint32_t index = id & kPickIndexMask;
  switch (id >> kPickIndexBits) {
    case kVertexCode: return ElementRef(ElementKind::Vertex, index);
    case kHalfedgeCode: return ElementRef(ElementKind::Halfedge, index);
    case kEdgeCode: return ElementRef(ElementKind::Edge, index);
    case kFaceCode: return ElementRef(ElementKind::Face, index);
    default: return ElementRef();
  }
}

ElementRef choose_pick(std::span<const uint32_t> ids, int width, int height, int cursor_x, int cursor_y) {
  uint32_t best = 0;
  uint32_t best_code = 0;
  long best_distance = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      if (i >= ids.size()) return decode_pick_id(best);
      const uint32_t id = ids[i];
      if (!decode_pick_id(id).valid()) continue;
      const uint32_t code = id >> kPickIndexBits;
      const long distance = long(x - cursor_x) * (x - cursor_x) + long(y - cursor_y) * (y - cursor_y);
      const long radius = code == kVertexCode ? kVertexPickRadius : kPickRadius;
      if (distance > radius * radius) continue;
      if (code > best_code || (code == best_code && distance < best_distance)) {
        best = id;
        best_code = code;
        best_distance = distance;
      }
    }
  }
  return decode_pick_id(best);
}

}  // namespace meshedit
