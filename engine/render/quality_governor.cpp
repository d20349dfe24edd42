// QualityGovernor: the level moves on medians of measured frame times (see quality_governor.h).
#include "render/quality_governor.h"

#include <algorithm>
#include <cmath>

namespace meshedit {

QualityGovernor::QualityGovernor(QualityRules rules) : rules_(rules), ratio_(rules.default_ratio) {
  rules_.down_samples = std::max<size_t>(rules_.down_samples, 1);
  rules_.window = std::max(rules_.window, rules_.down_samples);
}

void QualityGovernor::reset(int level) {
  level_ = std::clamp(level, 0, kQualitySteps);
  samples_.clear();
  skip_next_ = true;
  slow_ms_ = 0.0;
  ratio_ = rules_.default_ratio;
  crossed_ = -1;
}

void QualityGovernor::set_steps(QualitySteps steps) {
  if (steps == steps_) return;
  steps_ = steps;
  samples_.clear();
  crossed_ = -1;  // the costs on either side of the last move are not comparable any more
}

void QualityGovernor::view_changed() {
  samples_.clear();
  ratio_ = rules_.default_ratio;
  crossed_ = -1;
}

bool QualityGovernor::available(int step) const {
  switch (QualityStep(step)) {
    case QualityStep::Multisampling: return steps_.multisampling;
    case QualityStep::Wireframe: return steps_.wireframe;
    case QualityStep::BackSides: return steps_.back_sides;
  }
  return false;
}

bool QualityGovernor::drops(QualityStep step) const { return int(step) < level_ && available(int(step)); }

bool QualityGovernor::drops_anything() const {
  for (int step = 0; step < level_; ++step) {
    if (available(step)) return true;
  }
  return false;
}

double QualityGovernor::median() const {
  std::vector<double> sorted = samples_;
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

void QualityGovernor::move_to(int level, int crossed_step, double median_before) {
  moved_down_ = level > level_;
  level_ = level;
  samples_.clear();
  crossed_ = crossed_step;
  median_before_ = median_before;
}

void QualityGovernor::measured(double frame_ms) {
  if (!std::isfinite(frame_ms) || frame_ms <= 0.0) return;
  if (skip_next_) {
    skip_next_ = false;
    return;
  }
  samples_.push_back(frame_ms);
  if (samples_.size() > rules_.window) samples_.erase(samples_.begin());
  if (samples_.size() < rules_.down_samples) return;
  const double now = median();

  if (crossed_ >= 0) {  // the first frames after a move: what the step crossed costs
    const double with_step = moved_down_ ? median_before_ : now;
    const double without_step = moved_down_ ? now : median_before_;
    ratio_[size_t(crossed_)] = std::clamp(with_step / without_step, 1.0, std::max(1.0, rules_.max_ratio));
    crossed_ = -1;
  }

  if (now > rules_.down_ms) {
    for (int step = level_; step < kQualitySteps; ++step) {
      if (!available(step)) continue;
      slow_ms_ = now;
      move_to(step + 1, step, now);
      return;
    }
    return;
  }
  if (samples_.size() < rules_.window) return;
  for (int step = level_ - 1; step >= 0; --step) {
    if (!available(step)) continue;
    if (now * ratio_[size_t(step)] >= rules_.up_ms) return;
    int level = step;  // and past the steps before it that drop nothing, so the level says what is drawn
    while (level > 0 && !available(level - 1)) --level;
    move_to(level, step, now);
    return;
  }
}

}  // namespace meshedit
