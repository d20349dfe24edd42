// Formatting of peer_bench's table (see peer_table.h): fixed-width text with | separators, so it reads in
// a terminal and pastes into Markdown.
#include "bench/peer_table.h"

#include <cstdio>

namespace meshedit::bench {
namespace {

// Three significant digits or more: 1234.5, 12.3, 1.23, 0.123.
std::string number(double value, int decimals = -1) {
  if (std::isnan(value)) return "-";
  if (decimals < 0) decimals = value >= 10 ? 1 : value >= 1 ? 2 : 3;
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::string target_text(const TableRow& row) {
  if (!row.has_target) return "-";
  char text[64];
  if (row.target[0] == row.target[1]) {
    std::snprintf(text, sizeof text, ">= %gx both", row.target[0]);
  } else {
    std::snprintf(text, sizeof text, ">= %gx OM, >= %gx CGAL", row.target[0], row.target[1]);
  }
  return text;
}

std::string not_judged(const Judging& judging) {
  char text[64];
  std::snprintf(text, sizeof text, "not judged (load %.2f > 1)", judging.load);
  return text;
}

}  // namespace

std::string row_status(const TableRow& row, const Judging& judging) {
  if (!row.has_target) return "-";
  int measured = 0, met = 0;
  bool failed = false;  // a peer that is present but has no number (its output did not match) fails the row
  std::string missing;
  for (int k = 0; k < kPeerSlots; ++k) {
    if (std::isnan(row.peer[k]) || std::isnan(row.ours)) {
      missing += std::string(missing.empty() ? "" : ", ") + kPeerNames[k] + " " +
                 (row.peer_note[k].empty() ? "absent" : row.peer_note[k]);
      failed = failed || !row.peer_note[k].empty();
      continue;
    }
    ++measured;
    const double ratio = row.peer[k] / row.ours;
    if (ratio >= row.target[k]) ++met;
  }
  if (measured == 0) return (failed ? "NOT met (" : "n/a (") + missing + ")";
  std::string status = failed              ? "NOT met"
                       : !judging.judged() ? not_judged(judging)
                       : met == measured   ? "met"
                                           : "NOT met";
  if (!missing.empty()) status += " (" + missing + ")";
  return status;
}

void print_table(const std::vector<TableRow>& rows, int threads, const Judging& judging) {
  const bool with_threads = threads > 1;
  char thread_header[32];
  std::snprintf(thread_header, sizeof thread_header, "ours %d thr", threads);
  std::printf("| %-40s | %10s |", "measurement", "ours");
  if (with_threads) std::printf(" %10s |", thread_header);
  std::printf(" %10s | %10s | %8s | %9s | %-22s | %s\n", kPeerNames[0], kPeerNames[1], "OM/ours", "CGAL/ours",
              "target (peer/ours)", "status");
  std::printf("|%s|%s|", std::string(42, '-').c_str(), std::string(12, '-').c_str());
  if (with_threads) std::printf("%s|", std::string(12, '-').c_str());
  std::printf("%s|%s|%s|%s|%s|%s\n", std::string(12, '-').c_str(), std::string(12, '-').c_str(),
              std::string(10, '-').c_str(), std::string(11, '-').c_str(), std::string(24, '-').c_str(),
              std::string(8, '-').c_str());
  for (const TableRow& row : rows) {
    std::printf("| %-40s | %10s |", row.label.c_str(), number(row.ours).c_str());
    if (with_threads) std::printf(" %10s |", number(row.ours_threads).c_str());
    std::string cells[kPeerSlots], ratios[kPeerSlots];
    for (int k = 0; k < kPeerSlots; ++k) {
      cells[k] =
          std::isnan(row.peer[k]) ? (row.peer_note[k].empty() ? "absent" : row.peer_note[k]) : number(row.peer[k]);
      ratios[k] = std::isnan(row.peer[k]) || std::isnan(row.ours) ? "-" : number(row.peer[k] / row.ours, 2) + "x";
    }
    std::printf(" %10s | %10s | %8s | %9s | %-22s | %s\n", cells[0].c_str(), cells[1].c_str(), ratios[0].c_str(),
                ratios[1].c_str(), target_text(row).c_str(), row_status(row, judging).c_str());
  }
}

}  // namespace meshedit::bench
