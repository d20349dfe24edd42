// Pictures of the failing neighbourhood in the grader's feedback (see failure_pictures.h).
#include "app/failure_pictures.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <memory>
#include <optional>
#include <set>
#include <vector>

#include <glm/geometric.hpp>

#include "core/base64.h"
#include "core/normals.h"
#include "exercise/exercise_registry.h"
#include "exercise/exercises.h"
#include "grade/failing_case.h"
#include "io/file_access.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_context.h"
#include "render/render_target.h"
#include "render/shader_library.h"

namespace meshedit {
namespace {

constexpr int kPanelWidth = 320, kPanelHeight = 240, kGap = 4;
constexpr int kRings = 2;
// An element whose outside is within about 70 degrees of the three-quarter view is drawn from that view; the others
// from their outside.
constexpr double kFacesTheView = 0.35;

// The vertices of the element: a vertex, an edge's or a halfedge's two ends, a face's corners.
std::set<uint32_t> corners_of(const HalfedgeMesh& mesh, ElementRef element) {
  std::set<uint32_t> corners;
  if (!element.valid()) return corners;
  switch (element.kind) {
    case ElementKind::Vertex: corners.insert(element.index); break;
    case ElementKind::Edge:
    case ElementKind::Halfedge: {
      const HalfedgeId h =
          element.kind == ElementKind::Edge ? mesh.halfedge(EdgeId(element.index)) : HalfedgeId(element.index);
      corners.insert(mesh.vertex(h).index);
      corners.insert(mesh.vertex(mesh.twin(h)).index);
      break;
    }
    case ElementKind::Face:
    case ElementKind::Boundary:
      mesh.for_each_face_halfedge(element.face_id(), [&](HalfedgeId h) { corners.insert(mesh.vertex(h).index); });
      break;
  }
  return corners;
}

// The box around the element's corners and `kRings` rings of vertices around them in the (valid) input mesh; the
// whole mesh without an element.
BoundingBox neighbourhood(const HalfedgeMesh& mesh, ElementRef element) {
  BoundingBox box;
  std::set<uint32_t> near = corners_of(mesh, element);
  if (near.empty()) {
    for (const VertexId v : mesh.vertices()) box.add(mesh.position(v));
    return box;
  }
  for (int ring = 0; ring < kRings; ++ring) {
    std::set<uint32_t> next = near;
    for (uint32_t v : near) {
      mesh.for_each_outgoing(VertexId(v), [&](HalfedgeId h) { next.insert(mesh.vertex(mesh.twin(h)).index); });
    }
    near = std::move(next);
  }
  for (uint32_t v : near) box.add(mesh.position(VertexId(v)));
  return box;
}

// The element's outside: the sum of the unit normals of the faces beside it (an edge's or a halfedge's two faces,
// a face itself), or a vertex's area-weighted normal, in the input. Zero when it has none.
glm::dvec3 outside_of(const HalfedgeMesh& mesh, ElementRef element) {
  glm::dvec3 outside(0.0);
  const auto add_face = [&](HalfedgeId h) {
    if (!mesh.is_boundary(h)) outside += face_normal(mesh, mesh.face(h));
  };
  switch (element.kind) {
    case ElementKind::Vertex: return vertex_normal(mesh, VertexId(element.index));
    case ElementKind::Edge:
    case ElementKind::Halfedge: {
      const HalfedgeId h =
          element.kind == ElementKind::Edge ? mesh.halfedge(EdgeId(element.index)) : HalfedgeId(element.index);
      add_face(h);
      add_face(mesh.twin(h));
      return outside;
    }
    case ElementKind::Face:
    case ElementKind::Boundary: break;
  }
  return element.kind == ElementKind::Face ? face_normal(mesh, element.face_id()) : outside;
}

// Where the camera looks from (towards the box's centre; zero for the three-quarter view): the three-quarter view
// when the element faces it, else from the element's outside, so that an element on the far side of the
// three-quarter view (e0 of the cube) is in sight, an edge's two faces seen at the same slant.
glm::dvec3 view_direction(const HalfedgeMesh& mesh, ElementRef element) {
  if (!element.valid()) return glm::dvec3(0.0);
  OrbitCamera three_quarter;
  three_quarter.set_up_axis(UpAxis::Z);
  const glm::dvec3 back = glm::normalize(three_quarter.eye() - three_quarter.target());
  const glm::dvec3 outside = outside_of(mesh, element);
  const double length = glm::length(outside);
  if (!(length > 0.0) || !std::isfinite(length)) return glm::dvec3(0.0);
  if (glm::dot(outside / length, back) >= kFacesTheView) return glm::dvec3(0.0);
  return outside;
}

// The input as expect.exercise read it: a scripted exercise takes its element as it is, a built-in one its vertex or
// edge.
ExerciseInput input_of(Exercise exercise, std::shared_ptr<const HalfedgeMesh> mesh, ElementRef element) {
  if (!element.valid()) return ExerciseInput::whole_mesh(std::move(mesh));
  if (exercise.definition()) return ExerciseInput::element_of(std::move(mesh), element);
  if (element.kind == ElementKind::Vertex) return ExerciseInput::vertex(std::move(mesh), VertexId(element.index));
  return ExerciseInput::edge(std::move(mesh), EdgeId(element.index));
}

ElementRef alive_or_none(const HalfedgeMesh& mesh, ElementRef element) {
  return element.valid() && mesh.alive(element) ? element : ElementRef{};
}

// Draws the three panels of a case into one image (three panels and two gaps); draw() returns what the caption must
// add.
class PictureMaker {
 public:
  PictureMaker() : target_(kPanelWidth, kPanelHeight, 4), renderer_(shaders_) { options_.wireframe = true; }

  std::string draw(const FailingCase& failing, std::vector<uint8_t>& image) {
    const std::optional<Exercise> exercise = find_exercise(failing.exercise);
    auto input_mesh = std::make_shared<HalfedgeMesh>(case_mesh(failing));
    const ElementRef element = case_element(*input_mesh, failing);
    const BoundingBox box = neighbourhood(*input_mesh, element);
    direction_ = view_direction(*input_mesh, element);
    std::string caption;
    image.assign(size_t(width()) * kPanelHeight * 4, 0);
    panel(0, *input_mesh, box, element);
    std::optional<HalfedgeMesh> reference;
    if (exercise) {
      const ExerciseOutcome outcome = run_reference(*exercise, input_of(*exercise, input_mesh, element));
      if (outcome.mesh) reference = *outcome.mesh;
    }
    if (reference) panel(1, *reference, box, alive_or_none(*reference, element));
    else caption += " The reference's result could not be drawn.";
    if (const std::optional<HalfedgeMesh> mine = case_mine(failing))
      panel(2, *mine, box, alive_or_none(*mine, element));
    else caption += " Your function left no mesh to draw.";
    compose_blank_panels(image);
    return caption;
  }

  static int width() { return 3 * kPanelWidth + 2 * kGap; }

 private:
  void panel(int index, const HalfedgeMesh& mesh, const BoundingBox& box, ElementRef selected) {
    renderer_.update(mesh);
    OrbitCamera camera;
    camera.set_up_axis(UpAxis::Z);
    camera.fit_looking_from(box.empty() ? renderer_.bounds() : box, direction_);
    target_.clear(renderer_.style().background);
    Highlights highlights;
    highlights.selected = selected;
    renderer_.draw(camera, target_.viewport(), options_, highlights);
    drawn_[index] = target_.read_rgba();
  }

  // Copies each drawn panel into its place; an undrawn panel and the gaps keep the background.
  void compose_blank_panels(std::vector<uint8_t>& image) {
    const glm::vec4 bg = renderer_.style().background;
    for (size_t p = 0; p < image.size(); p += 4) {
      image[p] = static_cast<uint8_t>(bg.r * 255.0f);
      image[p + 1] = static_cast<uint8_t>(bg.g * 255.0f);
      image[p + 2] = static_cast<uint8_t>(bg.b * 255.0f);
      image[p + 3] = 255;
    }
    for (int index = 0; index < 3; ++index) {
      if (drawn_[index].empty()) continue;
      const int x0 = index * (kPanelWidth + kGap);
      for (int y = 0; y < kPanelHeight; ++y) {
        std::copy_n(drawn_[index].begin() + ptrdiff_t(y) * kPanelWidth * 4, kPanelWidth * 4,
                    image.begin() + (ptrdiff_t(y) * width() + x0) * 4);
      }
      drawn_[index].clear();
    }
  }

  ShaderLibrary shaders_;
  RenderTarget target_;
  MeshRenderer renderer_;
  ViewOptions options_;
  glm::dvec3 direction_{0.0};  // where this case's three panels are seen from (view_direction)
  std::vector<uint8_t> drawn_[3];
};

std::string file_name(const std::string& number) {
  std::string name = "test-";
  for (char c : number) name += std::isalnum(static_cast<unsigned char>(c)) || c == '.' ? c : '_';
  return name + ".png";
}

}  // namespace

std::string add_failure_pictures(GradeReport& report, const std::filesystem::path& folder) {
  const bool any = std::any_of(report.tests.begin(), report.tests.end(),
                               [](const TestResult& t) { return !t.passed && t.failing_case; });
  if (!any) return "";
  std::unique_ptr<OffscreenContext> context;
  std::unique_ptr<PictureMaker> maker;
  try {
    context = std::make_unique<OffscreenContext>();
    maker = std::make_unique<PictureMaker>();
  } catch (const std::exception& e) {
    return std::string("no pictures of the failed tests: ") + e.what();
  }
  std::string problems;
  for (TestResult& test : report.tests) {
    if (test.passed || !test.failing_case) continue;
    try {
      std::vector<uint8_t> image;
      const std::string caption = maker->draw(*test.failing_case, image);
      const std::filesystem::path path = folder / "pictures" / file_name(test.number);
      std::filesystem::create_directories(path.parent_path());
      write_png(path, PictureMaker::width(), kPanelHeight, image);
      test.output_markdown += "\n\n![test " + test.number +
                              ": the input, the reference's result and yours](data:image/png;base64," +
                              base64(read_file(path)) + ")\n\n*Left to right: the input (" + test.failing_case->input +
                              ", highlighted), the reference's result, yours." + caption + "*\n";
    } catch (const std::exception& e) {
      problems += (problems.empty() ? "no picture of test " : "; test ") + test.number + ": " + e.what();
    }
  }
  return problems;
}

}  // namespace meshedit
