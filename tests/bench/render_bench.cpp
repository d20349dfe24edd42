// render_bench: the window's costs on generated tori, offscreen through EGL (llvmpipe on a machine without a GPU),
// and the pointer tables' frame at 6M+ halfedges. Not a test: it prints numbers and asserts nothing.
//
//   render_bench [--faces N[,N...]] [--frames F] [--size WxH] [--samples S] [--tables-faces N] [--no-tables]
//                [--frames-only]
//   defaults: 10000,100000,1000000 faces, 10 frames, 1280x800, 4x multisampling, tables on 1M faces subdivided once;
//   --frames-only stops each mesh after the quality levels and skips the tables
//
// For each mesh (with the load average as it starts): the first update (CPU build + upload); a clear alone; the frame
// (clear + update + draw + resolve of the samples, as a buffer swap does, + glFinish; median and minimum of F frames)
// at each quality level of the governor (quality_governor.h: full, then without multisampling, the wireframe, the
// back sides), the ratios between them, and the governor run frame by frame on these frames from the app's starting
// guess, with the level it settles on; an idle update() and an orbit frame at that level with
// the counters that prove they do no per-element work; pick() with the id buffer redrawn (which pass) and at the
// same camera;
// update() after a flip, a split and a collapse (a patch of the touched slots) against a full rebuild, with the
// bytes sent, and what the document's own bookkeeping of the flip costs (snapshot, diff).
// Then the pointer tables (the halfedge tab) in the headless ImGui harness: the frame at the first row, the middle and
// the end, and the worst frame of a scroll through a window's worth of rows.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "core/change_journal.h"
#include "core/history.h"
#include "core/loop_subdivision.h"
#include "core/mesh_build.h"
#include "core/mesh_ops.h"
#include "core/mesh_patch.h"
#include "core/parallel_for.h"
#include "core/primitives.h"
#include "document/document_actions.h"
#include "document/mesh_document.h"
#include "document/script_console.h"
#include "document/selection.h"
#include "render/camera.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_context.h"
#include "render/quality_governor.h"
#include "render/render_error.h"
#include "render/render_target.h"
#include "render/shader_library.h"
#include "render/slot_geometry.h"
#include "support/imgui_harness.h"
#include "ui/pointer_tables.h"

namespace {

using Clock = std::chrono::steady_clock;
using namespace meshedit;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const char* arg(int argc, char** argv, const char* name, const char* fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return argv[i + 1];
  }
  return fallback;
}

bool flag(int argc, char** argv, const char* name) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return true;
  }
  return false;
}

std::vector<uint32_t> parse_counts(const std::string& text) {
  std::vector<uint32_t> counts;
  size_t start = 0;
  while (start < text.size()) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const long value = std::strtol(item.c_str(), nullptr, 10);
    if (value >= 8) counts.push_back(uint32_t(std::min(value, 20000000L)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return counts;
}

struct Timing {
  double min = 0.0, median = 0.0, max = 0.0;
};

Timing time_frames(int frames, const std::function<void()>& frame) {
  std::vector<double> times;
  for (int i = 0; i < frames; ++i) {
    const auto start = Clock::now();
    frame();
    times.push_back(ms_since(start));
  }
  std::sort(times.begin(), times.end());
  return {times.front(), times[times.size() / 2], times.back()};
}

void line(const char* label, const char* format, double value, const std::string& note = {}) {
  std::printf("  %-52s ", label);
  std::printf(format, value);
  if (!note.empty()) std::printf("  (%s)", note.c_str());
  std::printf("\n");
}

std::vector<ElementRef> changed_elements(const HalfedgeMesh& before, const HalfedgeMesh& after) {
  std::vector<ElementRef> out;
  for (const FieldChange& c : diff(before, after)) {
    if (out.empty() || !(out.back() == c.element)) out.push_back(c.element);
  }
  return out;
}

// An edge the operation accepts, searched from `start`.
template <class Can>
EdgeId edge_for(const HalfedgeMesh& mesh, uint32_t start, Can&& can) {
  for (uint32_t i = start; i < mesh.edge_capacity(); ++i) {
    if (can(mesh, EdgeId(i))) return EdgeId(i);
  }
  return EdgeId(0);
}

// Times update() after `op` changed the mesh: as a patch (with the change described) and as a full rebuild of the
// same change (the same renderer, no description).
void time_edit(MeshRenderer& renderer, HalfedgeMesh& mesh, const char* name,
               const std::function<bool(HalfedgeMesh&)>& op) {
  // As the window does it: the edit under a change journal, the renderer given its patch (the state before is read
  // through it, no copy of the mesh). The copy here only lists the changed elements, outside the timing.
  const HalfedgeMesh before = mesh;
  std::optional<MeshPatch> edit;
  {
    ChangeJournal journal(mesh);
    if (!op(mesh)) {
      std::printf("  %s refused\n", name);
      return;
    }
    journal.detach();
    edit = make_patch(journal, mesh);
  }
  const std::vector<ElementRef> elements = changed_elements(before, mesh);
  MeshRenderer::MeshChange change{nullptr, elements, before.version(), mesh.version(), &*edit};
  auto start = Clock::now();
  renderer.update(mesh, &change);
  glFinish();
  const double patch_ms = ms_since(start);
  const RenderStats patched = renderer.stats();
  char label[96], note[160];
  std::snprintf(label, sizeof label, "update() after a %s (patch)", name);
  std::snprintf(note, sizeof note, "%zu elements changed, %zu slots, %zu bytes sent%s", elements.size(),
                patched.last_update_slots, patched.last_update_bytes, patched.patches == 0 ? "; NOT a patch" : "");
  line(label, "%10.3f ms", patch_ms, note);
  // The same state again as a full rebuild.
  renderer.invalidate();
  start = Clock::now();
  renderer.update(mesh);
  glFinish();
  std::snprintf(label, sizeof label, "update() after a %s (full rebuild)", name);
  std::snprintf(note, sizeof note, "%.1f MB sent", double(renderer.stats().last_update_bytes) / 1e6);
  line(label, "%10.3f ms", ms_since(start), note);
}

const char* const kLevelNames[kQualitySteps + 1] = {"full: multisampling, wireframe, back sides", "no multisampling",
                                                    "no multisampling, no wireframe",
                                                    "no multisampling, no wireframe, no back sides"};
const char* const kStepNames[kQualitySteps] = {"multisampling", "wireframe", "back sides"};

// What the window draws at a quality level, on a closed mesh with the user's wireframe choice left to the governor.
ViewOptions options_at_level(int level) {
  ViewOptions options;
  options.multisampling = level < 1;
  options.wireframe = level < 2;
  options.back_sides = level < 3;
  return options;
}

// The 1-minute load average (other work on the machine skews every figure).
std::string load_average() {
  char text[64] = "?";
  if (FILE* file = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(file, "%15s", text) != 1) std::snprintf(text, sizeof text, "?");
    std::fclose(file);
  }
  return text;
}

// The governor as the window runs it: each frame drawn at its level and its time fed back, from the app's starting
// guess (the cheapest level for a large mesh, else full quality), until the level has not moved for three windows
// (or 80 frames). Prints the levels frame by frame and where it settled; returns the options it settled on.
ViewOptions run_governor(MeshRenderer& renderer, const std::function<void(const ViewOptions&)>& draw_frame) {
  const bool large = is_large_mesh(renderer.stats().triangles, renderer.style());
  QualityGovernor governor;
  governor.reset(large ? kQualitySteps : 0);
  QualitySteps steps;
  steps.multisampling = renderer.stats().framebuffer_samples > 1;
  steps.back_sides = is_closed(renderer.stats());
  governor.set_steps(steps);
  const size_t still_frames = 3 * QualityRules().window;
  std::string path;
  std::vector<double> times;
  size_t still = 0;
  int frame = 0;
  for (; frame < 80 && still < still_frames; ++frame) {
    const int level = governor.level();
    const auto start = Clock::now();
    draw_frame(options_at_level(level));
    const double ms = ms_since(start);
    governor.measured(ms);
    path += std::to_string(level);
    times.push_back(ms);
    still = governor.level() == level ? still + 1 : 0;
    if (governor.level() != level) times.clear();
  }
  std::sort(times.begin(), times.end());
  const double median = times.empty() ? 0.0 : times[times.size() / 2];
  char note[200];
  std::snprintf(note, sizeof note, "level %d (%s) after %d frames from level %d; levels: %s", governor.level(),
                kLevelNames[governor.level()], frame, large ? kQualitySteps : 0, path.c_str());
  line("governor: frame at the level it settles on (median)", "%10.2f ms", median, note);
  return options_at_level(governor.level());
}

void bench_mesh(uint32_t faces, int frames, Viewport viewport, RenderTarget& target, const ShaderLibrary& shaders,
                bool frames_only) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(faces));
  MeshRenderer renderer(shaders);
  std::printf("\ntorus: %zu triangles, %zu vertices; load average %s\n", mesh.num_faces(), mesh.num_vertices(),
              load_average().c_str());

  auto start = Clock::now();
  renderer.update(mesh);
  glFinish();
  char note[160];
  std::snprintf(note, sizeof note, "%.1f MB of GPU buffers", double(renderer.stats().gpu_bytes) / 1e6);
  line("first update (build + upload)", "%10.2f ms", ms_since(start), note);
  for (const int threads : {1, hardware_threads()}) {
    double best = 1e300;
    for (int i = 0; i < 3; ++i) {
      start = Clock::now();
      const SlotGeometry g = build_slot_geometry(mesh, threads);
      best = std::min(best, ms_since(start));
    }
    std::snprintf(note, sizeof note, "min of 3, %d thread%s%s", threads, threads == 1 ? "" : "s",
                  threads == hardware_threads() ? " (the renderer's)" : "");
    line("  CPU build of the slots (build_slot_geometry)", "%10.2f ms", best, note);
  }
  OrbitCamera camera;
  camera.fit(renderer.bounds());

  const Timing clear = time_frames(frames, [&] {
    target.clear(renderer.style().background);
    glFinish();
  });
  std::snprintf(note, sizeof note, "median %.2f", clear.median);
  line("clear only (min)", "%10.2f ms", clear.min, note);

  // The frame at each quality level (quality_governor.h), then the levels the governor picks frame by frame from
  // these frames' times, from the app's starting guess, and where it settles.
  const auto draw_frame = [&](const ViewOptions& options) {
    renderer.update(mesh);
    target.clear(renderer.style().background);
    renderer.draw(camera, viewport, options, {});
    target.resolve();  // as the window's buffer swap does
    glFinish();
  };
  std::array<double, kQualitySteps + 1> level_ms{};
  for (int level = 0; level <= kQualitySteps; ++level) {
    const ViewOptions options = options_at_level(level);
    draw_frame(options);  // llvmpipe compiles shader variants on first use
    const Timing t = time_frames(frames, [&] { draw_frame(options); });
    level_ms[size_t(level)] = t.median;
    std::snprintf(note, sizeof note, "min %.2f; %s", t.min, kLevelNames[level]);
    char label[96];
    std::snprintf(label, sizeof label, "frame at quality level %d (median)", level);
    line(label, "%10.2f ms", t.median, note);
  }
  std::printf("  %-52s ", "  ratios, level above / level");
  for (int step = 0; step < kQualitySteps; ++step) {
    std::printf(" %s %.2f", kStepNames[step], level_ms[size_t(step)] / level_ms[size_t(step) + 1]);
  }
  std::printf("  (the governor's defaults until measured: %.1f %.1f %.1f)\n", QualityRules().default_ratio[0],
              QualityRules().default_ratio[1], QualityRules().default_ratio[2]);
  const ViewOptions settled_options = run_governor(renderer, draw_frame);

  if (frames_only) return;

  // Idle and orbit: the counters must not move.
  renderer.draw(camera, viewport, settled_options, {});
  renderer.pick(camera, viewport, viewport.width / 2, viewport.height / 2);
  const RenderStats settled = renderer.stats();
  const Timing idle = time_frames(1000, [&] { renderer.update(mesh); });
  const Timing orbit = time_frames(frames, [&] {
    camera.orbit(3, 1);
    renderer.update(mesh);
    target.clear(renderer.style().background);
    renderer.draw(camera, viewport, settled_options, {});
    glFinish();
  });
  const RenderStats after = renderer.stats();
  std::snprintf(note, sizeof note, "uploads %llu -> %llu, patches %llu -> %llu",
                static_cast<unsigned long long>(settled.uploads), static_cast<unsigned long long>(after.uploads),
                static_cast<unsigned long long>(settled.patches), static_cast<unsigned long long>(after.patches));
  line("update(), unchanged version (idle frame)", "%10.5f ms", idle.median, note);
  std::snprintf(note, sizeof note, "median %.2f; id passes %llu -> %llu, highlight uploads %llu -> %llu", orbit.median,
                static_cast<unsigned long long>(settled.id_passes), static_cast<unsigned long long>(after.id_passes),
                static_cast<unsigned long long>(settled.highlight_uploads),
                static_cast<unsigned long long>(after.highlight_uploads));
  line("orbit frame (camera moved, update + draw) (min)", "%10.2f ms", orbit.min, note);

  // Picking.
  const ScreenPoint v0 = camera.project(mesh.position(VertexId(0)), viewport);
  const int x = std::clamp(int(v0.pixel.x), 0, viewport.width - 1);
  const int y = std::clamp(int(v0.pixel.y), 0, viewport.height - 1);
  start = Clock::now();
  const ElementRef first = renderer.pick(camera, viewport, x, y);
  const double pick_ms = ms_since(start);
  const std::string pick_note =
      format_id(first) + (renderer.stats().last_id_pass_faces_only ? ", faces-only pass (large mesh)" : ", exact pass");
  line("pick, id buffer redrawn (after a camera move)", "%10.2f ms", pick_ms, pick_note);
  const Timing again = time_frames(100, [&] { renderer.pick(camera, viewport, x + 3, y); });
  line("pick, same camera (reads 9x9 pixels)", "%10.3f ms", again.median);

  // Local edits: a patch against a full rebuild of the same state.
  time_edit(renderer, mesh, "flip",
            [](HalfedgeMesh& m) { return bool(flip(m, edge_for(m, m.edge_capacity() / 3, can_flip))); });
  time_edit(renderer, mesh, "split",
            [](HalfedgeMesh& m) { return bool(split(m, edge_for(m, m.edge_capacity() / 2, can_split))); });
  time_edit(renderer, mesh, "collapse",
            [](HalfedgeMesh& m) { return bool(collapse(m, edge_for(m, m.edge_capacity() / 5, can_collapse))); });

  // What the document itself does for an edit, outside the renderer: the change journal, the undo patch and the diff,
  // with no copy of the mesh (the renderer and the validation read the state before through the patch), so every edit,
  // undo and redo costs time proportional to the edit, the first after opening too. The first append to a tightly
  // sized array moves it once, as any append does (the operation itself, as "split alone" shows).
  {
    HalfedgeMesh alone = mesh;
    const EdgeId e = edge_for(alone, alone.edge_capacity() / 2, can_split);
    start = Clock::now();
    (void)split(alone, e);
    line("split alone, first append (no document)", "%10.3f ms", ms_since(start));
  }
  MeshDocument doc = make_document(mesh);
  auto document_step = [&](const char* label, const std::function<void()>& step) {
    start = Clock::now();
    step();
    line(label, "%10.3f ms", ms_since(start), std::to_string(doc.last.change_count) + " fields changed");
  };
  auto edit = [&](const char* label, const char* verb, uint32_t at) {
    const bool flipping = verb[0] == 'f';
    const EdgeId e = edge_for(doc.mesh, at, flipping ? can_flip : can_split);
    document_step(label, [&] {
      apply_operation(doc, verb, [&](HalfedgeMesh& m) { return flipping ? flip(m, e).check : split(m, e).check; });
    });
  };
  const uint32_t edges = doc.mesh.edge_capacity();
  edit("document: first apply_operation(flip) after opening", "flip", edges / 4);
  edit("document: apply_operation(flip) (journal + patch)", "flip", edges / 3);
  edit("document: apply_operation(split), first append", "split", edges / 2);
  edit("document: apply_operation(split), the second", "split", edges / 5);
  edit("document: apply_operation(split)", "split", edges / 6);
  document_step("document: undo (patch)", [&] { undo(doc); });
  document_step("document: undo (patch), again", [&] { undo(doc); });
  document_step("document: redo (patch)", [&] { redo(doc); });
  document_step("document: redo (patch), again", [&] { redo(doc); });

  // The status bar's validation of each new state: the whole mesh once, then each local edit from its patch alone.
  auto validation_step = [&](const char* label) {
    start = Clock::now();
    const bool ok = cached_validation(doc).ok();
    const char* how = doc.validation.value.from_patch ? ", from the patch" : ", whole mesh";
    line(label, "%10.3f ms", ms_since(start), std::string(ok ? "valid" : "broken") + how);
  };
  validation_step("document: validation (whole mesh, machine's threads)");
  edit("document: apply_operation(flip)", "flip", edges / 7);
  validation_step("document: validation after the flip");
  edit("document: apply_operation(split)", "split", edges / 8);
  validation_step("document: validation after the split");
  document_step("document: undo (patch)", [&] { undo(doc); });
  validation_step("document: validation after the undo");

  // A console line that edits the mesh: the console's own mesh syncs from the document, the script edits it, and the
  // change reaches the document as the same writes (a patch). The first line copies the document's mesh into the
  // console, and the script's undo history copies it again at its first operation; later lines, and a line after
  // one edit made elsewhere (F), cost time proportional to the edit.
  ScriptConsole console;
  const Selection nothing;
  auto console_step = [&](const char* label, const std::string& line) {
    document_step(label, [&] { console.submit(doc, nothing, line); });
  };
  console_step("console: a flip, first line (copies the mesh twice)",
               "mesh:flip(mesh:edge(" + std::to_string(edges / 9) + "))");
  validation_step("document: validation after the console's flip");
  console_step("console: a flip, next line", "mesh:flip(mesh:edge(" + std::to_string(edges / 10) + "))");
  console_step("console: one position written", "mesh:vertex(7).position = mesh:vertex(8).position");
  edit("document: apply_operation(flip) (as F would)", "flip", edges / 11);
  console_step("console: a flip after that (catches up by patch)",
               "mesh:flip(mesh:edge(" + std::to_string(edges / 12) + "))");
  validation_step("document: validation after those two lines");

  // A whole-mesh change (L, as the key does it) and its undo and redo: the history keeps a snapshot of the state
  // before, and `last` a copy of it only when its diff is listed (a small mesh); here the diff is too long to list.
  Selection selection;
  document_step("document: Loop subdivision (L)", [&] { loop_subdivide_all(doc, selection); });
  document_step("document: undo L (snapshot)", [&] { undo(doc); });
  document_step("document: redo L (snapshot)", [&] { redo(doc); });
  edit("document: apply_operation(flip), first after L", "flip", doc.mesh.edge_capacity() / 3);
}

// The halfedge tab of the pointer tables at 6M+ halfedges: frames at the top, the middle and the end, and the worst
// frame of a scroll (mouse wheel) through more than a window of rows, which slides the laid-out window.
void bench_tables(uint32_t faces, int frames) {
  HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(faces));
  loop_subdivide(mesh, LoopWeights::Course, 1, 2);
  MeshDocument doc = make_document(std::move(mesh));
  std::printf("\npointer tables: %zu halfedges (a %u-face torus subdivided once), headless ImGui 1280x800\n",
              doc.mesh.num_halfedges(), faces);
  ui_testing::ImGuiHarness imgui;
  Selection selection;
  TablesState state;
  state.active = TableTab::Halfedges;
  const auto draw = [&] {
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(ImVec2(560, 760));
    draw_pointer_tables(doc, selection, state);
  };
  const uint32_t n = doc.mesh.halfedge_capacity();
  for (const uint32_t target : {0u, n / 2, n - 1}) {
    reveal_in_tables(state, ElementRef(HalfedgeId(target)));
    for (int i = 0; i < 4; ++i) imgui.frame(draw);  // the tab opens, the row scrolls into view, settles
    const Timing t = time_frames(frames * 10, [&] { imgui.frame(draw); });
    char label[96], note[96];
    std::snprintf(label, sizeof label, "table frame at h%u (min)", target);
    std::snprintf(note, sizeof note, "median %.3f, max %.3f; %zu rows read", t.median, t.max, state.rows_drawn);
    line(label, "%10.3f ms", t.min, note);
  }
  // Scroll with the wheel from the middle: 3000 frames of 5 rows' worth each, past several window slides.
  reveal_in_tables(state, ElementRef(HalfedgeId(n / 2)));
  for (int i = 0; i < 4; ++i) imgui.frame(draw);
  ImGuiIO& io = ImGui::GetIO();
  io.MousePos = ImVec2(280, 400);
  const uint32_t start_row = state.window_start[static_cast<int>(ElementKind::Halfedge)];
  const Timing scroll = time_frames(3000, [&] {
    io.MouseWheel = -5.0f;
    imgui.frame(draw);
  });
  char note[160];
  std::snprintf(note, sizeof note, "median %.3f, max %.3f; window start h%u -> h%u", scroll.median, scroll.max,
                start_row, state.window_start[static_cast<int>(ElementKind::Halfedge)]);
  line("table frame while scrolling (min)", "%10.3f ms", scroll.min, note);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<uint32_t> counts = parse_counts(arg(argc, argv, "--faces", "10000,100000,1000000"));
  const int frames = std::clamp(std::atoi(arg(argc, argv, "--frames", "10")), 1, 1000);
  const int samples = std::clamp(std::atoi(arg(argc, argv, "--samples", "4")), 0, 16);
  const bool frames_only = flag(argc, argv, "--frames-only");
  const long table_faces_arg = std::atol(arg(argc, argv, "--tables-faces", "1000000"));
  const uint32_t table_faces = uint32_t(std::clamp(table_faces_arg, 8L, 4000000L));
  Viewport viewport{1280, 800};
  std::sscanf(arg(argc, argv, "--size", "1280x800"), "%dx%d", &viewport.width, &viewport.height);

  try {
    OffscreenContext context;
    const ShaderLibrary shaders;
    RenderTarget target(viewport.width, viewport.height, samples);
    std::printf("%s; %dx%d, %dx multisampling, %d frames per figure\n", context.description().c_str(), viewport.width,
                viewport.height, target.samples(), frames);
    for (uint32_t faces : counts) bench_mesh(faces, frames, viewport, target, shaders, frames_only);
  } catch (const RenderError& e) {
    // No OpenGL here (the render tests skip too): the table figures need none.
    std::fprintf(stderr, "render_bench: %s; the frame figures are skipped\n", e.what());
  }
  if (!flag(argc, argv, "--no-tables") && !frames_only) bench_tables(table_faces, frames);
  return 0;
}
