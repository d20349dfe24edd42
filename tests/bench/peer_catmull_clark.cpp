// peer_bench's Catmull-Clark section (see peer_catmull_clark.h): ours as a contender, the quad tori it is run on,
// the match check and the interleaved timings.
#include "bench/peer_catmull_clark.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "bench/bench_support.h"
#include "bench/peer_match.h"
#include "core/catmull_clark.h"
#include "core/mesh_build.h"
#include "core/primitives.h"

namespace meshedit::bench {
namespace {

class Ours final : public CatmullClarkContender {
 public:
  std::string name() const override { return "ours"; }
  std::string boundary_rule() const override { return "3/4 p + 1/8 boundary neighbours"; }
  bool boundary_rule_like_ours() const override { return true; }
  void build(const PolygonMesh& polygons) override { mesh_ = build_halfedge_mesh(polygons); }
  void subdivide(int levels) override {
    const Check done = catmull_clark_subdivide(mesh_, levels);
    if (!done) throw std::runtime_error("catmull_clark_subdivide refused: " + done.reason);
  }
  void clear() override { mesh_ = HalfedgeMesh(); }
  MeshCounts counts() const override { return {mesh_.num_vertices(), mesh_.num_edges(), mesh_.num_faces()}; }
  VertexData vertex_data() const override {
    VertexData data;
    for (VertexId v : mesh_.vertices()) {
      data.position.push_back(mesh_.position(v));
      data.normal.emplace_back(0.0);
      data.on_boundary.push_back(mesh_.is_boundary(v) ? 1 : 0);
    }
    return data;
  }

 private:
  HalfedgeMesh mesh_;
};

// The benchmark torus's vertices (make_torus: vertex (ring i, side j) is i * sides + j) joined as quads, with about
// `faces` of them; with `holes`, one quad left out every 8 rings and 8 sides (the holes share no vertex).
PolygonMesh quad_torus(uint32_t faces, bool holes) {
  const auto sides = static_cast<uint32_t>(std::max(4.0, std::round(std::sqrt(faces / 2.0))));
  const uint32_t rings = 2 * sides;
  PolygonMesh quads;
  quads.positions = make_torus(rings, sides).positions;
  for (uint32_t i = 0; i < rings; ++i) {
    for (uint32_t j = 0; j < sides; ++j) {
      if (holes && i % 8 == 4 && j % 8 == 4 && i + 2 < rings && j + 2 < sides) continue;
      const uint32_t i1 = (i + 1) % rings, j1 = (j + 1) % sides;
      quads.add_face({i * sides + j, i1 * sides + j, i1 * sides + j1, i * sides + j1});
    }
  }
  return quads;
}

struct Variant {
  std::string label;
  PolygonMesh mesh;
  bool closed;
};

}  // namespace

std::unique_ptr<CatmullClarkContender> make_ours_catmull_clark() { return std::make_unique<Ours>(); }

bool compare_catmull_clark(const CatmullClarkOptions& o) {
  std::vector<std::unique_ptr<CatmullClarkContender>> contenders;
  contenders.push_back(make_ours_catmull_clark());
#ifdef MESHEDIT_HAVE_OPENMESH
  contenders.push_back(make_openmesh_catmull_clark());
#endif
  std::vector<Variant> variants;
  variants.push_back({"quads, closed", quad_torus(o.faces, false), true});
  variants.push_back({"triangles, closed", make_torus_with_faces(o.faces), true});
  variants.push_back({"quads with holes", quad_torus(o.faces, true), false});

  std::printf("\nCatmull-Clark (%d levels): ours against %s\n", o.levels,
              contenders.size() > 1 ? "OpenMesh CatmullClarkT (PolyMesh_ArrayKernelT, Vec3d points)"
                                    : "no peer (OpenMesh absent: run scripts/setup_bench.sh, then reconfigure)");
  bool all_ok = true;
  for (const Variant& variant : variants) {
    const std::string label = std::to_string(variant.mesh.num_faces()) + " f " + variant.label;
    CatmullClarkContender& ours = *contenders[0];
    VertexData reference;
    MeshCounts expected;
    try {
      ours.build(variant.mesh);
      ours.subdivide(o.levels);
      reference = ours.vertex_data();
      expected = ours.counts();
      ours.clear();
    } catch (const std::exception& e) {
      std::printf("FAIL  Catmull-Clark %s, ours: %s\n", label.c_str(), e.what());
      return false;
    }
    std::vector<bool> matched(contenders.size(), true);
    for (size_t i = 1; i < contenders.size(); ++i) {
      CatmullClarkContender& c = *contenders[i];
      bool ok = true;
      try {
        c.build(variant.mesh);
        c.subdivide(o.levels);
      } catch (const std::exception& e) {
        std::printf("FAIL  Catmull-Clark %s, %s: %s\n", label.c_str(), c.name().c_str(), e.what());
        ok = false;
      }
      if (ok && !(c.counts() == expected)) {
        const MeshCounts got = c.counts();
        std::printf("FAIL  Catmull-Clark %s, %s: %zu vertices, %zu edges, %zu faces; ours %zu, %zu, %zu\n",
                    label.c_str(), c.name().c_str(), got.vertices, got.edges, got.faces, expected.vertices,
                    expected.edges, expected.faces);
        ok = false;
      }
      MatchOptions match;
      std::vector<unsigned char> skip;
      std::string scope = "all points";
      if (ok && !variant.closed && !c.boundary_rule_like_ours()) {
        // Only boundary vertex points differ after one level; each further level carries the difference one edge of
        // that level (half the last) inward, so it stays within one original edge of the boundary.
        const double radius = 2.0 * longest_edge(variant.mesh);
        skip = near_boundary(reference, radius);
        match.skip = &skip;
        scope = "interior points";
        std::printf(
            "note  %s: boundary rule %s differs from ours; comparing only points farther than %.3g from the "
            "boundary\n",
            c.name().c_str(), c.boundary_rule().c_str(), radius);
      }
      if (ok) {
        const MatchReport report = match_vertices(reference, c.vertex_data(), match);
        if (report.ok) {
          std::printf(
              "check Catmull-Clark %s, %s: %zu vertices, %zu faces as ours; %s (%zu) match ours point by "
              "point (max |d| %.1e x |p|max), boundary flags too\n",
              label.c_str(), c.name().c_str(), expected.vertices, expected.faces, scope.c_str(), report.compared,
              report.max_position_error);
        } else {
          std::printf("FAIL  Catmull-Clark %s, %s: %s\n", label.c_str(), c.name().c_str(), report.problem.c_str());
          ok = false;
        }
      }
      c.clear();
      matched[i] = ok;
      all_ok = all_ok && ok;
    }

    // Times: each round runs every matched contender once, so all of them get the same mix of the machine's load.
    std::vector<double> best(contenders.size(), INFINITY);
    for (int round = 0; round < o.reps; ++round) {
      for (size_t i = 0; i < contenders.size(); ++i) {
        if (!matched[i]) continue;
        CatmullClarkContender& c = *contenders[i];
        const auto setup = [&] {
          c.build(variant.mesh);
          if (o.back_memory) back_physical_memory(o.backed_mib);
        };
        best[i] = std::min(best[i], min_ms(1, setup, [&] { c.subdivide(o.levels); }));
        c.clear();
      }
    }
    std::printf("Catmull-Clark %s x%d: ours %.2f ms", label.c_str(), o.levels, best[0]);
    for (size_t i = 1; i < contenders.size(); ++i) {
      if (matched[i]) {
        std::printf(", %s %.2f ms (%s/ours %.2fx)", contenders[i]->name().c_str(), best[i],
                    contenders[i]->name().c_str(), best[i] / best[0]);
      } else {
        std::printf(", %s mismatch (no time)", contenders[i]->name().c_str());
      }
    }
    std::printf("\n");
  }
  return all_ok;
}

}  // namespace meshedit::bench
