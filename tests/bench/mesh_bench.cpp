// mesh_bench: prints how long the core's hot paths take on a generated torus (not a test: no timing is
// asserted anywhere). Each figure is the minimum over --reps runs, on one thread.
//
//   mesh_bench [--faces N] [--levels L] [--reps R]     defaults: 100000 faces, 1 level, 5 reps
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include "bench/bench_support.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/normals.h"
#include "core/primitives.h"
#include "core/validate.h"

using meshedit::bench::arg;
using meshedit::bench::min_ms;

int main(int argc, char** argv) {
  using namespace meshedit;
  const auto faces = static_cast<uint32_t>(std::max(8L, arg(argc, argv, "--faces", 100000)));
  const int levels = static_cast<int>(std::clamp(arg(argc, argv, "--levels", 1), 1L, 4L));
  const int reps = static_cast<int>(std::clamp(arg(argc, argv, "--reps", 5), 1L, 100L));

  const PolygonMesh torus = make_torus_with_faces(faces);
  std::printf("torus: %zu vertices, %zu faces; minimum of %d runs, one thread\n", torus.num_vertices(),
              torus.num_faces(), reps);

  HalfedgeMesh mesh;
  const double build = min_ms(reps, [] {}, [&] { mesh = build_halfedge_mesh(torus); });
  std::printf("%-34s %9.2f ms  %7.2f M faces/s\n", "build half-edge mesh", build, torus.num_faces() / build / 1e3);
  std::printf("%-34s %9.1f bytes/face\n", "  memory at rest", double(mesh.memory_bytes()) / mesh.num_faces());

  std::vector<glm::dvec3> normals;
  const double normal_ms = min_ms(reps, [] {}, [&] { normals = vertex_normals(mesh); });
  std::printf("%-34s %9.2f ms  %7.2f M faces/s\n", "area-weighted vertex normals", normal_ms,
              mesh.num_faces() / normal_ms / 1e3);

  const double validate_ms = min_ms(reps, [] {}, [&] { (void)validate(mesh); });
  std::printf("%-34s %9.2f ms\n", "validate", validate_ms);

  for (LoopWeights weights : {LoopWeights::Course, LoopWeights::Loop}) {
    HalfedgeMesh work;
    const double loop = min_ms(reps, [&] { work = mesh; }, [&] {
      for (int i = 0; i < levels; ++i) loop_subdivide(work, weights);
    });
    char label[64];
    std::snprintf(label, sizeof label, "Loop subdivision x%d (%s)", levels,
                  weights == LoopWeights::Course ? "course" : "loop");
    std::printf("%-34s %9.2f ms  %7.2f M output faces/s  (%zu faces)\n", label, loop,
                work.num_faces() / loop / 1e3, work.num_faces());
  }
  return 0;
}
