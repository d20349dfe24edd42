// Size limits every reader enforces before it allocates, so a small hostile file cannot make MeshEdit
// reserve gigabytes ("file declares 2^31 patches") and every index fits the uint32 ids of PolygonMesh.
//
// Invariants: kMaxVertices and kMaxCorners are far below 2^32, so sums of two in-limit counts never
// overflow uint32_t; a reader checks a declared count against these limits AND against what the file
// really holds before calling reserve/resize.
#pragma once

#include <cstddef>

namespace meshedit {

// A teaching editor has no use for more; at these sizes the mesh alone is ~0.5 GB. (Files themselves are capped at
// kMaxReadFileBytes, core/file_bytes.h.)
inline constexpr size_t kMaxVertices = size_t(1) << 24;  // 16.7 million
inline constexpr size_t kMaxCorners = size_t(1) << 26;   // polygon corners over all faces (indices)

}  // namespace meshedit
