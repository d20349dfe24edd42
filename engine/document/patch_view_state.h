// The patch view's state: bicubic Bézier patches (.bez), the tessellation of them the view shows, the selected
// patch and the (u, v) probe. ui/patch_view.h draws it (the panel, and the overlay the renderer draws over the
// surface); the app hands the tessellated mesh to MeshRenderer.
//
// Invariants kept by the functions below (not by direct writes to the fields):
// - resolution is in [1, kMaxPatchViewResolution]; u and v are finite and in [0, 1];
// - selected_patch is a valid index, or 0 when there are no patches;
// - the tessellation cache is rebuilt only when the patches (compared bit for bit) or the resolution
//   differ from what it was built from; each rebuilt HalfedgeMesh gets a version() above every earlier
//   one, so a renderer caching by version never mistakes a new mesh for the old one.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/bezier.h"
#include "core/halfedge_mesh.h"
#include "core/patch_tessellation.h"
#include "core/polygon_mesh.h"

namespace meshedit {

inline constexpr int kMaxPatchViewResolution = 64;

// The tessellated surface and what it was built from.
struct PatchTessellation {
  std::vector<BezierPatch> source;  // the patches it was built from
  int resolution = 0;               // 0: never built
  PolygonMesh polygons;
  std::optional<HalfedgeMesh> mesh;  // empty when the triangles do not form a manifold (see error)
  TessellationReport report;
  std::string error;               // why mesh is empty, when it is
  uint64_t rebuilds = 0;           // how many times it was built (tests and the panel show it)
  uint64_t last_mesh_version = 0;  // the largest version() handed out so far
};

struct PatchViewState {
  std::vector<BezierPatch> patches;
  int resolution = kDefaultPatchResolution;
  int selected_patch = 0;
  double u = 0.5;
  double v = 0.5;
  bool show_control_net = true;
  bool show_surface = true;
  bool show_probe = true;
  PatchTessellation tessellation;
};

// A state showing `patches`; the tessellation is built on the first update_tessellation.
PatchViewState make_patch_view(std::vector<BezierPatch> patches);

void set_resolution(PatchViewState& state, int resolution);  // clamped to [1, kMaxPatchViewResolution]
void select_patch(PatchViewState& state, int index);         // clamped to a valid index
void set_probe(PatchViewState& state, double u, double v);   // each clamped to [0, 1]; NaN ignored

// Rebuilds state.tessellation if the patches or the resolution changed since it was built (clamping
// the resolution and selected_patch first). Returns true if it rebuilt. A MeshError from tessellating
// or building the half-edge mesh is caught: the polygons are kept when there are any, `mesh` is empty
// and `error` says why.
bool update_tessellation(PatchViewState& state);

}  // namespace meshedit
