// `meshedit convert IN OUT` and
// `meshedit subdivide IN -n LEVELS [--scheme loop|catmull-clark|linear] [--weights course|loop] -o OUT`
// (the scheme defaults to loop; --weights is Loop's and refused with another scheme).
#include <algorithm>
#include <chrono>
#include <optional>
#include <stdexcept>

#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/parallel_for.h"
#include "core/subdivision_phases.h"
#include "io/file_error.h"
#include "io/polygon_checks.h"

namespace meshedit {
namespace {

// Subdividing multiplies faces by 4 per level; past this the output would not fit in memory sensibly.
constexpr double kMaxOutputFaces = 64e6;

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int run_convert(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const int resolution = take_resolution_option(args);
  reject_unknown_options(args);
  if (args.size() != 2) throw UsageError("convert takes an input and an output file");
  const PolygonMesh polygons = polygons_of(load_file(args[0]), args[0], resolution);
  try {
    require_writable(polygons, args[0]);  // a face the readers keep for repair (fewer than 3 corners), named by IN
  } catch (const FileError& e) {
    throw std::runtime_error(e.what() + std::string("; meshedit repair ") + args[0] +
                             " -o OUT drops it, with a report");
  }
  save_mesh(args[1], polygons);
  out << "wrote " << args[1] << ": " << polygons.num_vertices() << " vertices, " << polygons.num_faces() << " faces\n";
  return 0;
}

int run_subdivide(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const int resolution = take_resolution_option(args);
  const auto levels_text = take_option(args, "--levels", "-n");
  const auto output = take_option(args, "--output", "-o");
  const std::optional<std::string> weights_option = take_option(args, "--weights");
  const std::string weights_name = weights_option.value_or("course");
  const std::string scheme_text = take_option(args, "--scheme").value_or("loop");
  reject_unknown_options(args);
  if (args.size() != 1) throw UsageError("subdivide takes one input file");
  if (!levels_text) throw UsageError("subdivide needs -n LEVELS");
  if (!output) throw UsageError("subdivide needs -o OUT");
  if (weights_name != "course" && weights_name != "loop") {
    throw UsageError("--weights must be 'course' or 'loop', not '" + weights_name + "'");
  }
  const std::optional<SubdivisionScheme> scheme = scheme_named(scheme_text);
  if (!scheme) throw UsageError("--scheme must be " + std::string(scheme_names()) + ", not '" + scheme_text + "'");
  if (weights_option && scheme != SubdivisionScheme::Loop) throw UsageError("--weights is for --scheme loop only");
  const LoopWeights weights = weights_name == "loop" ? LoopWeights::Loop : LoopWeights::Course;
  const int levels = parse_count(*levels_text, "-n", 10);

  LoadedMesh loaded = load_halfedge_mesh(args[0], resolution);
  HalfedgeMesh& mesh = loaded.mesh;
  // Every scheme makes at most 4 faces of each face of up to 4 sides; an n-gon makes n, the first level only.
  double faces = 0;
  for (FaceId f : mesh.faces()) faces += std::max<uint32_t>(4, mesh.degree(f));
  for (int i = 1; i < levels; ++i) faces *= 4;
  if (faces > kMaxOutputFaces) {
    throw UsageError(std::to_string(levels) + " levels would make " + std::to_string(static_cast<long long>(faces)) +
                     " faces; use fewer levels");
  }
  out << args[0] << ": " << mesh.num_vertices() << " vertices, " << mesh.num_faces() << " faces\n";
  for (int level = 1; level <= levels; ++level) {
    const auto start = std::chrono::steady_clock::now();
    const Check done = subdivide(mesh, *scheme, weights, 1, hardware_threads());
    if (!done) throw MeshError(args[0] + ": cannot subdivide: " + done.reason);
    out << "level " << level << ": " << mesh.num_vertices() << " vertices, " << mesh.num_edges() << " edges, "
        << mesh.num_faces() << " faces (" << milliseconds_since(start) << " ms, "
        << (scheme == SubdivisionScheme::Loop ? weights_name + " weights" : scheme_text) << ")\n";
  }
  save_mesh(*output, to_polygon_mesh(mesh));
  out << "wrote " << *output << "\n";
  return 0;
}

}  // namespace meshedit
