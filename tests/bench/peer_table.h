// The one table peer_bench prints: a row per measurement, ours against OpenMesh and CGAL, the ratios
// peer/ours and whether each row's target ratio is met. Whether a target is met is judged only on a quiet machine
// (Judging: the load average at the start at most 1): on a busy one the peers pay for the load differently, and
// the status says the run was not judged.
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace meshedit::bench {

inline constexpr int kPeerSlots = 2;  // 0 = OpenMesh, 1 = CGAL
inline const char* const kPeerNames[kPeerSlots] = {"OpenMesh", "CGAL"};

struct TableRow {
  std::string label;  // says the unit: ms or B/face
  double ours = NAN;
  double ours_threads = NAN;  // ours with --threads N, NAN if not measured
  // The machine's memory read (machine_bandwidth.h) on one thread and on --threads threads, timed in the same rounds
  // as ours_threads (NAN if not measured): how far the host let a streaming pass scale in those rounds.
  double read_one_thread_ms = NAN, read_all_threads_ms = NAN;
  double peer[kPeerSlots] = {NAN, NAN};
  std::string peer_note[kPeerSlots];       // why a peer has no number ("absent", "mismatch")
  double target[kPeerSlots] = {1.0, 1.0};  // peer/ours must be at least this
  bool has_target = true;                  // false: the row informs (memory) and has no status
};

// Whether targets are judged, and why not.
struct Judging {
  double load = 0.0;  // the 1-minute load average when the program started
  bool judged() const { return load <= 1.0; }
};

// Prints the rows; `threads` > 1 adds the column of ours with that many threads.
void print_table(const std::vector<TableRow>& rows, int threads, const Judging& judging);

// "met", "NOT met", "n/a ...", or "not judged (load ...)" for one row.
std::string row_status(const TableRow& row, const Judging& judging);

}  // namespace meshedit::bench
