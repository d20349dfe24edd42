// The patch view's state and its tessellation cache: see patch_view_state.h. The cache compares the patches bit for
// bit (memcmp), so NaN control points do not force a rebuild every frame and an idle frame costs one comparison of
// the control points, never a tessellation.
#include "document/patch_view_state.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>
#include <utility>

#include "core/mesh_build.h"
#include "core/mesh_error.h"

namespace meshedit {

static_assert(std::is_trivially_copyable_v<BezierPatch> && sizeof(BezierPatch) == 16 * sizeof(glm::dvec3),
              "patches are compared with memcmp");

namespace {

bool same_patches(const std::vector<BezierPatch>& a, const std::vector<BezierPatch>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(BezierPatch)) == 0);
}

}  // namespace

// ---- state -----------------------------------------------------------------------------------------

PatchViewState make_patch_view(std::vector<BezierPatch> patches) {
  PatchViewState state;
  state.patches = std::move(patches);
  return state;
}

void set_resolution(PatchViewState& state, int resolution) {
  state.resolution = std::clamp(resolution, 1, kMaxPatchViewResolution);
}

void select_patch(PatchViewState& state, int index) {
  state.selected_patch = std::clamp(index, 0, std::max(0, static_cast<int>(state.patches.size()) - 1));
}

void set_probe(PatchViewState& state, double u, double v) {
  if (!std::isnan(u)) state.u = std::clamp(u, 0.0, 1.0);
  if (!std::isnan(v)) state.v = std::clamp(v, 0.0, 1.0);
}

bool update_tessellation(PatchViewState& state) {
  set_resolution(state, state.resolution);
  select_patch(state, state.selected_patch);
  PatchTessellation& cache = state.tessellation;
  if (cache.resolution == state.resolution && same_patches(cache.source, state.patches)) return false;

  cache.source = state.patches;
  cache.resolution = state.resolution;
  cache.polygons = PolygonMesh{};
  cache.mesh.reset();
  cache.report = TessellationReport{};
  cache.error.clear();
  ++cache.rebuilds;
  try {
    cache.polygons = tessellate_patches(state.patches, state.resolution, &cache.report);
    HalfedgeMesh mesh = build_halfedge_mesh(cache.polygons);
    mesh.bump_version_above(cache.last_mesh_version);
    cache.last_mesh_version = mesh.version();
    cache.mesh = std::move(mesh);
  } catch (const MeshError& e) {
    cache.error = e.what();
  }
  return true;
}

}  // namespace meshedit
