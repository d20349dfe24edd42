// peer_bench's Catmull-Clark section: ours (catmull_clark_subdivide) against OpenMesh's CatmullClarkT on a closed
// torus of quads, the same torus as triangles, and the quad torus with square holes. Every peer's result (counts,
// every position, boundary flags) is checked against ours before its time is printed, as peer/ours ratios.
//
// OpenMesh's boundary vertex rule is (p + the two boundary edge midpoints) / 3 = 2/3 p + 1/6 (neighbours), not
// ours (3/4 p + 1/8 neighbours); with holes only the points away from the boundary are compared. Its interior rule,
// (n - 2)/n p + (sum of neighbours + sum of face points) / n^2, is ours written otherwise.
#pragma once

#include <memory>
#include <string>

#include "bench/peer_contender.h"

namespace meshedit::bench {

// One library's Catmull-Clark behind the same calls (polygons of any size in).
class CatmullClarkContender {
 public:
  virtual ~CatmullClarkContender() = default;
  virtual std::string name() const = 0;
  virtual std::string boundary_rule() const = 0;
  virtual bool boundary_rule_like_ours() const = 0;
  // Replaces the mesh held; throws on refusal.
  virtual void build(const PolygonMesh& polygons) = 0;
  // `levels` levels; throws on refusal.
  virtual void subdivide(int levels) = 0;
  virtual void clear() = 0;
  virtual MeshCounts counts() const = 0;
  // Positions and boundary flags; normals are left empty-zero (not compared here).
  virtual VertexData vertex_data() const = 0;
};

std::unique_ptr<CatmullClarkContender> make_ours_catmull_clark();
#ifdef MESHEDIT_HAVE_OPENMESH
std::unique_ptr<CatmullClarkContender> make_openmesh_catmull_clark();
#endif

struct CatmullClarkOptions {
  uint32_t faces = 100000;  // about this many input faces (triangles for the triangle torus)
  int levels = 3, reps = 5;
  bool back_memory = true;  // touch this many MiB before each timed run (bench_support.h)
  size_t backed_mib = 1536;
};

// Prints the section; false when a peer's output did not match ours or a contender failed.
bool compare_catmull_clark(const CatmullClarkOptions& options);

}  // namespace meshedit::bench
