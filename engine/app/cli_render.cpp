// `meshedit render FILE [--shading flat|phong] [--wireframe] [--vertices] [--halfedges] [--subdivide N]
//  [--size WxH] [--up y|z] [--resolution N] -o out.png`: a picture of a mesh or patch file without a
// display, through an EGL surfaceless context (no X server needed), drawn by the same MeshRenderer as
// the window. The camera is the window's fitted three-quarter view, Z up as in the course viewer (see
// render/camera.h) unless --up y says otherwise.
#include <charconv>
#include <filesystem>

#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/loop_subdivision.h"
#include "core/mesh_error.h"
#include "render/camera.h"
#include "render/image_file.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_context.h"
#include "render/render_target.h"
#include "render/shader_library.h"

namespace meshedit {
namespace {

constexpr int kMaxSide = 8192;
constexpr int kSamples = 4;
// Subdividing multiplies faces by 4 per level; past this a picture is no longer worth the memory.
constexpr double kMaxRenderedFaces = 16e6;

Viewport parse_size(const std::string& text) {
  const size_t x = text.find('x');
  Viewport size{0, 0};
  if (x != std::string::npos) {
    const char* begin = text.data();
    const char* end = begin + text.size();
    const auto w = std::from_chars(begin, begin + x, size.width);
    const auto h = std::from_chars(begin + x + 1, end, size.height);
    const bool whole = w.ec == std::errc() && w.ptr == begin + x && h.ec == std::errc() && h.ptr == end;
    if (whole && size.width >= 1 && size.height >= 1 && size.width <= kMaxSide && size.height <= kMaxSide) {
      return size;
    }
  }
  throw UsageError("--size must be WIDTHxHEIGHT with each side from 1 to " + std::to_string(kMaxSide) + ", not '" +
                   text + "'");
}

}  // namespace

int run_render(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const auto output = take_option(args, "--output", "-o");
  const std::string shading = take_option(args, "--shading").value_or("flat");
  const auto subdivide_text = take_option(args, "--subdivide");
  const Viewport size = parse_size(take_option(args, "--size").value_or("800x600"));
  const int resolution = take_resolution_option(args);
  const auto up_text = take_option(args, "--up");
  ViewOptions options;
  options.wireframe = take_flag(args, "--wireframe");
  options.show_vertices = take_flag(args, "--vertices");
  options.show_halfedges = take_flag(args, "--halfedges");
  reject_unknown_options(args);
  if (args.size() != 1) throw UsageError("render takes one input file");
  if (!output) throw UsageError("render needs -o OUT.png");
  if (shading != "flat" && shading != "phong") {
    throw UsageError("--shading must be 'flat' or 'phong', not '" + shading + "'");
  }
  if (up_text && *up_text != "y" && *up_text != "z") {
    throw UsageError("--up must be 'y' or 'z', not '" + *up_text + "'");
  }
  options.smooth_shading = shading == "phong";
  const int levels = subdivide_text ? parse_count(*subdivide_text, "--subdivide", 8) : 0;
  const std::filesystem::path input = args[0];
  const bool z_up = !up_text || *up_text == "z";

  LoadedMesh loaded = load_halfedge_mesh(input, resolution);
  HalfedgeMesh& mesh = loaded.mesh;
  double faces = double(mesh.num_faces());
  for (int i = 0; i < levels; ++i) faces *= 4;
  if (faces > kMaxRenderedFaces) {
    throw UsageError(std::to_string(levels) + " levels would make " + std::to_string(static_cast<long long>(faces)) +
                     " faces; use fewer levels");
  }
  for (int level = 1; level <= levels; ++level) {
    const Check done = loop_subdivide(mesh);
    if (!done) {
      throw MeshError(input.string() + ": cannot subdivide (level " + std::to_string(level) + "): " + done.reason);
    }
  }

  OffscreenContext context;
  const ShaderLibrary shaders;
  RenderTarget target(size.width, size.height, kSamples);
  MeshRenderer renderer(shaders);
  renderer.update(mesh);
  OrbitCamera camera;
  camera.set_up_axis(z_up ? UpAxis::Z : UpAxis::Y);
  camera.fit(renderer.bounds());

  target.clear(renderer.style().background);
  renderer.draw(camera, target.viewport(), options, Highlights{});
  write_png(*output, size.width, size.height, target.read_rgba());

  out << "wrote " << output->c_str() << ": " << size.width << "x" << size.height << ", " << renderer.stats().triangles
      << " triangles, " << shading << " shading" << (options.wireframe ? ", wireframe" : "") << " ("
      << OffscreenContext::description() << ")\n";
  if (renderer.stats().skipped_faces > 0) {
    out << "note: " << renderer.stats().skipped_faces << " faces could not be walked and were not drawn\n";
  }
  return 0;
}

}  // namespace meshedit
