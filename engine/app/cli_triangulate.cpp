// `meshedit triangulate IN -o OUT`: every face of more than three corners split into triangles (core/triangulate.h).
// Works on the file's polygons as they are, so a file the half-edge builder refuses can be triangulated too.
#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/triangulate.h"

namespace meshedit {

int run_triangulate(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const int resolution = take_resolution_option(args);
  const auto output = take_option(args, "--output", "-o");
  reject_unknown_options(args);
  if (args.size() != 1) throw UsageError("triangulate takes one input file");
  if (!output) throw UsageError("triangulate needs -o OUT");
  const PolygonMesh polygons = polygons_of(load_file(args[0]), args[0], resolution);
  TriangulationReport report;
  const PolygonMesh triangles = triangulate(polygons, &report);
  out << args[0] << ": " << polygons.num_vertices() << " vertices, " << polygons.num_faces() << " faces; "
      << report.polygons_split << " polygons split into " << report.triangles_made << " triangles";
  if (report.fan_fallbacks > 0) out << " (" << report.fan_fallbacks << " had no ear and were cut as a fan)";
  out << "\n";
  save_mesh(*output, triangles);
  out << "wrote " << *output << ": " << triangles.num_vertices() << " vertices, " << triangles.num_faces()
      << " faces\n";
  return 0;
}

}  // namespace meshedit
