// `meshedit repair IN -o OUT`: the file's polygons repaired (core/mesh_repair.h), every change listed with the
// file's own vertex and face numbers, then built as a half-edge mesh before anything is written, so OUT is only
// written when it opens.
#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"

namespace meshedit {

int run_repair(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const int resolution = take_resolution_option(args);
  const auto output = take_option(args, "--output", "-o");
  reject_unknown_options(args);
  if (args.size() != 1) throw UsageError("repair takes one input file");
  if (!output) throw UsageError("repair needs -o OUT");
  const PolygonMesh polygons = polygons_of(load_file(args[0]), args[0], resolution);
  out << args[0] << ": " << polygons.num_vertices() << " vertices, " << polygons.num_faces() << " faces\n";
  const RepairResult repaired = repair_polygons(polygons);
  for (const std::string& change : repaired.report.changes) out << "  " << change << "\n";
  out << repaired.report.summary() << "\n";
  try {
    build_halfedge_mesh(repaired.polygons);
  } catch (const MeshError& e) {
    throw MeshError(args[0] + ": still not a manifold after repair: " + e.what(), e.element());
  }
  save_mesh(*output, repaired.polygons);
  out << "wrote " << *output << ": " << repaired.polygons.num_vertices() << " vertices, "
      << repaired.polygons.num_faces() << " faces\n";
  return 0;
}

}  // namespace meshedit
