// Pick ids: how an element is written into the R32UI id buffer, and how a small window of that buffer
// around the cursor becomes one element. Pure functions, tested without GL.
//
// Encoding: the top 3 bits hold the kind (1 face, 2 edge, 3 halfedge, 4 vertex: the picking priority),
// the low 29 bits the element's index; 0 is the background. Boundary loops are never drawn, so they
// have no pick id.
// Indices from 2^29 on cannot be encoded (encode gives 0: not pickable); that is 536 million elements
// of one kind, far beyond what fits in memory next to the GPU buffers.
//
// Choosing within the window: among the pixels within their kind's radius of the cursor (Euclidean),
// the highest-priority kind wins (vertex > halfedge > edge > face: the smaller target must beat the
// larger one it sits on), then the pixel nearest the cursor, then the first in row order.
#pragma once

#include <cstdint>
#include <span>

#include "core/ids.h"

namespace meshedit {

inline constexpr uint32_t kPickIndexBits = 29;
inline constexpr uint32_t kPickIndexMask = (1u << kPickIndexBits) - 1u;
// How far from the cursor (in pixels) pick() finds each kind: vertices a little further than edges,
// halfedge arrows and faces, because they are the smallest targets. The id pass draws vertices as
// single pixels and edges and arrows as hairlines, so these distances are the whole tolerance.
inline constexpr int kVertexPickRadius = 6;
inline constexpr int kPickRadius = 4;  // edges, halfedges, faces

// The kind's code in the top bits (0 for Boundary, which is not pickable); the shaders OR the index in.
uint32_t pick_kind_bits(ElementKind kind);
// 0 for an invalid ref, a boundary loop or an index that does not fit.
uint32_t encode_pick_id(ElementRef element);
// Invalid ElementRef for 0 and for codes no encode_pick_id produces.
ElementRef decode_pick_id(uint32_t id);

// `ids` is a width x height window, row 0 first; (cursor_x, cursor_y) is the cursor's cell in it.
// pick() reads a window of kVertexPickRadius around the cursor.
ElementRef choose_pick(std::span<const uint32_t> ids, int width, int height, int cursor_x, int cursor_y);

}  // namespace meshedit
