// index.html and writeup.md of a write-up (see writeup_page.h).
#include "writeup/writeup_page.h"

#include <system_error>

#include "core/base64.h"
#include "core/file_bytes.h"
#include "core/text_escapes.h"

namespace meshedit {
namespace {

constexpr const char* kStyle =
    "body{font-family:'DejaVu Sans',sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;color:#222}"
    "h2{border-bottom:2px solid #ccc;padding-bottom:.2em;margin-top:2em}"
    ".made{color:#555;font-style:italic}.row{display:flex;flex-wrap:wrap;gap:12px}"
    "figure{margin:0}figure img{width:480px;max-width:100%;border:1px solid "
    "#ccc}figcaption{text-align:center;color:#444}"
    ".problem{background:#fdecea;border-left:4px solid #c0392b;padding:.5em 1em}"
    ".gap{width:480px;height:360px;max-width:100%;border:2px dashed "
    "#c0392b;display:flex;align-items:center;justify-content:center;"
    "text-align:center;color:#c0392b}"
    ".yours{border:2px dashed #888;padding:1em;min-height:6em;color:#888}"
    "table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 8px;font-family:monospace}";

// Markdown text that shows as written: its punctuation escaped, its lines joined.
std::string md_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (std::string_view("\\`*_{}[]<>()#+-!|~").find(c) != std::string_view::npos) out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out;
}

std::string image_name(const WriteupFigure& figure, size_t index) {
  return "figures/" + figure.number + "-" + static_cast<char>('a' + index % 26) + ".png";
}

void add_figure(const WriteupFigure& figure, WriteupFiles& files) {
  std::string& html = files.html;
  std::string& md = files.markdown;
  html += "<h3>Figure " + figure.number + ": " + html_escaped(figure.caption) + "</h3>\n";
  md += "### Figure " + figure.number + ": " + md_escaped(figure.caption) + "\n\n";
  html += "<p class=\"made\">Made by " + html_escaped(figure.made_by) + "</p>\n";
  md += "*Made by " + md_escaped(figure.made_by) + "*\n\n";
  if (!figure.problem.empty()) {
    html += "<p class=\"problem\"><b>Problem:</b> " + html_escaped(figure.problem) + "</p>\n";
    md += "> **Problem:** " + md_escaped(figure.problem) + "\n\n";
  }
  html += "<div class=\"row\">\n";
  for (size_t i = 0; i < figure.pictures.size(); ++i) {
    const WriteupPicture& picture = figure.pictures[i];
    if (picture.png.empty()) {
      html += "<figure><div class=\"gap\">this picture could not be drawn</div><figcaption>" +
              html_escaped(picture.label) + "</figcaption></figure>\n";
      md += "*(" + md_escaped(picture.label) + ": this picture could not be drawn)*\n\n";
      continue;
    }
    const std::string name = image_name(figure, i);
    html += "<figure><img alt=\"" + html_escaped(picture.label) + "\" src=\"data:image/png;base64," +
            base64(picture.png) + "\"><figcaption>" + html_escaped(picture.label) + "</figcaption></figure>\n";
    md += "![" + md_escaped(picture.label) + "](" + name + ")\n";
    files.images.emplace_back(name, picture.png);
  }
  html += "</div>\n";
  md += "\n";
  if (!figure.numbers.empty()) {
    html += "<ul>\n";
    for (const std::string& line : figure.numbers) {
      html += "<li>" + html_escaped(line) + "</li>\n";
      md += "- " + md_escaped(line) + "\n";
    }
    html += "</ul>\n";
    md += "\n";
  }
  if (figure.table.size() > 1) {
    html += "<table>\n";
    for (size_t r = 0; r < figure.table.size(); ++r) {
      html += "<tr>";
      md += "|";
      for (const std::string& cell : figure.table[r]) {
        html += (r == 0 ? "<th>" : "<td>") + html_escaped(cell) + (r == 0 ? "</th>" : "</td>");
        md += " " + md_escaped(cell) + " |";
      }
      html += "</tr>\n";
      md += "\n";
      if (r == 0) {
        md += "|";
        for (size_t c = 0; c < figure.table[r].size(); ++c) md += " --- |";
        md += "\n";
      }
    }
    html += "</table>\n";
    md += "\n";
  }
}

void add_part(const WriteupPart& part, WriteupFiles& files) {
  files.html += "<h2>" + html_escaped(part.heading) + "</h2>\n<p>" + html_escaped(part.task) + "</p>\n";
  files.markdown += "## " + md_escaped(part.heading) + "\n\n" + md_escaped(part.task) + "\n\n";
  for (const WriteupFigure& figure : part.figures) add_figure(figure, files);
  files.html += "<h3>Your explanation</h3>\n<ul>\n";
  files.markdown += "### Your explanation\n\n";
  for (const std::string& question : part.questions) {
    files.html += "<li>" + html_escaped(question) + "</li>\n";
    files.markdown += "- " + md_escaped(question) + "\n";
  }
  files.html += "</ul>\n<div class=\"yours\">(yours to write: replace this box with your explanation)</div>\n";
  files.markdown += "\n<!-- yours to write: your explanation goes here -->\n\n";
}

constexpr const char* kMadeBy =
    "Every figure below was made by your own functions, run by MeshEdit as the grader runs "
    "them.";

// The folder's own name ("hw2" for /home/alice/hw2/ or for "." there): the page names no place on the student's disk.
std::string folder_name(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::path whole = std::filesystem::absolute(folder, error).lexically_normal();
  if (error) whole = folder.lexically_normal();
  if (whole.filename().empty()) whole = whole.parent_path();
  return whole.filename().string();
}

}  // namespace

WriteupFiles writeup_files(const Writeup& writeup) {
  WriteupFiles files;
  const std::string title = "Write-up: " + folder_name(writeup.folder);
  files.html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escaped(title) +
               "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" + html_escaped(title) + "</h1>\n<p>" +
               kMadeBy + "</p>\n";
  files.markdown = "# " + md_escaped(title) + "\n\n" + kMadeBy + "\n\n";
  if (!writeup.notes.empty()) {
    files.html += "<ul class=\"notes\">\n";
    for (const std::string& note : writeup.notes) {
      files.html += "<li>" + html_escaped(note) + "</li>\n";
      files.markdown += "- " + md_escaped(note) + "\n";
    }
    files.html += "</ul>\n";
    files.markdown += "\n";
  }
  for (const WriteupPart& part : writeup.parts) add_part(part, files);
  files.html += "</body>\n</html>\n";
  return files;
}

std::string write_writeup_files(const WriteupFiles& files, const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder / "figures", error);
  if (error) return (folder / "figures").string() + ": cannot be made: " + error.message();
  std::string problems;
  auto write = [&](const std::filesystem::path& path, const std::string& bytes) {
    const std::string failed = write_file_bytes(path, bytes);
    if (!failed.empty() && problems.empty()) problems = path.string() + ": " + failed;
  };
  write(folder / "index.html", files.html);
  write(folder / "writeup.md", files.markdown);
  for (const auto& [name, bytes] : files.images) write(folder / name, bytes);
  return problems;
}

}  // namespace meshedit
