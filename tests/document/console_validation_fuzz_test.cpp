// The window's validation never says valid wrongly, end to end: random console lines (operations, pointer writes,
// deletions, new elements, the script's own undo), undo and redo, and edits made elsewhere, on meshes with
// boundaries, quads and dead slots; after most steps (some states are never validated, as when two changes come in one
// frame) the status bar's validation (cached, from a patch when it can) agrees with the whole-mesh validator, and the
// local path is really taken.
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/primitives.h"
#include "core/validate.h"
#include "document/mesh_document.h"
#include "document/script_console.h"
#include "support/random_edits.h"

namespace meshedit {
namespace {

// A console line a student might type, on ids below the mesh's capacities.
std::string random_line(const HalfedgeMesh& m, std::mt19937& random) {
  const auto id = [&](uint32_t capacity) { return std::to_string(random() % capacity); };
  const std::string e = id(m.edge_capacity()), h = id(m.halfedge_capacity()), h2 = id(m.halfedge_capacity());
  const std::string v = id(m.vertex_capacity()), f = id(m.face_capacity());
  switch (random() % 12) {
    case 0:
    case 1: return "mesh:flip(mesh:edge(" + e + "))";
    case 2: return "mesh:split(mesh:edge(" + e + "))";
    case 3: return "mesh:collapse(mesh:edge(" + e + "))";
    case 4: return "mesh:halfedge(" + h + ").next = mesh:halfedge(" + h2 + ")";
    case 5: return "mesh:halfedge(" + h + ").twin = mesh:halfedge(" + h2 + ")";
    case 6: return "mesh:vertex(" + v + ").halfedge = mesh:halfedge(" + h + ")";
    case 7: return "mesh:delete(mesh:vertex(" + v + "))";
    case 8: return "mesh:delete(mesh:face(" + f + "))";
    case 9: return "mesh:vertex(" + v + ").position = {1, 2, 3}";
    case 10:
      return "local x = mesh:new_halfedge(); x:set_neighbors(x, x, mesh:vertex(" + v + "), mesh:edge(" + e +
             "), mesh:face(" + f + "))";
    default: return "mesh:undo()";
  }
}

TEST(ConsoleValidationFuzz, TheCachedValidationAgreesWithTheWholeMeshValidator) {
  size_t from_patch = 0, broken = 0, steps = 0;
  for (uint32_t seed = 1; seed <= 100; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    HalfedgeMesh start = seed % 3 == 0   ? build_halfedge_mesh(make_grid(5, 4))
                         : seed % 3 == 1 ? testing::edited_torus(seed)
                                         : build_halfedge_mesh(make_cube());
    MeshDocument doc = make_document(std::move(start));
    ScriptConsole console;
    std::mt19937 random(seed);
    for (int step = 0; step < 25; ++step) {
      std::string what;
      switch (random() % 6) {
        case 0:
          what = "undo";
          undo(doc);
          break;
        case 1:
          what = "redo";
          redo(doc);
          break;
        case 2: {
          what = "flip elsewhere";
          const EdgeId e(random() % doc.mesh.edge_capacity());
          apply_operation(doc, "flip", [&](HalfedgeMesh& m) { return flip(m, e); });
          break;
        }
        default: what = random_line(doc.mesh, random); console.submit(doc, {}, what);
      }
      SCOPED_TRACE("step " + std::to_string(step) + ": " + what);
      if (random() % 4 == 0) continue;  // a state the status bar never validated (two changes in one frame)
      const ValidationReport whole = validate_without_shortcut(doc.mesh);
      const ValidationReport& shown = cached_validation(doc);
      ASSERT_EQ(shown.ok(), whole.ok()) << whole.summary();
      EXPECT_EQ(shown.total, whole.total);
      from_patch += doc.validation.value.from_patch ? 1 : 0;
      broken += whole.ok() ? 0 : 1;
      ++steps;
      if (!whole.ok() && random() % 2 == 0) undo(doc);  // often back to a valid state, so patches serve again
    }
  }
  EXPECT_GT(from_patch, steps / 8);  // the local path is taken often
  EXPECT_GT(broken, steps / 10);     // and the fuzz really breaks meshes
}

}  // namespace
}  // namespace meshedit
