// WriteupRoom's run in a page (see writeup_room.h): the student's folder, and the files its writeup.json names, go as
// a request to the page's Web Worker for student code (document/page_worker_job.h, the worker's meshedit_writeup),
// which runs the student's functions there and sends the write-up back as bytes (writeup/writeup_text.h); between two
// frames the page draws its pictures, writes the files into FOLDER/writeup/ and the browser downloads index.html.
#include <exception>
#include <system_error>

#include "app/exercise_room.h"
#include "app/window_host.h"
#include "app/writeup_pictures.h"
#include "app/writeup_room.h"
#include "core/file_bytes.h"
#include "core/translation.h"
#include "document/page_worker_job.h"
#include "writeup/writeup_page.h"
#include "writeup/writeup_settings.h"
#include "writeup/writeup_text.h"

namespace meshedit {
namespace {

constexpr double kWorkerSeconds = 600.0;           // the whole write-up: each call of the student's has its own limit
constexpr size_t kMaxFileBytes = size_t(8) << 20;  // a student file, or a mesh writeup.json names
constexpr size_t kMaxFiles = 256;

// The files the worker needs: the folder's (but the write-up's own), and the curve and mesh writeup.json names.
std::vector<WriteupRequestFile> request_files(const std::filesystem::path& folder, const std::filesystem::path& out) {
  std::vector<WriteupRequestFile> files;
  auto add = [&](const std::filesystem::path& path) {
    if (files.size() >= kMaxFiles) return;
    const FileBytes read = read_file_bytes(path, kMaxFileBytes);
    if (read.ok()) files.push_back({path, read.bytes});
  };
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(folder, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->path() == out) {
      it.disable_recursion_pending();
    } else if (it->is_regular_file(ec)) {
      add(it->path());
    }
  }
  const WriteupSettings settings = read_writeup_settings(folder);
  for (const auto& named : {settings.curve, settings.mesh}) {
    if (named && std::filesystem::is_regular_file(*named, ec)) add(*named);
  }
  return files;
}

}  // namespace

struct WriteupRoom::Host {
  PageWorkerJob job;
  std::optional<Writeup> made;  // sent back by the worker, its pictures not drawn yet
};

WriteupRoom::WriteupRoom(DocumentRoom& document, ExerciseRoom& exercises, ViewRoom& view)
    : document_(document), exercises_(exercises), view_(view), host_(std::make_unique<Host>()) {}

WriteupRoom::~WriteupRoom() = default;  // the job ends a worker still on it

bool WriteupRoom::running() const { return host_->job.running() || host_->made.has_value(); }

std::string WriteupRoom::start_run(const std::filesystem::path& folder) {
  stop_run();
  const std::vector<uint8_t> request = encode_writeup_request(folder, request_files(folder, output_folder()));
  const std::string why = host_->job.start("meshedit_writeup", request, kWorkerSeconds);
  if (why.empty()) return "";
  return tr_format("the page could not start a worker for your code (a Web Worker): {why}", {{"why", why}});
}

void WriteupRoom::stop_run() {
  host_->job.stop();
  host_->made.reset();
}

std::optional<WriteupRoom::RunEnd> WriteupRoom::poll_run() {
  if (!host_->job.running()) return std::nullopt;
  RunEnd end;
  switch (host_->job.poll()) {
    case PageWorkerJob::End::None: return std::nullopt;
    case PageWorkerJob::End::Answered:
      host_->made = decode_writeup(host_->job.take_answer());  // drawn by finish_made, after this frame
      host_->job.release(false);  // its memory grew with the write-up's meshes: a new worker for the next job
      return std::nullopt;
    case PageWorkerJob::End::Overdue: end.problem = tr("the page's worker ran past 600 s and was stopped"); break;
    case PageWorkerJob::End::NeverStarted: end.problem = tr("the page's worker did not start within 120 s"); break;
    case PageWorkerJob::End::Died:
      end.problem = tr_format("the page's worker stopped: {why}", {{"why", host_->job.died_words()}});
      break;
    case PageWorkerJob::End::Stopped: return std::nullopt;
  }
  return end;
}

void WriteupRoom::finish_made() {
  if (!host_->made) return;
  Writeup writeup = std::move(*host_->made);
  host_->made.reset();
  RunEnd end;
  try {
    if (writeup.parts.empty()) {
      end.problem = writeup.notes.empty() ? tr("the worker sent an empty write-up") : writeup.notes.front();
      announce(end);
      return;
    }
    const std::string not_drawn = draw_writeup_pictures(writeup);
    const std::filesystem::path page = output_folder() / "index.html";
    if (const std::string why = write_writeup_files(writeup_files(writeup), output_folder()); !why.empty()) {
      end.problem = why;
      announce(end);
      return;
    }
    end.made = true;
    for (const WriteupPart& part : writeup.parts) {
      for (const WriteupFigure& figure : part.figures) {
        if (!figure.problem.empty()) end.failed.push_back(figure.number);
      }
    }
    if (!not_drawn.empty()) end.failed.push_back(tr("a picture not drawn"));
    end.where = host_hand_over(page);  // "downloaded as index.html"
  } catch (const std::exception& e) {  // the browser refused the download, memory ran out drawing
    end = RunEnd{};
    end.problem = e.what();
  }
  announce(end);
}

}  // namespace meshedit
