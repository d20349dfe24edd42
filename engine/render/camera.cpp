// OrbitCamera math (see camera.h for the conventions). Everything is in doubles: the matrices are
// converted to float only when they are handed to OpenGL.
#include "render/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace meshedit {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxPitch = 89.0 * kPi / 180.0;
// The fitted box fills the field of view up to this margin.
constexpr double kFitMargin = 1.15;
// Clip planes sit this many scene radii beyond the fitted sphere, so overlays a little outside the mesh
// (a patch's control net) are not clipped either.
constexpr double kClipRadii = 2.0;

double radians(double degrees) { return degrees * kPi / 180.0; }
double degrees(double radians) { return radians * 180.0 / kPi; }

// The front view's frame for an up axis (core/up_axis.h): yaw = pitch = 0 puts the eye towards the viewer, yaw
// = 90 degrees to the right, pitch = 90 degrees above.
struct AxisFrame {
  glm::dvec3 right;
  glm::dvec3 up;
  glm::dvec3 towards_viewer;
};

AxisFrame axis_frame(UpAxis axis) {
  switch (axis) {
    case UpAxis::X: return {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}};
    case UpAxis::Y: return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    case UpAxis::Z: return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
  }
  return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
}

}  // namespace

void BoundingBox::add(const glm::dvec3& p) {
  min = glm::min(min, p);
  max = glm::max(max, p);
}

double BoundingBox::diagonal() const { return empty() ? 0.0 : glm::length(max - min); }

OrbitCamera::OrbitCamera() { fit(BoundingBox{}); }

void OrbitCamera::fit(const BoundingBox& box) {
  fit_box_ = box;
  if (fit_box_.empty()) {
    fit_box_.add(glm::dvec3(-0.5));
    fit_box_.add(glm::dvec3(0.5));
  } else if (!(fit_box_.diagonal() > 0.0) || !std::isfinite(fit_box_.diagonal())) {
    const glm::dvec3 centre = fit_box_.centre();
    fit_box_ = BoundingBox{};
    fit_box_.add(centre - 0.5);
    fit_box_.add(centre + 0.5);
  }
  scene_centre_ = fit_box_.centre();
  scene_radius_ = fit_box_.diagonal() * 0.5;
  fitted_yaw_ = radians(kDefaultYawDegrees);
  fitted_pitch_ = radians(kDefaultPitchDegrees);
  fitted_distance_ = fit_distance(fitted_yaw_, fitted_pitch_);
  reset();
}

void OrbitCamera::fit_looking_from(const BoundingBox& box, const glm::dvec3& direction) {
  fit(box);
  const double length = glm::length(direction);
  if (!(length > 0.0) || !std::isfinite(length)) return;
  // The angles whose view_offset is the direction: pitch from its part along up, yaw from the rest.
  const AxisFrame frame = axis_frame(up_axis_);
  const glm::dvec3 d = direction / length;
  fitted_pitch_ = std::clamp(std::asin(std::clamp(glm::dot(d, frame.up), -1.0, 1.0)), -kMaxPitch, kMaxPitch);
  fitted_yaw_ = std::atan2(glm::dot(d, frame.right), glm::dot(d, frame.towards_viewer));
  fitted_distance_ = fit_distance(fitted_yaw_, fitted_pitch_);
  reset();
}

double OrbitCamera::fit_distance(double yaw, double pitch) const {
  // In the view's frame, corner q (relative to the centre) at lateral offsets x, y and depth z
  // beyond the centre is inside the field of view when max(|x|, |y|) <= tan(fov/2) (d + z).
  const glm::dvec3 back = view_offset(yaw, pitch);
  const glm::dvec3 forward = -back;
  const glm::dvec3 right = glm::normalize(glm::cross(forward, up_vector()));
  const glm::dvec3 up = glm::cross(right, forward);
  const double slope = std::tan(radians(kFovDegrees) * 0.5) / kFitMargin;
  double distance = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner((i & 1) ? fit_box_.max.x : fit_box_.min.x, (i & 2) ? fit_box_.max.y : fit_box_.min.y,
                            (i & 4) ? fit_box_.max.z : fit_box_.min.z);
    const glm::dvec3 q = corner - scene_centre_;
    const double lateral = std::max(std::abs(glm::dot(q, right)), std::abs(glm::dot(q, up)));
    const double depth = glm::dot(q, forward);
    // Also keep the eye a little outside the box, in front of every corner.
    distance = std::max({distance, lateral / slope - depth, -depth + 0.1 * scene_radius_});
  }
  return distance;
}

void OrbitCamera::reset() {
  target_ = scene_centre_;
  distance_ = fitted_distance_;
  yaw_ = fitted_yaw_;
  pitch_ = fitted_pitch_;
}

void OrbitCamera::orbit(double dx_pixels, double dy_pixels) {
  yaw_ = std::remainder(yaw_ - dx_pixels * kRadiansPerPixel, 2.0 * kPi);
  pitch_ = std::clamp(pitch_ + dy_pixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::set_angles(double yaw_degrees, double pitch_degrees) {
  if (std::isfinite(yaw_degrees)) yaw_ = std::remainder(yaw_degrees * kPi / 180.0, 2.0 * kPi);
  if (std::isfinite(pitch_degrees)) pitch_ = std::clamp(pitch_degrees * kPi / 180.0, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::set_distance(double distance) {
  if (std::isfinite(distance) && distance > 0.0) distance_ = distance;
}

void OrbitCamera::set_target(const glm::dvec3& target) {
  if (std::isfinite(target.x) && std::isfinite(target.y) && std::isfinite(target.z)) target_ = target;
}

void OrbitCamera::pan(double dx_pixels, double dy_pixels, Viewport viewport) {
  const double height = std::max(1, viewport.height);
  const double world_per_pixel = 2.0 * distance_ * std::tan(fov_y_radians(viewport.aspect()) * 0.5) / height;
  target_ += (-right_direction() * dx_pixels + screen_up_direction() * dy_pixels) * world_per_pixel;
}

void OrbitCamera::zoom(double steps) {
  distance_ = std::clamp(distance_ * std::pow(kZoomPerStep, steps), fitted_distance_ / 100.0, fitted_distance_ * 20.0);
}

double OrbitCamera::zoom_steps() const { return std::log(distance_ / fitted_distance_) / std::log(kZoomPerStep); }

void OrbitCamera::set_up_axis(UpAxis axis) {
  up_axis_ = axis;
  fitted_distance_ = fit_distance(fitted_yaw_, fitted_pitch_);
}

double OrbitCamera::yaw_degrees() const { return degrees(yaw_); }
double OrbitCamera::pitch_degrees() const { return degrees(pitch_); }

glm::dvec3 OrbitCamera::up_vector() const { return axis_frame(up_axis_).up; }

glm::dvec3 OrbitCamera::view_offset(double yaw, double pitch) const {
  const AxisFrame frame = axis_frame(up_axis_);
  const double c = std::cos(pitch);
  return c * (std::sin(yaw) * frame.right + std::cos(yaw) * frame.towards_viewer) + std::sin(pitch) * frame.up;
}

glm::dvec3 OrbitCamera::eye() const { return target_ + view_offset(yaw_, pitch_) * distance_; }

glm::dvec3 OrbitCamera::forward_direction() const { return glm::normalize(target_ - eye()); }

glm::dvec3 OrbitCamera::right_direction() const { return glm::normalize(glm::cross(forward_direction(), up_vector())); }

glm::dvec3 OrbitCamera::screen_up_direction() const { return glm::cross(right_direction(), forward_direction()); }

double OrbitCamera::far_plane() const { return glm::length(eye() - scene_centre_) + kClipRadii * scene_radius_; }

double OrbitCamera::near_plane() const {
  const double far = far_plane();
  return std::max(glm::length(eye() - scene_centre_) - kClipRadii * scene_radius_, far * 1e-4);
}

glm::dmat4 OrbitCamera::view() const { return glm::lookAt(eye(), target_, up_vector()); }

double OrbitCamera::fov_y_radians(double aspect) {
  const double fov = radians(kFovDegrees);
  if (aspect >= 1.0 || !(aspect > 0.0)) return fov;
  return 2.0 * std::atan(std::tan(fov * 0.5) / aspect);
}

glm::dmat4 OrbitCamera::projection(double aspect) const {
  if (!(aspect > 0.0)) aspect = 1.0;
  return glm::perspective(fov_y_radians(aspect), aspect, near_plane(), far_plane());
}

ScreenPoint OrbitCamera::project(const glm::dvec3& world, Viewport viewport) const {
  const glm::dvec4 clip = view_projection(viewport) * glm::dvec4(world, 1.0);
  ScreenPoint out;
  out.in_front = clip.w > 0.0;
  if (clip.w == 0.0) return out;
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  out.pixel = glm::dvec2((ndc.x * 0.5 + 0.5) * viewport.width, (0.5 - ndc.y * 0.5) * viewport.height);
  out.depth = ndc.z * 0.5 + 0.5;
  return out;
}

Ray OrbitCamera::ray(const glm::dvec2& pixel, Viewport viewport) const {
  const double x = 2.0 * pixel.x / std::max(1, viewport.width) - 1.0;
  const double y = 1.0 - 2.0 * pixel.y / std::max(1, viewport.height);
  const glm::dmat4 inverse = glm::inverse(view_projection(viewport));
  const glm::dvec4 far = inverse * glm::dvec4(x, y, 1.0, 1.0);
  Ray ray;
  ray.origin = eye();
  ray.direction = glm::normalize(glm::dvec3(far) / far.w - ray.origin);
  return ray;
}

}  // namespace meshedit
