// HeadlessHost: records each LessonHost call as a line and keeps the scene state (see headless_host.h).
#include "lesson/headless_host.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/value_format.h"

namespace meshedit {
namespace {

// A number in a message: 30, 0.5, -2.25 (ten digits, no trailing zeros).
std::string number(double value) { return format_rounded(value, 10); }

std::string mesh_summary(const HalfedgeMesh& mesh) {
  return "(" + std::to_string(mesh.num_vertices()) + " vertices, " + std::to_string(mesh.num_edges()) + " edges, " +
         std::to_string(mesh.num_faces()) + " faces)";
}

std::string point_text(const glm::dvec3& p) {
  return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
}

}  // namespace

std::string colour_hex(glm::vec3 colour) {
  char buffer[8];
  const auto byte = [](float c) {
    const float clamped = std::isnan(c) ? 0.0f : std::clamp(c, 0.0f, 1.0f);
    return static_cast<unsigned>(std::lround(clamped * 255.0f));
  };
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", byte(colour.r), byte(colour.g), byte(colour.b));
  return buffer;
}

void HeadlessHost::show_mesh(std::shared_ptr<HalfedgeMesh> mesh, std::optional<UpAxis> up) {
  if (!mesh) {
    calls_.push_back("show_mesh (none)");
    shown_mesh_.reset();
    screen_mesh_.reset();
    return;
  }
  calls_.push_back("show_mesh " + mesh_summary(*mesh) + (up ? " " + std::string(up_axis_name(*up)) : ""));
  screen_mesh_ = std::make_shared<HalfedgeMesh>(*mesh);
  shown_mesh_ = std::move(mesh);
  curve_.reset();
  patches_.clear();
  selection_ = {};
}

void HeadlessHost::show_curve(const BezierCurve& curve) {
  calls_.push_back("show_curve " + std::to_string(curve.control_points.size()) + " points");
  curve_ = curve;
  curve_t_ = 0.5;
  patches_.clear();
  shown_mesh_.reset();
  screen_mesh_.reset();
  selection_ = {};
}

void HeadlessHost::show_patches(const std::vector<BezierPatch>& patches) {
  calls_.push_back("show_patches " + std::to_string(patches.size()));
  patches_ = patches;
  patch_probe_ = {};
  curve_.reset();
  shown_mesh_.reset();
  screen_mesh_.reset();
  selection_ = {};
}

void HeadlessHost::highlight(ElementRef element, glm::vec3 colour) {
  calls_.push_back("highlight " + format_id(element) + " " + colour_hex(colour));
  highlights_[element] = colour;
}

void HeadlessHost::label(ElementRef element, const std::string& text) {
  calls_.push_back("label " + format_id(element) + " \"" + text + "\"");
  labels_[element] = text;
}

void HeadlessHost::arrow(const glm::dvec3& from, const glm::dvec3& to, glm::vec3 colour) {
  calls_.push_back("arrow " + point_text(from) + " -> " + point_text(to) + " " + colour_hex(colour));
  arrows_.push_back({from, to, colour});
}

void HeadlessHost::clear_annotations() {
  calls_.push_back("clear_annotations");
  highlights_.clear();
  labels_.clear();
  arrows_.clear();
}

std::optional<CurveReading> HeadlessHost::curve_reading() const {
  if (!curve_) return std::nullopt;
  return CurveReading{curve_t_, curve_->control_points};
}

std::optional<PatchReading> HeadlessHost::patch_reading() const {
  if (patches_.empty()) return std::nullopt;
  return patch_probe_;
}

void HeadlessHost::set_patch_uv(double u, double v) {
  if (!std::isnan(u)) patch_probe_.u = std::clamp(u, 0.0, 1.0);
  if (!std::isnan(v)) patch_probe_.v = std::clamp(v, 0.0, 1.0);
}

void HeadlessHost::set_curve_t(double t) {
  if (!std::isnan(t)) curve_t_ = std::clamp(t, 0.0, 1.0);
}

void HeadlessHost::camera(const CameraRequest& request) {
  std::string line = "camera";
  if (request.reset) line += " reset";
  if (request.fit) line += " fit";
  if (request.yaw_degrees) line += " yaw=" + number(*request.yaw_degrees);
  if (request.pitch_degrees) line += " pitch=" + number(*request.pitch_degrees);
  if (request.distance) line += " distance=" + number(*request.distance);
  if (request.target) line += " target=" + point_text(*request.target);
  calls_.push_back(line);
  cameras_.push_back(request);
}

void HeadlessHost::view(const ViewRequest& request) {
  std::string line = "view";
  const std::pair<const char*, const std::optional<bool>*> parts[] = {
      {"halfedges", &request.halfedges}, {"wireframe", &request.wireframe}, {"vertices", &request.vertices},
      {"labels", &request.labels},       {"curve", &request.curve},         {"tangent", &request.tangent}};
  for (const auto& [name, value] : parts) {
    if (*value) line += std::string(" ") + name + (**value ? "=on" : "=off");
  }
  calls_.push_back(line);
}

std::shared_ptr<HalfedgeMesh> HeadlessHost::current_mesh() const {
  return screen_mesh_ ? std::make_shared<HalfedgeMesh>(*screen_mesh_) : nullptr;
}

}  // namespace meshedit
