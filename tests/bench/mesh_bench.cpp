// mesh_bench: prints how long the core's hot paths take on a generated torus (not a test: no timing is
// asserted anywhere). Each figure is the minimum over --reps runs, on one thread.
//
//   mesh_bench [--faces N] [--levels L] [--reps R] [--threads T] [--fast-only 1] [--warm 1]
//   defaults: 100000 faces, 1 level, 5 reps, 2 threads for the second fast-path row; --fast-only skips the
//   (slow) phase-by-phase teaching path. The last rows time the normals again on the Loop result, then the floor a
//   bare index buffer gives there (normals_floor.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>

#include "bench/bench_support.h"
#include "bench/normals_floor.h"
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
  const bool fast_only = arg(argc, argv, "--fast-only", 0) != 0;
  const bool warm = arg(argc, argv, "--warm", 0) != 0;

  const PolygonMesh torus = make_torus_with_faces(faces);
  std::printf("torus: %zu vertices, %zu faces; minimum of %d runs, one thread\n", torus.num_vertices(),
              torus.num_faces(), reps);

  HalfedgeMesh mesh;
  const double build = min_ms(
      reps, [] {}, [&] { mesh = build_halfedge_mesh(torus); });
  std::printf("%-34s %9.2f ms  %7.2f M faces/s\n", "build half-edge mesh", build, torus.num_faces() / build / 1e3);
  std::printf("%-34s %9.1f bytes/face\n", "  memory at rest", double(mesh.memory_bytes()) / mesh.num_faces());

  std::vector<glm::dvec3> normals;
  const int threads = static_cast<int>(std::clamp(arg(argc, argv, "--threads", 2), 1L, 64L));
  const auto normals_row = [&](const HalfedgeMesh& of, const char* which, int thread_count) {
    const double normal_ms = min_ms(
        reps, [] {}, [&] { vertex_normals(of, normals, thread_count); });
    char label[80];
    std::snprintf(label, sizeof label, "area-weighted vertex normals%s (%d thr)", which, thread_count);
    std::printf("%-34s %9.2f ms  %7.2f M faces/s\n", label, normal_ms, of.num_faces() / normal_ms / 1e3);
  };
  normals_row(mesh, "", 1);
  if (threads > 1) normals_row(mesh, "", threads);

  const double validate_ms = min_ms(
      reps, [] {}, [&] { (void)validate(mesh); });
  std::printf("%-34s %9.2f ms\n", "validate", validate_ms);

  const auto loop_row = [&](const char* path, LoopWeights weights, int thread_count,
                            const std::function<void(HalfedgeMesh&)>& run) {
    HalfedgeMesh work;
    // Cold: every run subdivides into freshly mapped memory, as a user's first subdivision does. Warm (--warm 1):
    // the copy reuses the arrays of the previous run, so page faults are out of the figure.
    const double ms = min_ms(
        reps,
        [&] {
          if (!warm) work = HalfedgeMesh();
          work = mesh;
        },
        [&] { run(work); });
    char label[80];
    std::snprintf(label, sizeof label, "Loop x%d %s (%s, %d thr)", levels, path,
                  weights == LoopWeights::Course ? "course" : "loop", thread_count);
    std::printf("%-34s %9.2f ms  %7.2f M output faces/s  (%zu faces, %.1f bytes/face)\n", label, ms,
                work.num_faces() / ms / 1e3, work.num_faces(), double(work.memory_bytes()) / work.num_faces());
  };
  for (LoopWeights weights : {LoopWeights::Course, LoopWeights::Loop}) {
    if (!fast_only) {
      loop_row("phases", weights, 1, [&](HalfedgeMesh& m) {
        for (int i = 0; i < levels; ++i) loop_subdivide_by_phases(m, weights);
      });
    }
    loop_row("fast", weights, 1, [&](HalfedgeMesh& m) { loop_subdivide(m, weights, levels, 1); });
    if (threads > 1) {
      loop_row("fast", weights, threads, [&](HalfedgeMesh& m) { loop_subdivide(m, weights, levels, threads); });
    }
  }
  // Normals on Loop's output, whose teaching-order ids scatter a face's halfedges and corners: the case the peer
  // benchmark measures, and the one where the two threads' halves of the faces cost the most differently.
  HalfedgeMesh subdivided = mesh;
  loop_subdivide(subdivided, LoopWeights::Loop, levels, threads);
  std::printf("after Loop x%d: %zu faces\n", levels, subdivided.num_faces());
  normals_row(subdivided, " after Loop", 1);
  if (threads > 1) normals_row(subdivided, " after Loop", threads);
  // The floor without the half-edge chase, with today's ids and with renumbered ones (normals_floor.h).
  bench::print_normals_floor(subdivided, reps);
  return 0;
}
