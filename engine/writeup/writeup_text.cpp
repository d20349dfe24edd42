// A write-up and its request as CBOR (see writeup_text.h).
#include "writeup/writeup_text.h"

#include <fstream>
#include <memory>
#include <new>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "exercise/cbor_values.h"
#include "grade/submission.h"
#include "writeup/writeup_settings.h"

namespace meshedit {
namespace {

using nlohmann::json;

constexpr const char* kRequestFormat = "meshedit-writeup-request-1";
constexpr const char* kWriteupFormat = "meshedit-writeup-1";

using cbor::element_from;
using cbor::element_json;
using cbor::mesh_from;
using cbor::mesh_json;
using cbor::point_from;
using cbor::point_json;
using cbor::points_from;
using cbor::points_json;

json levels_json(const std::vector<std::vector<glm::dvec3>>& levels) {
  json j = json::array();
  for (const auto& level : levels) j.push_back(points_json(level));
  return j;
}
std::vector<std::vector<glm::dvec3>> levels_from(const json& j) {
  std::vector<std::vector<glm::dvec3>> levels;
  for (const json& level : j) levels.push_back(points_from(level));
  return levels;
}

json mesh_picture_json(const MeshPicture& picture) {
  json marked = json::array();
  for (const ElementRef e : picture.marked) marked.push_back(element_json(e));
  json normals = json::array();
  for (const glm::vec3& n : picture.normals) normals.push_back(json::array({n.x, n.y, n.z}));
  return {{"mesh", mesh_json(picture.mesh.get())},
          {"marked", std::move(marked)},
          {"smooth", picture.smooth},
          {"wireframe", picture.wireframe},
          {"normals", std::move(normals)},
          {"net_lines", levels_json(picture.net_lines)}};
}

MeshPicture mesh_picture_from(const json& j) {
  MeshPicture picture;
  picture.mesh = mesh_from(j.at("mesh"), "a figure");
  for (const json& e : j.at("marked")) picture.marked.push_back(element_from(e));
  picture.smooth = j.at("smooth").get<bool>();
  picture.wireframe = j.at("wireframe").get<bool>();
  for (const json& n : j.at("normals"))
    picture.normals.emplace_back(n.at(0).get<float>(), n.at(1).get<float>(), n.at(2).get<float>());
  picture.net_lines = levels_from(j.at("net_lines"));
  return picture;
}

json curve_picture_json(const CurvePicture& picture) {
  json points = json::array();
  for (const glm::dvec2& p : picture.curve.control_points) points.push_back(json::array({p.x, p.y}));
  const CurveMineLevels& yours = picture.yours;
  return {{"points", std::move(points)},
          {"t", picture.t},
          {"level", picture.level},
          {"show_curve", picture.show_curve},
          {"file", picture.file},
          {"yours",
           {{"levels", levels_json(yours.levels)},
            {"failed_level", yours.failed_level},
            {"load_failed", yours.load_failed},
            {"error", yours.error},
            {"wrong_point", yours.wrong_point},
            {"mine_point", point_json(yours.mine_point)},
            {"reference_point", point_json(yours.reference_point)},
            {"reference_level", points_json(yours.reference_level)},
            {"details", yours.details},
            {"message", yours.message}}}};
}

CurvePicture curve_picture_from(const json& j) {
  CurvePicture picture;
  for (const json& p : j.at("points"))
    picture.curve.control_points.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
  picture.t = j.at("t").get<double>();
  picture.level = j.at("level").get<int>();
  picture.show_curve = j.at("show_curve").get<bool>();
  picture.file = j.at("file").get<std::string>();
  const json& y = j.at("yours");
  CurveMineLevels& yours = picture.yours;
  yours.levels = levels_from(y.at("levels"));
  yours.failed_level = y.at("failed_level").get<int>();
  yours.load_failed = y.at("load_failed").get<bool>();
  yours.error = y.at("error").get<std::string>();
  yours.wrong_point = y.at("wrong_point").get<int>();
  yours.mine_point = point_from(y.at("mine_point"));
  yours.reference_point = point_from(y.at("reference_point"));
  yours.reference_level = points_from(y.at("reference_level"));
  yours.details = y.at("details").get<std::vector<std::string>>();
  yours.message = y.at("message").get<std::string>();
  return picture;
}

json figure_json(const WriteupFigure& figure) {
  json pictures = json::array();
  for (const WriteupPicture& picture : figure.pictures) {
    json p = {{"label", picture.label}, {"png", picture.png}};
    if (const auto* mesh = std::get_if<MeshPicture>(&picture.content)) p["mesh"] = mesh_picture_json(*mesh);
    else p["curve"] = curve_picture_json(std::get<CurvePicture>(picture.content));
    pictures.push_back(std::move(p));
  }
  return {{"number", figure.number},         {"caption", figure.caption}, {"made_by", figure.made_by},
          {"pictures", std::move(pictures)}, {"numbers", figure.numbers}, {"table", figure.table},
          {"problem", figure.problem}};
}

WriteupFigure figure_from(const json& j) {
  WriteupFigure figure;
  figure.number = j.at("number").get<std::string>();
  figure.caption = j.at("caption").get<std::string>();
  figure.made_by = j.at("made_by").get<std::string>();
  for (const json& p : j.at("pictures")) {
    WriteupPicture picture;
    picture.label = p.at("label").get<std::string>();
    picture.png = p.at("png").get<std::string>();
    if (p.contains("mesh")) picture.content = mesh_picture_from(p.at("mesh"));
    else picture.content = curve_picture_from(p.at("curve"));
    figure.pictures.push_back(std::move(picture));
  }
  figure.numbers = j.at("numbers").get<std::vector<std::string>>();
  figure.table = j.at("table").get<std::vector<std::vector<std::string>>>();
  figure.problem = j.at("problem").get<std::string>();
  return figure;
}

}  // namespace

std::vector<uint8_t> encode_writeup_request(const std::filesystem::path& folder,
                                            const std::vector<WriteupRequestFile>& files) {
  json list = json::array();
  for (const WriteupRequestFile& file : files) list.push_back({{"path", file.path.string()}, {"bytes", file.bytes}});
  return json::to_cbor(json{{"format", kRequestFormat}, {"folder", folder.string()}, {"files", std::move(list)}});
}

Writeup make_requested_writeup(std::span<const uint8_t> request) {
  const auto [folder, files] = cbor::read_cbor_text(request, kRequestFormat, "write-up request", [](const json& j) {
    std::vector<WriteupRequestFile> read;
    for (const json& file : j.at("files")) {
      read.push_back({file.at("path").get<std::string>(), file.at("bytes").get<std::string>()});
    }
    return std::make_pair(std::filesystem::path(j.at("folder").get<std::string>()), std::move(read));
  });
  for (const WriteupRequestFile& file : files) {
    std::error_code ec;
    std::filesystem::create_directories(file.path.parent_path(), ec);
    std::ofstream out(file.path, std::ios::binary | std::ios::trunc);
    out << file.bytes;
    if (!out.flush()) throw std::runtime_error("the worker could not write " + file.path.string());
  }
  return make_writeup(Submission::read(folder), read_writeup_settings(folder));
}

std::vector<uint8_t> encode_writeup(const Writeup& writeup) {
  json parts = json::array();
  for (const WriteupPart& part : writeup.parts) {
    json figures = json::array();
    for (const WriteupFigure& figure : part.figures) figures.push_back(figure_json(figure));
    parts.push_back({{"heading", part.heading},
                     {"task", part.task},
                     {"figures", std::move(figures)},
                     {"questions", part.questions}});
  }
  const json j = {{"format", kWriteupFormat},
                  {"folder", writeup.folder.string()},
                  {"camera", {writeup.camera.yaw, writeup.camera.pitch, writeup.camera.zoom}},
                  {"parts", std::move(parts)},
                  {"notes", writeup.notes}};
  return json::to_cbor(j);
}

Writeup decode_writeup(std::span<const uint8_t> bytes) {
  return cbor::read_cbor_text(bytes, kWriteupFormat, "write-up", [](const json& j) {
    Writeup writeup;
    writeup.folder = j.at("folder").get<std::string>();
    const json& camera = j.at("camera");
    writeup.camera = {camera.at(0).get<double>(), camera.at(1).get<double>(), camera.at(2).get<double>()};
    for (const json& p : j.at("parts")) {
      WriteupPart part;
      part.heading = p.at("heading").get<std::string>();
      part.task = p.at("task").get<std::string>();
      for (const json& figure : p.at("figures")) part.figures.push_back(figure_from(figure));
      part.questions = p.at("questions").get<std::vector<std::string>>();
      writeup.parts.push_back(std::move(part));
    }
    writeup.notes = j.at("notes").get<std::vector<std::string>>();
    return writeup;
  });
}

}  // namespace meshedit
