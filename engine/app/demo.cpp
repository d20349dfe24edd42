// `meshedit demo [FILE]`: the headless tour until the window exists. Loads a file (the project's Utah
// teapot by default), then runs each part of the core on it and prints what happened: tessellation,
// half-edge build, validation, area-weighted normals, a flip with its diff and undo, a split, and one
// level of Loop subdivision.
#include <chrono>
#include <cmath>
#include <string>

#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/bezier.h"
#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_stats.h"
#include "core/normals.h"
#include "core/validate.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

using Clock = std::chrono::steady_clock;

// The milliseconds since `start`, to two decimals.
std::string ms(Clock::time_point start) {
  return format_fixed(std::chrono::duration<double, std::milli>(Clock::now() - start).count(), 2);
}

std::string point(const glm::dvec3& p) {
  return "(" + format_rounded(p.x, 4) + ", " + format_rounded(p.y, 4) + ", " + format_rounded(p.z, 4) + ")";
}

// The first interior edge the core agrees to flip, if any.
EdgeId first_flippable(const HalfedgeMesh& mesh) {
  for (EdgeId e : mesh.edges()) {
    if (can_flip(mesh, e)) return e;
  }
  return EdgeId();
}

}  // namespace

int run_demo(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  reject_unknown_options(args);
  if (args.size() > 1) throw UsageError("demo takes at most one file");
  const std::filesystem::path path = args.empty() ? assets_dir() / "teapot.bez" : std::filesystem::path(args[0]);

  auto start = Clock::now();
  const LoadedFile file = load_file(path);
  out << "loaded " << path.string() << " in " << ms(start) << " ms";
  if (file.kind == FileKind::Patches) out << ": " << file.patches.size() << " Bézier patches";
  out << "\n";
  if (file.kind == FileKind::Patches && !file.patches.empty()) {
    const PatchEvaluation probe = evaluate_patch_steps(file.patches.front(), 0.5, 0.5);
    out << "  patch 0 at (u, v) = (0.5, 0.5): rows at u give " << point(probe.row_points[0]) << " ... "
        << point(probe.row_points[3]) << "; the column at v gives " << point(probe.point) << "\n";
  }

  start = Clock::now();
  const PolygonMesh polygons = polygons_of(file, path, kDefaultPatchResolution);
  if (file.kind == FileKind::Patches) {
    out << "tessellated " << kDefaultPatchResolution << "x" << kDefaultPatchResolution << " per patch and welded in "
        << ms(start) << " ms: " << polygons.num_vertices() << " vertices, " << polygons.num_faces() << " triangles\n";
  }
  start = Clock::now();
  HalfedgeMesh mesh = build_halfedge_mesh(polygons);
  const MeshStats stats = compute_stats(mesh);
  out << "half-edge mesh built in " << ms(start) << " ms: " << stats.vertices << " vertices, " << stats.edges
      << " edges, " << stats.faces << " faces, " << stats.halfedges << " halfedges, " << stats.boundary_loops
      << " boundary loops, Euler characteristic " << stats.euler_characteristic << "\n";
  out << "validate: " << validate(mesh).summary() << "\n";

  start = Clock::now();
  const auto normals = vertex_normals(mesh);
  const VertexId v0 = *mesh.vertices().begin();
  out << "area-weighted vertex normals in " << ms(start) << " ms; " << format_id(v0) << " at "
      << point(mesh.position(v0)) << " has normal " << point(normals[v0.index]) << "\n";

  History history;
  if (const EdgeId e = first_flippable(mesh)) {
    const HalfedgeMesh before = mesh;
    flip(mesh, e);
    history.record("flip " + format_id(e), before);
    const auto changes = diff(before, mesh);
    out << "flip " << format_id(e) << ": " << changes.size() << " fields changed, e.g.";
    for (size_t i = 0; i < changes.size() && i < 3; ++i) {
      out << " " << format_id(changes[i].element) << "." << changes[i].field << " " << changes[i].before << "->"
          << changes[i].after;
    }
    out << "; validate: " << validate(mesh).summary() << "\n";
    history.undo(mesh);
    out << "undo: the mesh is " << (mesh.same_as(before) ? "identical to" : "DIFFERENT from")
        << " the one before the flip\n";
    const OpResult<VertexId> split_result = split(mesh, e);
    if (split_result) {
      out << "split " << format_id(e) << ": new vertex " << format_id(split_result.value) << " at "
          << point(mesh.position(split_result.value)) << "; validate: " << validate(mesh).summary() << "\n";
    } else {
      out << "split " << format_id(e) << " refused: " << split_result.check.reason << "\n";
    }
  }

  start = Clock::now();
  const Check subdivided = loop_subdivide(mesh);
  if (subdivided) {
    out << "Loop subdivision in " << ms(start) << " ms: " << mesh.num_vertices() << " vertices, " << mesh.num_faces()
        << " faces; validate: " << validate(mesh).summary() << "\n";
  } else {
    out << "Loop subdivision refused: " << subdivided.reason << "\n";
  }
  return 0;
}

}  // namespace meshedit
