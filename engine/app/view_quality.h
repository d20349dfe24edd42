// ViewQuality: the mesh view's side of the quality governor (render/quality_governor.h). It decides which frames'
// times the governor hears, when it starts over, whose the wireframe is, and what the status bar says. No GL: the
// window's EditorApp calls it each frame; tests drive it with made-up times and stats.
//
// Per frame, in this order:
//   frame_started(ms of the last frame)   counted only when the last frame drew the mesh at the governor's level
//   follow_mesh(...)                       before anything else may change the options this frame (a lesson's view{})
//   options_to_draw(options, stats)        what to draw with; only on frames that draw the mesh
//
// Invariants:
// - The governor hears only frames that drew the mesh (not the curve or patch views, not a mesh the renderer refused),
//   each once, and frame times that leave out waiting for input (window_command.cpp measures them so).
// - It starts over on another document (a file, a lesson, the start cube) and when the drawn triangles grow or shrink
//   by 2x or more (L, its undo): from the cheapest level for a large mesh (is_large_mesh: before any frame is measured
//   a million triangles would take most of a second at full quality), else from full quality. The frame that showed
//   the new mesh is not counted (the governor ignores the first after a reset).
// - The wireframe is the user's once it changes other than by this class (W, the View menu, a lesson's view{}): from
//   then on the governor passes over it, shown or not, until another document. Otherwise `options.wireframe` is what
//   the governor's level says, written here so that W toggles what is on screen.
// - When the user changes what is shown (the wireframe, vertices, arrows, boundary, shading), the governor forgets
//   what it measured of each step (QualityGovernor::view_changed): those costs changed.
// - Multisampling and the back sides are never written into the caller's options, only into the copy drawn.
// - note() names what is dropped and why, short enough to leave room in the status bar: "frame 62 ms: multisampling
//   off", "large mesh: multisampling, back sides and wireframe off (W shows it)"; "" at full quality.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "render/mesh_renderer.h"
#include "render/quality_governor.h"
#include "render/view_options.h"

namespace meshedit {

class ViewQuality {
 public:
  void frame_started(float last_frame_ms);
  // `generation` is the document's (another one means another mesh); `triangles` the renderer's drawn count. May set
  // options.wireframe (to the starting level's).
  void follow_mesh(uint64_t generation, size_t triangles, const RenderStyle& style, ViewOptions& options);
  // Reads the user's wireframe choice from `options` and writes the governor's into it (unless it is the user's);
  // returns the options to draw with (multisampling and back sides as the level says).
  ViewOptions options_to_draw(ViewOptions& options, const RenderStats& stats);

  // Held: every frame draws at full quality, whatever it costs (the governor hears no frame times and starts each mesh
  // at level 0); a scripted run that compares pictures holds it. Let go: the governor measures again from here.
  void hold_full(bool hold, ViewOptions& options);

  const std::string& note() const { return note_; }
  const QualityGovernor& governor() const { return governor_; }
  bool wireframe_is_users() const { return users_wireframe_; }

 private:
  void write_wireframe(ViewOptions& options);
  void update_note();

  QualityGovernor governor_;
  bool following_ = false;  // follow_mesh has seen a mesh
  uint64_t generation_ = 0;
  size_t triangles_ = 0;  // at the last start-over
  bool users_wireframe_ = false;
  bool wireframe_written_ = true;  // what this class last wrote into options.wireframe
  bool drew_ = false;              // this frame drew the mesh (options_to_draw ran)
  bool held_full_ = false;         // hold_full: full quality, no frame heard
  ViewOptions last_options_;       // as options_to_draw last saw them
  std::string note_;
};

}  // namespace meshedit
