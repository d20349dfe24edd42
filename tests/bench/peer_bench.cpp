// peer_bench: MeshEdit against OpenMesh and CGAL on the same generated input. For each
// contender: build a half-edge mesh from indexed triangles, Loop subdivision with Loop's weights (closed
// torus, and the torus with holes), area-weighted vertex normals, memory at rest; then Catmull-Clark against
// OpenMesh (peer_catmull_clark.h). Every contender's subdivided mesh (counts, every position, boundary flags,
// normals) is checked against ours before any of its times is taken; a mismatch makes the program exit 1. The
// peers take part when CMake found them (scripts/setup_bench.sh installs them); without them it runs ours alone.
//
//   peer_bench [--faces 100000] [--levels 3] [--reps 5] [--build-faces 1000000] [--threads 2]
//              [--closed | --boundary]   only the closed torus / only the torus with holes (default both)
//              [--interior-only]         compare only points away from the boundary, as for a peer whose
//                                        boundary rule differs from ours (for testing that path)
//              [--cold]                  skip backing physical memory before each timed run (see
//                                        back_physical_memory in bench_support.h), so each run pays whatever
//                                        host faults the order of the jobs leaves it
// Exit status: 0 when every check passed, 1 on a mismatch or a contender's failure, 2 for a wrong command line.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "bench/machine_bandwidth.h"
#include "bench/peer_catmull_clark.h"
#include "bench/peer_contender.h"
#include "bench/peer_input.h"
#include "bench/peer_match.h"
#include "bench/peer_memory.h"
#include "bench/peer_table.h"

using namespace meshedit;
using namespace meshedit::bench;

namespace {

struct Options {
  uint32_t faces = 100000, build_faces = 1000000;
  int levels = 3, reps = 5, threads = 2;
  bool closed = true, boundary = true, interior_only = false, cold = false;
};

// Enough for the largest contender's peak at the default sizes (CGAL, about 800 MB at 6.4M faces).
constexpr size_t kBackedMiB = 1536;

struct Entry {
  std::unique_ptr<Contender> contender;
  int slot;  // column in the table: -1 for ours, else 0 OpenMesh / 1 CGAL
};

bool parse(int argc, char** argv, Options& o) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--closed") {
      o.boundary = false;
      continue;
    }
    if (a == "--boundary") {
      o.closed = false;
      continue;
    }
    if (a == "--interior-only") {
      o.interior_only = true;
      continue;
    }
    if (a == "--cold") {
      o.cold = true;
      continue;
    }
    if (i + 1 >= argc) return false;
    char* end = nullptr;
    const long value = std::strtol(argv[++i], &end, 10);
    if (*end != '\0' || value < 1) return false;
    if (a == "--faces") o.faces = static_cast<uint32_t>(std::max(200L, std::min(value, 50000000L)));
    else if (a == "--build-faces") o.build_faces = static_cast<uint32_t>(std::max(200L, std::min(value, 50000000L)));
    else if (a == "--levels") o.levels = static_cast<int>(std::min(value, 5L));
    else if (a == "--reps") o.reps = static_cast<int>(std::min(value, 100L));
    else if (a == "--threads") o.threads = static_cast<int>(std::min(value, 64L));
    else return false;
  }
  return o.closed || o.boundary;
}

// Runs `fn`; on an exception prints it for `who` and returns false.
template <class Fn>
bool attempt(const std::string& who, Fn&& fn) {
  try {
    fn();
    return true;
  } catch (const std::exception& e) {
    std::printf("FAIL  %s: %s\n", who.c_str(), e.what());
    return false;
  }
}

double& cell(TableRow& row, const Entry& e) { return e.slot < 0 ? row.ours : row.peer[e.slot]; }

// One timed job: `work` after an untimed `setup`; `after(round)` runs untimed once the round's time is taken.
struct Job {
  double* result;
  std::function<void()> setup, work;
  std::function<void(int)> after;
};

// Runs every job once per round, `reps` rounds, and keeps each job's minimum. On a machine shared with
// others the load comes and goes; interleaving the contenders gives each of them the same mix of it.
// Unless `cold`, physical memory is backed right before every timed run, the same for every contender.
void run_interleaved(int reps, bool cold, const std::vector<Job>& jobs) {
  for (const Job& job : jobs) *job.result = NAN;
  for (int round = 0; round < reps; ++round) {
    for (const Job& job : jobs) {
      const auto setup = [&] {
        job.setup();
        if (!cold) back_physical_memory(kBackedMiB);
      };
      const double ms = min_ms(1, setup, job.work);
      *job.result = std::isnan(*job.result) ? ms : std::min(*job.result, ms);
      if (job.after) job.after(round);
    }
  }
}

void mark_mismatch(TableRow& row, const Entry& e, const char* note) {
  if (e.slot >= 0) row.peer_note[e.slot] = note;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parse(argc, argv, o)) {
    std::fprintf(stderr,
                 "usage: peer_bench [--faces N] [--levels L] [--reps R] [--build-faces N] [--threads N] "
                 "[--closed | --boundary] [--interior-only] [--cold]\n");
    return 2;
  }
  std::vector<Entry> entries;
  entries.push_back({make_ours(), -1});
#ifdef MESHEDIT_HAVE_OPENMESH
  entries.push_back({make_openmesh(), 0});
#endif
#ifdef MESHEDIT_HAVE_CGAL
  entries.push_back({make_cgal(), 1});
#endif
  Contender& ours = *entries[0].contender;
  const bool ours_threads_subdivide = o.threads > 1 && ours.takes_threads_for_subdivision();
  const bool ours_threads_normals = o.threads > 1 && ours.takes_threads_for_normals();
  const int thread_column = ours_threads_subdivide || ours_threads_normals ? o.threads : 1;

  std::printf("peer_bench: minimum of %d runs, single thread unless a column says otherwise; times in ms\n", o.reps);
  if (o.cold) {
    std::printf(
        "  --cold: memory not backed before the runs; times depend on the host's page faults and the order "
        "of the jobs\n");
  } else {
    std::printf(
        "  before every timed run %zu MiB are touched and freed, so every contender gets backed pages "
        "(bench_support.h)\n",
        kBackedMiB);
  }
  Judging judging;
  if (FILE* load = std::fopen("/proc/loadavg", "r")) {  // the machine is shared: say how busy it was
    double one = 0, five = 0;
    if (std::fscanf(load, "%lf %lf", &one, &five) == 2) {
      std::printf("  load average at start: %.2f (1 min), %.2f (5 min)%s\n", one, five,
                  one > 1.0 ? "; above 1, so no target is judged met or not (rerun on a quiet machine)" : "");
      judging.load = one;
    }
    std::fclose(load);
  }
  for (const Entry& e : entries)
    std::printf("  %-9s %s\n", e.contender->name().c_str(), e.contender->library().c_str());
  for (int k = 0; k < kPeerSlots; ++k) {
    bool present = false;
    for (const Entry& e : entries) present = present || e.slot == k;
    if (!present)
      std::printf("  %-9s absent (not compiled in: run scripts/setup_bench.sh, then reconfigure)\n", kPeerNames[k]);
  }

  bool all_ok = true;
  // The targets, all on one thread: Loop >= 3x OpenMesh and >= 2x CGAL, normals >= 1.1x both, build >= 3x both.
  // Normals on two threads and memory are reported with no target: what a second thread gains depends on what else
  // shares the machine's memory, which the rows print beside it.
  TableRow build_row, closed_row, boundary_row, normal_row, normal_threads_row, memory_row;
  normal_row.target[0] = normal_row.target[1] = 1.1;
  normal_threads_row.has_target = false;
  memory_row.has_target = false;

  // ---- 1. build from indexed triangles ----------------------------------------------------------------
  {
    const PolygonMesh input = make_torus_with_faces(o.build_faces);
    TableRow& row = build_row;
    row.label = "build, " + std::to_string(input.num_faces()) + " faces (ms)";
    row.target[0] = row.target[1] = 3.0;
    MeshCounts expected;
    std::vector<Job> jobs;
    for (Entry& e : entries) {
      Contender& c = *e.contender;
      MeshCounts got;
      bool ok = attempt(c.name() + " build", [&] {
        c.build(input);
        got = c.counts();
      });
      if (ok && e.slot < 0) expected = got;
      if (ok && !(got == expected)) {
        std::printf("FAIL  build: %s has %zu vertices, %zu edges, %zu faces; ours %zu, %zu, %zu\n", c.name().c_str(),
                    got.vertices, got.edges, got.faces, expected.vertices, expected.edges, expected.faces);
        ok = false;
      }
      if (ok && e.slot >= 0)
        std::printf("check build: %s has the same %zu vertices, %zu edges, %zu faces as ours\n", c.name().c_str(),
                    got.vertices, got.edges, got.faces);
      if (!ok) {
        all_ok = false;
        mark_mismatch(row, e, "mismatch");
        c.clear();
        continue;
      }
      c.clear();
      jobs.push_back({&cell(row, e), [&c] { c.clear(); }, [&c, &input] { c.build(input); }, [&c](int) { c.clear(); }});
    }
    run_interleaved(o.reps, o.cold, jobs);
  }

  // ---- 2-5. Loop subdivision (closed, with holes), normals and memory on the closed result -------------
  struct Variant {
    bool closed;
    PolygonMesh mesh;
    std::string label;
  };
  std::vector<Variant> variants;
  if (o.closed) {
    PolygonMesh torus = make_torus_with_faces(o.faces);
    const std::string label = std::to_string(torus.num_faces()) + " f x" + std::to_string(o.levels);
    variants.push_back({true, std::move(torus), label + ", closed"});
  }
  if (o.boundary) {
    HoledTorus holed = make_torus_with_holes(o.faces);
    const std::string label = std::to_string(holed.mesh.num_faces()) + " f x" + std::to_string(o.levels) + ", " +
                              std::to_string(holed.holes) + " holes";
    variants.push_back({false, std::move(holed.mesh), label});
  }

  double first_threaded_normals_ms = NAN;  // ours on --threads, the first call after Loop (closed torus)
  // The machine's memory reads, timed in the same rounds as ours on one and on several threads.
  std::unique_ptr<MemoryReadProbe> reads;
  if (ours_threads_subdivide || ours_threads_normals) reads = std::make_unique<MemoryReadProbe>(o.threads);
  const auto add_read_jobs = [&reads](std::vector<Job>& jobs, TableRow& row) {
    MemoryReadProbe* probe = reads.get();
    jobs.push_back({&row.read_one_thread_ms, [] {}, [probe] { probe->read_on_one_thread(); }, {}});
    jobs.push_back({&row.read_all_threads_ms, [] {}, [probe] { probe->read_on_all_threads(); }, {}});
  };
  for (const Variant& variant : variants) {
    TableRow& loop_row = variant.closed ? closed_row : boundary_row;
    loop_row.label = "Loop " + variant.label + " (ms)";
    loop_row.target[0] = 3.0;
    loop_row.target[1] = 2.0;

    // Our result is the reference every other output must match.
    VertexData reference;
    MeshCounts expected;
    if (!attempt("ours Loop subdivision", [&] {
          ours.build(variant.mesh);
          ours.subdivide(o.levels, 1);
          ours.compute_normals(1);
          reference = ours.vertex_data();
          expected = ours.counts();
        })) {
      return 1;
    }
    if (variant.closed) {
      normal_row.label = "vertex normals, " + std::to_string(expected.faces) + " faces (ms)";
      memory_row.label = "memory at rest, " + std::to_string(expected.faces) + " faces (B/face)";
    }
    const long long ours_bytes = ours.self_reported_bytes();
    std::vector<unsigned char> interior_skip;

    // The peers, and ours again with --threads when the core takes a thread count.
    std::vector<bool> matched(entries.size(), true);
    bool ours_threads_ok = true;
    for (size_t i = 0; i < entries.size(); ++i) {
      Entry& e = entries[i];
      Contender& c = *e.contender;
      if (e.slot < 0 && thread_column == 1) continue;
      const std::string who = e.slot < 0 ? "ours with " + std::to_string(o.threads) + " threads" : c.name();
      MatchOptions match;
      bool ok = attempt(who + " Loop subdivision", [&] {
        c.build(variant.mesh);
        c.subdivide(o.levels, e.slot < 0 && ours_threads_subdivide ? o.threads : 1);
        const bool threaded_normals = e.slot < 0 && ours_threads_normals;
        const double first_ms = min_ms(
            1, [] {}, [&] { c.compute_normals(threaded_normals ? o.threads : 1); });
        if (threaded_normals && variant.closed) first_threaded_normals_ms = first_ms;
      });
      if (ok && !(c.counts() == expected)) {
        const MeshCounts got = c.counts();
        std::printf("FAIL  %s, %s: %zu vertices, %zu edges, %zu faces; ours %zu, %zu, %zu\n", variant.label.c_str(),
                    who.c_str(), got.vertices, got.edges, got.faces, expected.vertices, expected.edges, expected.faces);
        ok = false;
      }
      std::string scope = "all points";
      if (ok && !variant.closed && (o.interior_only || !c.boundary_rule_like_ours())) {
        const double radius = 4.0 * longest_edge(variant.mesh);
        if (interior_skip.empty()) interior_skip = near_boundary(reference, radius);
        match.skip = &interior_skip;
        std::printf("note  %s: boundary rule %s%s; comparing only points farther than %.3g from the boundary\n",
                    who.c_str(), c.boundary_rule().c_str(), c.boundary_rule_like_ours() ? "" : " differs from ours",
                    radius);
        scope = "interior points";
      }
      if (ok) {
        const MatchReport report = match_vertices(reference, c.vertex_data(), match);
        if (report.ok) {
          std::printf(
              "check %s, %s: %zu vertices, %zu faces as ours; %s (%zu) match ours point by point "
              "(max |d| %.1e x |p|max), boundary flags too, normals max |d| %.1e%s\n",
              variant.label.c_str(), who.c_str(), expected.vertices, expected.faces, scope.c_str(), report.compared,
              report.max_position_error, report.max_normal_error,
              variant.closed ? "" : (", boundary rule " + c.boundary_rule()).c_str());
        } else {
          std::printf("FAIL  %s, %s: %s\n", variant.label.c_str(), who.c_str(), report.problem.c_str());
          ok = false;
        }
      }
      c.clear();
      if (!ok && e.slot < 0) {
        all_ok = ours_threads_ok = false;
      } else if (!ok) {
        all_ok = false;
        matched[i] = false;
        mark_mismatch(loop_row, e, "mismatch");
        mark_mismatch(normal_row, e, "mismatch");
        mark_mismatch(memory_row, e, "mismatch");
      }
    }

    // Times, interleaved; each contender keeps its last subdivided mesh for the normals.
    const Variant* v = &variant;
    std::vector<Job> loop_jobs, normal_jobs;
    for (size_t i = 0; i < entries.size(); ++i) {
      if (!matched[i]) continue;
      const Entry& e = entries[i];
      Contender* c = e.contender.get();
      const auto keep_last = [c, reps = o.reps](int round) {
        if (round + 1 < reps) c->clear();
      };
      loop_jobs.push_back(
          {&cell(loop_row, e), [c, v] { c->build(v->mesh); }, [c, &o] { c->subdivide(o.levels, 1); }, keep_last});
      normal_jobs.push_back({&cell(normal_row, e), [c] { c->drop_normals(); }, [c] { c->compute_normals(1); }, {}});
      if (e.slot >= 0 || !ours_threads_ok) continue;
      if (ours_threads_subdivide) {
        loop_jobs.push_back({&loop_row.ours_threads, [c, v] { c->build(v->mesh); },
                             [c, &o] { c->subdivide(o.levels, o.threads); }, keep_last});
        add_read_jobs(loop_jobs, loop_row);
      }
      if (ours_threads_normals) {
        normal_jobs.push_back(
            {&normal_row.ours_threads, [c] { c->drop_normals(); }, [c, &o] { c->compute_normals(o.threads); }, {}});
        add_read_jobs(normal_jobs, normal_row);
      }
    }
    run_interleaved(o.reps, o.cold, loop_jobs);
    if (variant.closed) run_interleaved(o.reps, o.cold, normal_jobs);
    for (Entry& e : entries) e.contender->clear();

    // Memory at rest, one child per contender.
    for (size_t i = 0; variant.closed && i < entries.size(); ++i) {
      if (!matched[i]) continue;
      Contender& c = *entries[i].contender;
      const long long growth = rss_growth_in_child([&] { c.clear(); },
                                                   [&] {
                                                     c.build(variant.mesh);
                                                     c.subdivide(o.levels, 1);
                                                   });
      if (growth >= 0) cell(memory_row, entries[i]) = double(growth) / double(expected.faces);
    }
    if (variant.closed) {
      std::printf(
          "memory: growth of the resident set (after malloc_trim) of a forked child over build + subdivision, "
          "per output face, same for all; ours by HalfedgeMesh::memory_bytes(): %.1f B/face\n",
          double(ours_bytes) / double(expected.faces));
    }
  }

  std::vector<TableRow> rows = {build_row};
  for (const Variant& variant : variants) rows.push_back(variant.closed ? closed_row : boundary_row);
  if (o.closed) {
    // Ours on all its threads against the peers on one (neither peer's normals take threads).
    normal_threads_row.label = "vertex normals, ours on " + std::to_string(o.threads) + " threads (ms)";
    normal_threads_row.ours = normal_row.ours_threads;
    std::copy(std::begin(normal_row.peer), std::end(normal_row.peer), std::begin(normal_threads_row.peer));
    for (int k = 0; k < kPeerSlots; ++k) normal_threads_row.peer_note[k] = normal_row.peer_note[k];
    rows.push_back(normal_row);
    if (ours_threads_normals) rows.push_back(normal_threads_row);
    rows.push_back(memory_row);
  }
  std::printf("\n");
  print_table(rows, thread_column, judging);
  if (ours_threads_subdivide || ours_threads_normals) {
    if (!std::isnan(first_threaded_normals_ms)) {
      std::printf(
          "ours on %d threads, the first vertex normals after Loop, memory not backed: %.1f ms (the rows then find "
          "the seam between the threads' runs and keep it for the timed calls)\n",
          o.threads, first_threaded_normals_ms);
    }
    for (const TableRow& row : rows) {
      if (std::isnan(row.ours_threads)) continue;
      const double speedup = row.ours / row.ours_threads;
      const double machine = reads->scaling(row.read_one_thread_ms, row.read_all_threads_ms);
      std::printf(
          "ours with %d threads over one, %s: %.2fx; memory reads in the same rounds %.1f GB/s on one thread, %.1f "
          "GB/s on %d: %.2fx (no target)\n",
          o.threads, row.label.substr(0, row.label.rfind(" (")).c_str(), speedup,
          reads->one_thread_gbs(row.read_one_thread_ms), reads->all_threads_gbs(row.read_all_threads_ms), o.threads,
          machine);
    }
  }
  CatmullClarkOptions catmull_clark;
  catmull_clark.faces = o.faces;
  catmull_clark.levels = o.levels;
  catmull_clark.reps = o.reps;
  catmull_clark.back_memory = !o.cold;
  catmull_clark.backed_mib = kBackedMiB;
  all_ok = compare_catmull_clark(catmull_clark) && all_ok;
  if (!all_ok) {
    std::printf("\nSOME OUTPUTS DID NOT MATCH OURS (see FAIL lines): their times are left out\n");
    return 1;
  }
  return 0;
}
