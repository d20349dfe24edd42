// Following the document's changes and timing their animation (see edit_animator.h).
#include "app/edit_animator.h"

#include <algorithm>

#include "document/edge_edit_label.h"
#include "render/edit_motion.h"

namespace meshedit {

void EditAnimator::set_enabled(bool enabled) {
  enabled_ = enabled;
  if (!enabled_) animation_.reset();
}

void EditAnimator::follow(const MeshDocument& doc) {
  if (animation_ && (doc.generation != generation_ || doc.mesh.version() != version_)) animation_.reset();
  const bool first = !seen_serial_;
  if (seen_serial_ == doc.last.serial) return;
  seen_serial_ = doc.last.serial;
  animation_.reset();
  if (first || !enabled_ || !doc.last.patch) return;
  const std::optional<EdgeEditLabel> label = read_edge_edit_label(doc.last.label);
  if (!label) return;
  animation_ = edit_animation_of_change(label->operation, label->edge, label->undone, doc.mesh, *doc.last.patch);
  elapsed_ = 0.0;
  generation_ = doc.generation;
  version_ = doc.mesh.version();
}

void EditAnimator::advance(double seconds) {
  if (!animation_) return;
  elapsed_ += seconds > 0.0 ? std::min(seconds, kMaxStepSeconds) : 0.0;  // NaN moves nothing
  if (elapsed_ >= kEditAnimationSeconds) animation_.reset();
}

Overlay EditAnimator::overlay(const EditAnimationLook& look) const {
  if (!animation_) return {};
  return edit_animation_frame(*animation_, time(), look);
}

}  // namespace meshedit
