// QualityGovernor: keeps the mesh view interactive by choosing how much optional quality it draws, from the measured
// times of the frames that drew it. Pure (no GL, no clock): the app feeds it frame times and reads its choice
// (app/view_quality.h); tests feed it series of times.
//
// Steps, dropped in this order (what a student misses least goes first) and taken back in the reverse order:
//   0 multisampling   (about half of llvmpipe's frame on a dense mesh)
//   1 the wireframe   (at a million triangles it costs more than the faces)
//   2 the back sides  (their pass; only on a closed mesh, where none can be seen from outside)
// The level is how many steps are taken: 0 is full quality, kQualitySteps the cheapest. A step that would change
// nothing now (QualitySteps: no samples to drop, the wireframe chosen by the user, an open mesh) drops nothing and is
// passed over when the level moves, so every move changes the picture.
//
// Rules (the numbers are QualityRules'):
// - Samples are the times of the frames drawn at the current level; the last `window` are kept. They are cleared when
//   the level moves or the steps change (the cost changes with them). The first sample after reset() is ignored: that
//   frame opened the file and uploaded the mesh.
// - Down: with at least `down_samples` samples whose median is over `down_ms`, one step down. A median passes over one
//   spike among three frames (an edit, a panel opening) and two among five.
// - Up: with `window` samples, when the cost predicted with the last step taken back, median x that step's ratio, is
//   under `up_ms`. A step's ratio is the one measured when the level last crossed it (the median of the first
//   `down_samples` frames after the move against the median that made the move), within [1, max_ratio]; before that,
//   or after view_changed(), `default_ratio`. The default is optimistic on purpose (render_bench on llvmpipe measures
//   1.2 to 2.8 per step): a display synchronised at 60 Hz makes every frame at least 16.7 ms, and 16.7 x 1.4 is still
//   under 25, so a fast GPU climbs back to full quality; a try that turns out slow costs `down_samples` frames once and
//   measures the true ratio.
// - Hysteresis: between up_ms and down_ms nothing moves, up needs a whole window and down fewer frames. A step up that
//   turns out slow comes back down after `down_samples` frames, having measured the step's ratio, so it is not tried
//   again while the frames cost what they did.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshedit {

enum class QualityStep : uint8_t { Multisampling, Wireframe, BackSides };
constexpr int kQualitySteps = 3;

// Which steps would change the picture (and so the cost) now.
struct QualitySteps {
  bool multisampling = true;  // the framebuffer has samples
  bool wireframe = true;      // the wireframe is the governor's to drop: the user has not chosen it (W)
  bool back_sides = true;     // the mesh is closed: skipping the back-side pass hides nothing seen from outside
  bool operator==(const QualitySteps&) const = default;
};

struct QualityRules {
  double down_ms = 40.0;
  double up_ms = 25.0;
  size_t down_samples = 3;
  size_t window = 5;
  // Frame time with the step taken back over frame time with it taken, until measured; and the most a measurement may
  // say: no step costs that much (render_bench: 2.8 at most), so more means the frames got dearer or cheaper for
  // another reason as the level moved, and believing it would keep the step away for good.
  std::array<double, kQualitySteps> default_ratio{1.4, 1.4, 1.4};
  double max_ratio = 4.0;
};

class QualityGovernor {
 public:
  explicit QualityGovernor(QualityRules rules = {});

  // Starts over at `level` (clamped to 0..kQualitySteps; the app's guess from the mesh's size), forgetting every
  // sample and measured ratio; the next sample is ignored.
  void reset(int level);
  void set_steps(QualitySteps steps);
  // The view's cost changed for a reason of its own (the user showed or hid something): forgets the samples and the
  // measured ratios, keeping the level.
  void view_changed();
  // The time of one frame drawn at level() with the current steps. Not finite or not positive: ignored.
  void measured(double frame_ms);

  int level() const { return level_; }
  // The step is taken and would change something: the app drops it.
  bool drops(QualityStep step) const;
  bool drops_anything() const;
  // The median frame time that made the last move down; 0 while the level is reset()'s guess.
  double slow_ms() const { return slow_ms_; }
  // The ratio up() would use for `step` (measured, or the default).
  double ratio(QualityStep step) const { return ratio_[size_t(step)]; }
  const QualitySteps& steps() const { return steps_; }

 private:
  bool available(int step) const;
  double median() const;
  void move_to(int level, int crossed_step, double median_before);

  QualityRules rules_;
  QualitySteps steps_;
  int level_ = 0;
  std::vector<double> samples_;  // oldest first, at most rules_.window
  bool skip_next_ = false;
  double slow_ms_ = 0.0;
  std::array<double, kQualitySteps> ratio_{};
  // The last move, until its ratio is measured: the step crossed and the median before it (crossed_ < 0: none).
  int crossed_ = -1;
  double median_before_ = 0.0;
  bool moved_down_ = false;
};

}  // namespace meshedit
