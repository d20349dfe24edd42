// render_bench: frame times of the mesh view on generated tori, offscreen through EGL (llvmpipe on a
// machine without a GPU). Not a test: it prints numbers and asserts nothing.
//
//   render_bench [--faces N[,N...]] [--frames F] [--size WxH] [--samples S]
//   defaults: 10000,100000,1000000 faces, 10 frames, 1280x800, 4x multisampling
//
// For each mesh: the first update() (CPU geometry + upload), the time of a clear alone, the frame time
// (clear + draw + glFinish; minimum and median of F frames) with the wireframe on and off, update() on
// an unchanged version (what every idle frame pays: no per-element work, the upload counter does not
// move) against update() after one vertex moved (a full rebuild), and pick(): the first one redraws the
// id buffer, the next ones at the same camera only read a few pixels.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "core/mesh_build.h"
#include "core/primitives.h"
#include "render/camera.h"
#include "render/mesh_renderer.h"
#include "render/offscreen_context.h"
#include "render/render_error.h"
#include "render/render_target.h"
#include "render/shader_library.h"

namespace {

using Clock = std::chrono::steady_clock;
using namespace meshedit;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

const char* arg(int argc, char** argv, const char* name, const char* fallback) {
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], name) == 0) return argv[i + 1];
  }
  return fallback;
}

std::vector<uint32_t> parse_counts(const std::string& text) {
  std::vector<uint32_t> counts;
  size_t start = 0;
  while (start < text.size()) {
    const size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const long value = std::strtol(item.c_str(), nullptr, 10);
    if (value >= 8) counts.push_back(uint32_t(std::min(value, 20000000L)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return counts;
}

struct Timing {
  double min = 0.0, median = 0.0;
};

Timing time_frames(int frames, const std::function<void()>& frame) {
  std::vector<double> times;
  for (int i = 0; i < frames; ++i) {
    const auto start = Clock::now();
    frame();
    times.push_back(ms_since(start));
  }
  std::sort(times.begin(), times.end());
  return {times.front(), times[times.size() / 2]};
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<uint32_t> counts = parse_counts(arg(argc, argv, "--faces", "10000,100000,1000000"));
  const int frames = std::clamp(std::atoi(arg(argc, argv, "--frames", "10")), 1, 1000);
  const int samples = std::clamp(std::atoi(arg(argc, argv, "--samples", "4")), 0, 16);
  Viewport viewport{1280, 800};
  std::sscanf(arg(argc, argv, "--size", "1280x800"), "%dx%d", &viewport.width, &viewport.height);

  try {
    OffscreenContext context;
    const ShaderLibrary shaders;
    RenderTarget target(viewport.width, viewport.height, samples);
    std::printf("%s; %dx%d, %dx multisampling, %d frames per figure\n", context.description().c_str(),
                viewport.width, viewport.height, target.samples(), frames);

    for (uint32_t faces : counts) {
      HalfedgeMesh mesh = build_halfedge_mesh(make_torus_with_faces(faces));
      MeshRenderer renderer(shaders);
      std::printf("\ntorus: %zu triangles, %zu vertices\n", mesh.num_faces(), mesh.num_vertices());

      auto start = Clock::now();
      renderer.update(mesh);
      std::printf("  %-44s %10.2f ms  (%.1f MB of GPU buffers)\n", "first update (geometry + upload)", ms_since(start),
                  double(renderer.stats().gpu_bytes) / 1e6);
      OrbitCamera camera;
      camera.fit(renderer.bounds());

      const Timing clear = time_frames(frames, [&] {
        target.clear(renderer.style().background);
        glFinish();
      });
      std::printf("  %-44s %10.2f ms / %.2f ms\n", "clear only (min / median)", clear.min, clear.median);
      for (bool wireframe : {false, true}) {
        ViewOptions options;
        options.wireframe = wireframe;
        const Timing t = time_frames(frames, [&] {
          renderer.update(mesh);
          target.clear(renderer.style().background);
          renderer.draw(camera, viewport, options, {});
          glFinish();
        });
        char label[64];
        std::snprintf(label, sizeof label, "frame, %s (min / median)", wireframe ? "faces + wireframe" : "faces only");
        std::printf("  %-44s %10.2f ms / %.2f ms\n", label, t.min, t.median);
      }

      const uint64_t uploads = renderer.stats().uploads;
      const Timing idle = time_frames(1000, [&] { renderer.update(mesh); });
      std::printf("  %-44s %10.5f ms  (uploads %llu -> %llu)\n", "update(), unchanged version", idle.median,
                  static_cast<unsigned long long>(uploads),
                  static_cast<unsigned long long>(renderer.stats().uploads));
      const Timing changed = time_frames(std::min(frames, 5), [&] {
        mesh.set_position(VertexId(0), mesh.position(VertexId(0)) * 1.0);  // any write bumps the version
        renderer.update(mesh);
      });
      std::printf("  %-44s %10.2f ms\n", "update(), changed version (full rebuild)", changed.median);

      renderer.draw(camera, viewport, {}, {});
      renderer.pick(camera, viewport, 0, 0);  // the first id pass also compiles its shaders (llvmpipe JITs)
      camera.orbit(3, 0);
      start = Clock::now();
      // Where vertex 0 (on the outer equator) is seen: the pick has something to find.
      const ScreenPoint v0 = camera.project(mesh.position(VertexId(0)), viewport);
      const int x = int(v0.pixel.x), y = int(v0.pixel.y);
      const ElementRef first = renderer.pick(camera, viewport, x, y);
      const double first_ms = ms_since(start);
      const Timing again =
          time_frames(100, [&] { renderer.pick(camera, viewport, x + 3, y); });
      std::printf("  %-44s %10.2f ms  (%s)\n", "pick, id buffer redrawn", first_ms, format_id(first).c_str());
      std::printf("  %-44s %10.3f ms\n", "pick, same camera (reads 9x9 pixels)", again.median);
    }
  } catch (const RenderError& e) {
    std::fprintf(stderr, "render_bench: %s\n", e.what());
    return 1;
  }
  return 0;
}
