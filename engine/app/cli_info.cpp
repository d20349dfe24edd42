// `meshedit info FILE [--json]`: what a file holds. Meshes get counts, topology and validation;
// patch files their patch count and the stats of their tessellation; curve files their point count.
// A mesh also gets what `meshedit repair` would change (core/mesh_repair.h), when anything; a mesh that does not
// build prints that on stdout and still fails with the builder's message on stderr.
#include <nlohmann/json.hpp>

#include "app/cli_commands.h"
#include "app/mesh_loading.h"
#include "core/mesh_build.h"
#include "core/mesh_error.h"
#include "core/mesh_repair.h"
#include "core/mesh_stats.h"
#include "core/validate.h"

namespace meshedit {
namespace {

constexpr size_t kProblemsShown = 5;
constexpr size_t kRepairsShown = 20;

nlohmann::json repair_json(const RepairReport& report) {
  nlohmann::json changes = nlohmann::json::array();
  for (size_t i = 0; i < report.changes.size() && i < kRepairsShown; ++i) changes.push_back(report.changes[i]);
  return {{"summary", report.summary()}, {"change_count", report.changes.size()}, {"changes", changes}};
}

void print_repair(const nlohmann::json& r, std::ostream& out) {
  out << "  meshedit repair would: " << r["summary"].get<std::string>() << "\n";
  for (const auto& change : r["changes"]) out << "    " << change.get<std::string>() << "\n";
  const size_t shown = r["changes"].size(), total = r["change_count"].get<size_t>();
  if (total > shown) out << "    ... and " << total - shown << " more\n";
}

nlohmann::json mesh_json(const HalfedgeMesh& mesh, size_t unused_vertices) {
  const MeshStats s = compute_stats(mesh);
  const ValidationReport report = validate(mesh, kProblemsShown);
  nlohmann::json problems = nlohmann::json::array();
  for (const auto& v : report.violations) {
    problems.push_back(
        {{"element", format_id(v.element)}, {"invariant", invariant_name(v.invariant)}, {"message", v.message}});
  }
  return {{"vertices", s.vertices},
          {"edges", s.edges},
          {"faces", s.faces},
          {"halfedges", s.halfedges},
          {"boundary_loops", s.boundary_loops},
          {"components", s.components},
          {"euler_characteristic", s.euler_characteristic},
          {"closed", s.closed()},
          {"genus", s.genus ? nlohmann::json(*s.genus) : nlohmann::json(nullptr)},
          {"triangles_only", s.triangles_only},
          {"unused_vertices", unused_vertices},
          {"valid", report.ok()},
          {"problem_count", report.total},
          {"problems", problems}};
}

// The vertices a glTF or PLY file repeats at one position, joined on reading (io/mesh_file.h).
void print_joined(const nlohmann::json& m, std::ostream& out) {
  if (!m.contains("joined_vertices")) return;
  out << "  joined vertices       " << m["joined_vertices"]
      << " (repeated at one position in the file, for normals, texture coordinates or colours)\n";
}

void print_mesh(const nlohmann::json& m, std::ostream& out, const std::string& indent) {
  auto line = [&](const std::string& label, const std::string& value) {
    out << indent << label << std::string(label.size() < 22 ? 22 - label.size() : 1, ' ') << value << "\n";
  };
  line("vertices", std::to_string(m["vertices"].get<size_t>()) +
                       (m["unused_vertices"].get<size_t>() > 0
                            ? " (+" + std::to_string(m["unused_vertices"].get<size_t>()) + " unused in the file)"
                            : ""));
  line("edges", std::to_string(m["edges"].get<size_t>()));
  line("faces", std::to_string(m["faces"].get<size_t>()) + (m["triangles_only"].get<bool>() ? " (all triangles)" : ""));
  line("halfedges", std::to_string(m["halfedges"].get<size_t>()));
  line("boundary loops", std::to_string(m["boundary_loops"].get<size_t>()));
  line("components", std::to_string(m["components"].get<size_t>()));
  line("Euler characteristic", std::to_string(m["euler_characteristic"].get<long>()) +
                                   (m["closed"].get<bool>() ? " (closed)" : " (with boundary)"));
  if (!m["genus"].is_null()) line("genus", std::to_string(m["genus"].get<long>()));
  if (m["valid"].get<bool>()) {
    line("validation", "valid");
  } else {
    line("validation", std::to_string(m["problem_count"].get<size_t>()) + " problem(s)");
    for (const auto& p : m["problems"]) out << indent << "  " << p["message"].get<std::string>() << "\n";
  }
}

}  // namespace

int run_info(const std::vector<std::string>& arguments, std::ostream& out) {
  std::vector<std::string> args = arguments;
  const bool json = take_flag(args, "--json");
  const int resolution = take_resolution_option(args);
  reject_unknown_options(args);
  if (args.size() != 1) throw UsageError("info takes one file");
  const std::filesystem::path path = args[0];

  const LoadedFile file = load_file(path);
  nlohmann::json result = {{"file", path.string()}};
  switch (file.kind) {
    case FileKind::Curve:
      result["kind"] = "curve";
      result["points"] = file.curve.control_points.size();
      result["degree"] = file.curve.control_points.empty() ? 0 : file.curve.control_points.size() - 1;
      break;
    case FileKind::Patches: {
      result["kind"] = "patches";
      result["patches"] = file.patches.size();
      result["resolution"] = resolution;
      BuildReport report;
      try {
        const HalfedgeMesh mesh = build_halfedge_mesh(polygons_of(file, path, resolution), &report);
        result["tessellation"] = mesh_json(mesh, report.unused_vertices);
      } catch (const MeshError& e) {
        result["tessellation_error"] = e.what();
      }
      break;
    }
    case FileKind::Mesh: {
      result["kind"] = "mesh";
      if (file.joined_vertices > 0) result["joined_vertices"] = file.joined_vertices;
      const RepairReport repair = repair_polygons(file.mesh).report;
      if (!repair.empty()) result["repair"] = repair_json(repair);
      try {
        const LoadedMesh loaded = build_from_file(file.mesh, path);
        result.update(mesh_json(loaded.mesh, loaded.unused_vertices));
      } catch (const MeshError&) {
        if (json) out << result.dump(2) << "\n";
        if (!json && result.contains("repair")) {
          out << path.string() << ": mesh that is not a manifold\n";
          print_joined(result, out);
          print_repair(result["repair"], out);
        }
        throw;
      }
      break;
    }
  }

  if (json) {
    out << result.dump(2) << "\n";
    return 0;
  }
  out << path.string() << ": " << result["kind"].get<std::string>() << "\n";
  if (file.kind == FileKind::Curve) {
    out << "  control points        " << result["points"] << " (degree " << result["degree"] << ")\n";
  } else if (file.kind == FileKind::Patches) {
    out << "  patches               " << result["patches"] << " (4x4 control points each)\n";
    if (result.contains("tessellation")) {
      out << "  tessellated at " << resolution << "x" << resolution << " per patch:\n";
      print_mesh(result["tessellation"], out, "    ");
    } else {
      out << "  tessellation is not a manifold: " << result["tessellation_error"].get<std::string>() << "\n";
    }
  } else {
    print_mesh(result, out, "  ");
    print_joined(result, out);
    if (result.contains("repair")) print_repair(result["repair"], out);
  }
  return 0;
}

}  // namespace meshedit
