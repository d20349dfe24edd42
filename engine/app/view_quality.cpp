// ViewQuality: frames, documents and the wireframe's owner for the quality governor (see view_quality.h).
#include "app/view_quality.h"

#include <vector>

#include "core/translation.h"
#include "core/value_format.h"

namespace meshedit {

void ViewQuality::frame_started(float last_frame_ms) {
  if (drew_ && !held_full_) governor_.measured(double(last_frame_ms));
  drew_ = false;
}

void ViewQuality::follow_mesh(uint64_t generation, size_t triangles, const RenderStyle& style, ViewOptions& options) {
  const bool other_document = !following_ || generation != generation_;
  const bool resized = triangles != triangles_ && (triangles >= 2 * triangles_ || 2 * triangles <= triangles_);
  if (!other_document && !resized) return;
  following_ = true;
  generation_ = generation;
  triangles_ = triangles;
  if (other_document) users_wireframe_ = false;
  governor_.reset(!held_full_ && is_large_mesh(triangles, style) ? kQualitySteps : 0);
  QualitySteps steps = governor_.steps();
  steps.wireframe = !users_wireframe_;
  governor_.set_steps(steps);
  write_wireframe(options);
  update_note();
}

void ViewQuality::hold_full(bool hold, ViewOptions& options) {
  held_full_ = hold;
  if (hold) governor_.reset(0);
  write_wireframe(options);
  update_note();
}

namespace {

// What the user shows besides the wireframe (whose changes are told apart by ViewQuality itself).
bool same_parts_shown(const ViewOptions& a, const ViewOptions& b) {
  return a.smooth_shading == b.smooth_shading && a.show_vertices == b.show_vertices &&
         a.show_halfedges == b.show_halfedges && a.show_boundary == b.show_boundary;
}

}  // namespace

ViewOptions ViewQuality::options_to_draw(ViewOptions& options, const RenderStats& stats) {
  drew_ = true;
  const bool user_wireframe_change = options.wireframe != wireframe_written_;
  if (user_wireframe_change) users_wireframe_ = true;
  if (user_wireframe_change || !same_parts_shown(options, last_options_)) governor_.view_changed();
  last_options_ = options;
  governor_.set_steps({stats.framebuffer_samples > 1, !users_wireframe_, is_closed(stats)});
  write_wireframe(options);
  ViewOptions drawn = options;
  drawn.multisampling = !governor_.drops(QualityStep::Multisampling);
  drawn.back_sides = !governor_.drops(QualityStep::BackSides);
  update_note();
  return drawn;
}

void ViewQuality::write_wireframe(ViewOptions& options) {
  if (!users_wireframe_) options.wireframe = !governor_.drops(QualityStep::Wireframe);
  wireframe_written_ = options.wireframe;
}

void ViewQuality::update_note() {
  // In the window's language (made again each frame the view draws): each dropped step's name, listed by a template
  // per count, the list under the frame time or "large mesh", then how to get the wireframe back.
  std::vector<std::string> dropped;
  if (governor_.drops(QualityStep::Multisampling)) dropped.emplace_back(tr("multisampling"));
  if (governor_.drops(QualityStep::BackSides)) dropped.emplace_back(tr("back sides"));
  if (governor_.drops(QualityStep::Wireframe)) dropped.emplace_back(tr("wireframe"));  // last: "(W shows it)" follows
  note_.clear();
  if (dropped.empty()) return;
  std::string off;
  if (dropped.size() == 1) {
    off = tr_format("{a} off", {{"a", dropped[0]}});
  } else if (dropped.size() == 2) {
    off = tr_format("{a} and {b} off", {{"a", dropped[0]}, {"b", dropped[1]}});
  } else {
    off = tr_format("{a}, {b} and {c} off", {{"a", dropped[0]}, {"b", dropped[1]}, {"c", dropped[2]}});
  }
  note_ = governor_.slow_ms() > 0.0
              ? tr_format("frame {ms} ms: {dropped}", {{"ms", format_fixed(governor_.slow_ms(), 0)}, {"dropped", off}})
              : tr_format("large mesh: {dropped}", {{"dropped", off}});
  if (governor_.drops(QualityStep::Wireframe)) note_ = tr_format("{note} (W shows it)", {{"note", note_}});
}

}  // namespace meshedit
