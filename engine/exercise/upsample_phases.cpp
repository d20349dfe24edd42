// The phases of a recorded upsample (see upsample_phases.h for the contract).
//
// Two passes: the first gives operations, creations and position writes their phase and counts, for each script
// line, how many of its pointer writes were near a creation; the second gives each pointer write the phase its line
// mostly wrote in (a hand-written split or flip). Spans and problems are read off the phases.
#include "exercise/upsample_phases.h"

#include <algorithm>
#include <map>

#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {
namespace {

bool is_pointer_write(const RecordedEdit& edit) { return edit.what == EditKind::Set && edit.field != "position"; }

std::string write_text(size_t index, const RecordedEdit& edit) {
  const MessageParts parts = {{"number", std::to_string(index + 1)}, {"where", edit.where}};
  return edit.where.empty() ? tr_format("write {number}", parts) : tr_format("write {number} ({where})", parts);
}

const char* never_started_reason(UpsamplePhase phase) {
  switch (phase) {
    case UpsamplePhase::Split: return tr("no split was recorded");
    case UpsamplePhase::Flip: return tr("no flip was recorded");
    case UpsamplePhase::Commit: return tr("no vertex was moved");
    default: return "";
  }
}

constexpr UpsamplePhase kWritingPhases[] = {UpsamplePhase::Split, UpsamplePhase::Flip, UpsamplePhase::Commit};

}  // namespace

const char* upsample_phase_name(UpsamplePhase phase) {
  switch (phase) {
    case UpsamplePhase::Compute: return "new positions computed";
    case UpsamplePhase::Split: return "edges split";
    case UpsamplePhase::Flip: return "new edges flipped";
    case UpsamplePhase::Commit: return "positions committed";
    case UpsamplePhase::Other: break;
  }
  return "not part of Loop subdivision";
}

std::string upsample_phase_title(UpsamplePhase phase) {
  if (phase == UpsamplePhase::Other) return tr(upsample_phase_name(phase));
  return tr_format("phase {number} ({name})",
                   {{"number", std::to_string(int(phase))}, {"name", tr(upsample_phase_name(phase))}});
}

UpsamplePhase UpsamplePhases::phase_at(size_t k) const {
  if (k == 0 || phase_of.empty()) return UpsamplePhase::Compute;
  return phase_of[std::min(k, phase_of.size()) - 1];
}

std::optional<size_t> UpsamplePhases::start_position(UpsamplePhase p) const {
  if (p == UpsamplePhase::Compute) return size_t(0);
  if (p == UpsamplePhase::Other || !span[size_t(p)].started) return std::nullopt;
  return span[size_t(p)].first + 1;
}

size_t UpsamplePhases::end_position(UpsamplePhase p) const {
  if (p != UpsamplePhase::Compute && p != UpsamplePhase::Other && span[size_t(p)].started) {
    return span[size_t(p)].last + 1;
  }
  // Phase 1 (it writes nothing) and a phase that never started: the mesh the phases below it left, i.e. just
  // before the first write of a higher phase.
  size_t end = size();
  for (const UpsamplePhase q : kWritingPhases) {
    if (q > p && span[size_t(q)].started) end = std::min(end, span[size_t(q)].first);
  }
  return end;
}

std::optional<size_t> UpsamplePhases::next_phase_position(size_t k) const {
  std::optional<size_t> best;
  for (int p = 1; p <= kUpsamplePhaseCount; ++p) {
    const std::optional<size_t> start = start_position(UpsamplePhase(p));
    if (start && *start > k && (!best || *start < *best)) best = start;
  }
  return best;
}

std::optional<size_t> UpsamplePhases::previous_phase_position(size_t k) const {
  std::optional<size_t> best;
  for (int p = 1; p <= kUpsamplePhaseCount; ++p) {
    const std::optional<size_t> start = start_position(UpsamplePhase(p));
    if (start && *start < k && (!best || *start > *best)) best = start;
  }
  return best;
}

namespace {

// How many of a script line's pointer writes came near a creation, of all its pointer writes.
struct LineCount {
  size_t near = 0, total = 0;
};

// Pass 1: operations, creations and position writes get their phase; each pointer write is marked near a creation
// or not (`near`) and counted for its script line. A creation opens a window for kNearCreation edits (a hand-written
// split's pointer writes and its new vertex's position); an operation or a committed position closes it.
void phase_by_kind(std::span<const RecordedEdit> edits, UpsamplePhases& out, std::vector<uint8_t>& near,
                   std::map<std::string, LineCount>& lines) {
  bool created = false;                    // a creation is in the window
  size_t last_creation = 0;                // its index
  std::vector<uint32_t> created_vertices;  // in the open window
  const auto close_window = [&] {
    created = false;
    created_vertices.clear();
  };
  for (size_t i = 0; i < edits.size(); ++i) {
    const RecordedEdit& edit = edits[i];
    const bool window_open = created && i - last_creation <= UpsamplePhases::kNearCreation;
    if (!window_open) close_window();
    switch (edit.what) {
      case EditKind::Operation:
        out.phase_of[i] = edit.field == "split"  ? UpsamplePhase::Split
                          : edit.field == "flip" ? UpsamplePhase::Flip
                                                 : UpsamplePhase::Other;
        close_window();
        break;
      case EditKind::Create:
      case EditKind::Delete:
        out.phase_of[i] = UpsamplePhase::Split;
        if (edit.what == EditKind::Create && edit.element.kind == ElementKind::Vertex) {
          created_vertices.push_back(edit.element.index);
        }
        created = true;
        last_creation = i;
        break;
      case EditKind::Set:
        if (edit.field == "position") {
          const bool made_here =
              window_open && edit.element.kind == ElementKind::Vertex &&
              std::find(created_vertices.begin(), created_vertices.end(), edit.element.index) != created_vertices.end();
          out.phase_of[i] = made_here ? UpsamplePhase::Split : UpsamplePhase::Commit;
          if (!made_here) close_window();
        } else {
          near[i] = window_open ? 1 : 0;
          LineCount& count = lines[edit.where];
          count.near += near[i];
          ++count.total;
        }
        break;
    }
  }
}

// Pass 2: each pointer write takes the phase its line mostly wrote in (a line without a name: the write's own).
void phase_by_line(std::span<const RecordedEdit> edits, UpsamplePhases& out, const std::vector<uint8_t>& near,
                   std::map<std::string, LineCount>& lines) {
  for (size_t i = 0; i < edits.size(); ++i) {
    if (!is_pointer_write(edits[i])) continue;
    const LineCount& count = lines[edits[i].where];
    const bool split = edits[i].where.empty() ? near[i] != 0 : 2 * count.near > count.total;
    out.phase_of[i] = split ? UpsamplePhase::Split : UpsamplePhase::Flip;
  }
}

// Each phase's first and last write and its number of writes, read off phase_of.
void measure_spans(UpsamplePhases& out) {
  out.span[size_t(UpsamplePhase::Compute)].started = true;
  for (size_t i = 0; i < out.phase_of.size(); ++i) {
    const UpsamplePhase p = out.phase_of[i];
    if (p == UpsamplePhase::Other) {
      ++out.other_writes;
      continue;
    }
    UpsamplePhaseSpan& s = out.span[size_t(p)];
    if (!s.started) {
      s.started = true;
      s.first = i;
    }
    s.last = i;
    ++s.writes;
  }
}

void add_problem(UpsamplePhases& out, std::string line) {
  if (out.problems.size() < UpsamplePhases::kMaxProblems) out.problems.push_back(std::move(line));
}

// The problem of the earlier phase p against the later phase q, both started: q began first, or writes of p come
// after q began.
void check_order(std::span<const RecordedEdit> edits, UpsamplePhase p, UpsamplePhase q, UpsamplePhases& out) {
  const UpsamplePhaseSpan& sp = out.span[size_t(p)];
  const UpsamplePhaseSpan& sq = out.span[size_t(q)];
  MessageParts parts = {{"later", upsample_phase_title(q)},
                        {"write", write_text(sq.first, edits[sq.first])},
                        {"earlier", upsample_phase_title(p)},
                        {"earlier_write", write_text(sp.first, edits[sp.first])}};
  if (sq.first < sp.first) {
    add_problem(out, tr_format("{later} began at {write}, before {earlier} began at {earlier_write}: each step must be "
                               "done for every element before the next step begins",
                               parts));
    return;
  }
  size_t late = 0;
  std::optional<size_t> first_late;
  for (size_t i = sq.first + 1; i <= sp.last && i < edits.size(); ++i) {
    if (out.phase_of[i] != p) continue;
    ++late;
    if (!first_late) first_late = i;
  }
  if (late > 0) {
    parts.emplace_back("count", std::to_string(late));
    parts.emplace_back("first", write_text(*first_late, edits[*first_late]));
    add_problem(out, late == 1 ? tr_format("{count} write of {earlier} comes after {later} began at {write} (first: "
                                           "{first})",
                                           parts)
                               : tr_format("{count} writes of {earlier} come after {later} began at {write} (first: "
                                           "{first})",
                                           parts));
  }
}

// Problems: phases that never started, started out of order, or came back after a later phase began; then writes
// that are not part of Loop subdivision.
void find_problems(std::span<const RecordedEdit> edits, UpsamplePhases& out) {
  for (const UpsamplePhase p : kWritingPhases) {
    if (!out.span[size_t(p)].started) {
      add_problem(out, tr_format("{phase} never started: {reason}",
                                 {{"phase", upsample_phase_title(p)}, {"reason", never_started_reason(p)}}));
    }
  }
  for (const UpsamplePhase p : kWritingPhases) {
    if (!out.span[size_t(p)].started) continue;
    for (const UpsamplePhase q : kWritingPhases) {
      if (q > p && out.span[size_t(q)].started) check_order(edits, p, q, out);
    }
  }
  if (out.other_writes > 0) {
    const auto other = std::find(out.phase_of.begin(), out.phase_of.end(), UpsamplePhase::Other);
    const size_t i = size_t(other - out.phase_of.begin());
    const MessageParts parts = {
        {"count", std::to_string(out.other_writes)}, {"write", write_text(i, edits[i])}, {"edit", describe(edits[i])}};
    add_problem(out,
                out.other_writes == 1
                    ? tr_format("{count} write is not part of Loop subdivision (first: {write}, {edit})", parts)
                    : tr_format("{count} writes are not part of Loop subdivision (first: {write}, {edit})", parts));
  }
}

}  // namespace

UpsamplePhases find_upsample_phases(std::span<const RecordedEdit> edits) {
  UpsamplePhases out;
  out.phase_of.assign(edits.size(), UpsamplePhase::Other);
  std::vector<uint8_t> near(edits.size(), 0);
  std::map<std::string, LineCount> lines;
  phase_by_kind(edits, out, near, lines);
  phase_by_line(edits, out, near, lines);
  measure_spans(out);
  find_problems(edits, out);
  return out;
}

}  // namespace meshedit
