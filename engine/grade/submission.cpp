// Reading a submission folder (see submission.h for the rules).
#include "grade/submission.h"

#include <algorithm>
#include <map>
#include <system_error>

#include "core/file_bytes.h"
#include "script/lua_source.h"

namespace meshedit {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxDepth = 4;

bool skipped_folder(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.empty() || name[0] == '.' || name == "__MACOSX";
}

struct Found {
  fs::path path;
  std::string relative;
  int depth;
};

void collect(const fs::path& root, const fs::path& folder, int depth, std::map<std::string, std::vector<Found>>& found,
             std::vector<std::string>& notes) {
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  if (ec) {
    if (depth == 0) throw GradeError("cannot list the submission folder " + folder.string() + ": " + ec.message());
    notes.push_back("could not read the folder " + fs::relative(folder, root, ec).string());
    return;
  }
  std::vector<fs::directory_entry> entries;
  for (; it != fs::directory_iterator(); it.increment(ec)) {
    if (ec) break;
    entries.push_back(*it);
  }
  std::sort(entries.begin(), entries.end(),
            [](const fs::directory_entry& a, const fs::directory_entry& b) { return a.path() < b.path(); });
  for (const auto& entry : entries) {
    const fs::file_status status = entry.symlink_status(ec);
    if (ec) continue;
    const fs::path& p = entry.path();
    if (fs::is_symlink(status)) {
      if (p.extension() == ".lua") notes.push_back(p.filename().string() + " is a symbolic link: skipped");
      continue;
    }
    if (fs::is_directory(status)) {
      if (depth + 1 < kMaxDepth && !skipped_folder(p)) collect(root, p, depth + 1, found, notes);
      continue;
    }
    if (fs::is_regular_file(status) && p.extension() == ".lua") {
      found[p.filename().string()].push_back({p, fs::relative(p, root, ec).generic_string(), depth});
    }
  }
}

}  // namespace

Submission Submission::read(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) throw GradeError("the submission folder " + folder.string() + " does not exist");
  std::map<std::string, std::vector<Found>> found;
  Submission s;
  s.folder_ = folder;
  collect(folder, folder, 0, found, s.notes_);
  for (auto& [name, candidates] : found) {
    if (s.files_.size() >= kMaxFiles) {
      s.notes_.push_back("more than " + std::to_string(kMaxFiles) + " .lua files: the rest were skipped");
      break;
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Found& a, const Found& b) { return a.depth < b.depth; });
    const Found& chosen = candidates.front();
    if (chosen.depth > 0) s.notes_.push_back(name + " was found in " + chosen.relative);
    if (candidates.size() > 1 && candidates[1].depth == chosen.depth) {
      s.notes_.push_back("several files are called " + name + "; used " + chosen.relative);
    }
    const auto size = fs::file_size(chosen.path, ec);
    if (ec || size > kMaxSubmittedFileBytes) {
      s.notes_.push_back(name + " is larger than " + std::to_string(kMaxSubmittedFileBytes >> 10) + " KB: skipped");
      continue;
    }
    FileBytes file = read_file_bytes(chosen.path, kMaxSubmittedFileBytes);
    if (!file.ok()) {
      s.notes_.push_back(name + " could not be read");
      continue;
    }
    s.files_.push_back({name, chosen.relative, lua_source_text(std::move(file.bytes))});
  }
  return s;
}

Submission Submission::from_files(std::vector<SubmissionFile> files) {
  Submission s;
  std::sort(files.begin(), files.end(),
            [](const SubmissionFile& a, const SubmissionFile& b) { return a.name < b.name; });
  s.files_ = std::move(files);
  return s;
}

const SubmissionFile* Submission::find(const std::string& name) const {
  for (const auto& f : files_) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

}  // namespace meshedit
