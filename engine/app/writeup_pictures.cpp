// The write-up's pictures, drawn by the window's renderers (see writeup_pictures.h).
#include "app/writeup_pictures.h"

#include <cmath>
#include <exception>
#include <memory>

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "document/curve_view_state.h"
#include "render/camera.h"
#include "render/gl_api.h"
#include "render/image_file.h"
#include "render/mesh_renderer.h"
#include "render/overlay_renderer.h"
#include "render/render_target.h"
#include "render/shader_library.h"
#include "ui/curve_editor.h"
#include "ui/fonts.h"
#include "ui/theme.h"

namespace meshedit {
namespace {

constexpr int kSamples = 4;
constexpr float kFontPixels = 15.0f;
constexpr double kFromAbove = 89.0;  // degrees of pitch: a flat mesh is seen from straight above
// Scroll steps nearer than the window's fit, a picture having no panels to spare: a flat mesh seen from above fills it
// at 2; a solid seen at an angle keeps the fit, which shows every corner of its box (the cube of figure 6.1 whole).
constexpr double kCloserFlat = 2.0, kCloserSolid = 0.0;

// An ImGui context of its own, with the window's fonts and theme and the OpenGL backend, for the curve pictures; the
// caller's context is current again when it goes.
class CurveCanvas {
 public:
  CurveCanvas() : previous_(ImGui::GetCurrentContext()), context_(ImGui::CreateContext()) {
    ImGui::SetCurrentContext(context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    io.DisplaySize = ImVec2(kWriteupPictureWidth, kWriteupPictureHeight);
    io.DeltaTime = 1.0f / 60.0f;
    apply_theme(ImGui::GetStyle(), Theme::Dark);
    load_fonts(kFontPixels, 1.0f);
    ImGui_ImplOpenGL3_Init(gl::kGlslVersionLine);
  }
  ~CurveCanvas() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(previous_);
  }
  CurveCanvas(const CurveCanvas&) = delete;
  CurveCanvas& operator=(const CurveCanvas&) = delete;

  std::vector<uint8_t> draw(const CurvePicture& picture, const RenderTarget& target) {
    ImGui::SetCurrentContext(context_);
    CurveEditorState state = make_curve_editor(picture.curve);
    state.t = picture.t;
    state.levels_shown = picture.level;
    state.show_curve = picture.show_curve;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    draw_curve_picture(ImGui::GetBackgroundDrawList(), state, ImVec2(0, 0),
                       ImVec2(kWriteupPictureWidth, kWriteupPictureHeight), &picture.yours, picture.file);
    ImGui::Render();
    target.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    return target.read_rgba();
  }

 private:
  ImGuiContext* previous_;
  ImGuiContext* context_;
};

class PictureDrawer {
 public:
  explicit PictureDrawer(const WriteupCamera& camera)
      : camera_(camera),
        target_(kWriteupPictureWidth, kWriteupPictureHeight, kSamples),
        meshes_(shaders_),
        overlays_(shaders_) {}

  // The pictures of one figure; "" or why one was not drawn.
  std::string draw(WriteupFigure& figure) {
    BoundingBox box;
    for (const WriteupPicture& picture : figure.pictures) {
      const auto* mesh = std::get_if<MeshPicture>(&picture.content);
      if (mesh == nullptr || !mesh->mesh) continue;
      for (const VertexId v : mesh->mesh->vertices()) {
        const glm::dvec3& p = mesh->mesh->position(v);
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) box.add(p);  // a student's NaN is not
      }
    }
    std::string problem;
    for (WriteupPicture& picture : figure.pictures) {
      try {
        if (const auto* curve = std::get_if<CurvePicture>(&picture.content)) {
          if (!canvas_) canvas_ = std::make_unique<CurveCanvas>();
          picture.png = png_bytes(kWriteupPictureWidth, kWriteupPictureHeight, canvas_->draw(*curve, target_));
        } else if (const auto& mesh = std::get<MeshPicture>(picture.content); mesh.mesh) {
          picture.png = png_bytes(kWriteupPictureWidth, kWriteupPictureHeight, draw_mesh(mesh, box));
        }
      } catch (const std::exception& e) {
        if (problem.empty()) problem = "figure " + figure.number + " (" + picture.label + "): " + e.what();
      }
    }
    return problem;
  }

 private:
  std::vector<uint8_t> draw_mesh(const MeshPicture& picture, BoundingBox box) {
    if (picture.normals.empty()) {
      meshes_.invalidate();  // another figure's given normals must not stay
      meshes_.update(*picture.mesh);
    } else {
      meshes_.update_with_normals(*picture.mesh, picture.normals);
    }
    if (box.empty()) box = meshes_.bounds();
    const bool flat = box.max.z - box.min.z <= 1e-12 * box.diagonal();
    OrbitCamera aim;  // only for the direction the angles look from
    aim.set_up_axis(UpAxis::Z);
    aim.set_angles(flat ? 0.0 : camera_.yaw, flat ? kFromAbove : camera_.pitch);
    OrbitCamera camera;
    camera.set_up_axis(UpAxis::Z);
    camera.fit_looking_from(box, aim.eye() - aim.target());
    camera.zoom((flat ? kCloserFlat : kCloserSolid) + camera_.zoom);
    ViewOptions options;
    options.smooth_shading = picture.smooth;
    options.wireframe = picture.wireframe;
    Highlights highlights;
    highlights.changed = picture.marked;
    target_.clear(meshes_.style().background);
    meshes_.draw(camera, target_.viewport(), options, highlights);
    if (!picture.net_lines.empty()) {
      Overlay net;
      const glm::vec4 colour(ui_palette().probed_net, 1.0f);  // hidden where the surface is in front, as in the view
      for (const auto& line : picture.net_lines) net.lines.push_back({line, colour, 1.5f, false});
      overlays_.draw(camera, target_.viewport(), net);
    }
    return target_.read_rgba();
  }

  WriteupCamera camera_;
  ShaderLibrary shaders_;
  RenderTarget target_;
  MeshRenderer meshes_;
  OverlayRenderer overlays_;
  std::unique_ptr<CurveCanvas> canvas_;
};

}  // namespace

std::string draw_writeup_pictures(Writeup& writeup) {
  std::string problem;
  try {
    PictureDrawer drawer(writeup.camera);
    for (WriteupPart& part : writeup.parts) {
      for (WriteupFigure& figure : part.figures) {
        const std::string said = drawer.draw(figure);
        if (problem.empty()) problem = said;
      }
    }
  } catch (const std::exception& e) {  // no shaders, no framebuffer: no picture at all, said once
    problem = std::string("the pictures could not be drawn: ") + e.what();
  }
  return problem;
}

}  // namespace meshedit
