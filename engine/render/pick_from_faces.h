// pick_from_faces: picking on a large mesh from an id window that holds faces only. The renderer's exact id pass
// also draws every edge, arrow and vertex, which costs several times what the faces do on a software rasteriser
// (render_bench prints both); on a large mesh whose live elements are all drawn, the faces seen around
// the cursor are enough to find the smaller elements on the CPU.
//
// The rule, the same priorities and radii as the exact pass (pick_id.h):
// - The faces seen: the faces in the window's pixels within kVertexPickRadius of the cursor. Only their corners,
//   sides and (when shown) arrows are candidates, so what no visible face touches cannot be picked; on a mesh
//   whose every live face is drawn (the renderer's condition for this path), every edge and vertex with a face
//   is reachable that way.
// - A candidate's distance is measured on the screen from the cursor's pixel centre to the projected point or
//   segment (both ends in front of the eye). The nearest vertex within kVertexPickRadius wins; else the nearest
//   arrow, then the nearest edge, within kPickRadius; else the face choose_pick finds in the window. Ties go to
//   the lower id, so the answer does not depend on the order the faces were seen in.
// Invariants: reads the mesh only through bounded face walks and alive-checked ids (a broken mesh gives fewer
// candidates, never a stray read); pure CPU, tested without GL.
#pragma once

#include <cstdint>
#include <span>

#include "core/halfedge_mesh.h"
#include "render/camera.h"

namespace meshedit {

// A window of the id buffer: `ids` row 0 first (top-down), `width` x `height` pixels whose top-left pixel is
// (left, top) in the viewport (top-left origin).
struct PickWindow {
  std::span<const uint32_t> ids;
  int width = 0, height = 0;
  int left = 0, top = 0;
};

// The element under pixel (x, y) of `viewport`, the window holding face ids only (or background).
ElementRef pick_from_faces(const HalfedgeMesh& mesh, const OrbitCamera& camera, Viewport viewport,
                           const PickWindow& window, int x, int y, bool halfedges);

}  // namespace meshedit
