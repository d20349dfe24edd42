// The one table peer_bench prints: a row per measurement, ours against OpenMesh and CGAL, the ratios
// peer/ours and whether each row's target ratio is met.
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
  double peer[kPeerSlots] = {NAN, NAN};
  std::string peer_note[kPeerSlots];       // why a peer has no number ("absent", "mismatch")
  double target[kPeerSlots] = {1.0, 1.0};  // peer/ours must be at least this
  bool strictly_below = false;             // memory: ours must be below the peer (peer/ours > 1)
};

// Prints the rows; `threads` > 1 adds the column of ours with that many threads.
void print_table(const std::vector<TableRow>& rows, int threads);

// "met", "NOT met" or "n/a ..." for one row (also used for the exit summary).
std::string row_status(const TableRow& row);

}  // namespace meshedit::bench
