// What the student chose for their write-up: `writeup.json` in their folder, read by `meshedit writeup` and by File >
// Write-up. Every key may be left out; what is missing is the default that shows each effect well.
//
//   {
//     "curve": "my_curve.bzc",          part 1's curve (a path in the folder; default: a six-point curve)
//     "t": 0.5, "other_t": 0.3,         part 1's t, and the t of the moved curve
//     "camera": {"yaw": 30, "pitch": 20, "zoom": 0},   the 3D figures' view (degrees; zoom in scroll steps)
//     "mesh": "cow.obj",                parts 4 and 5's mesh (a path in the folder or anywhere; default: a 4x3 grid)
//     "flip_edges": [12, 30, 48],       part 4's edges of that mesh to flip, in order (ids as the window shows: e12)
//     "split_edges": [12, 30],          part 5's edges to split
//     "levels": 3                       part 6's levels of upsample (1 to 4)
//   }
//
// Invariants:
// - Reading never throws: a file that does not parse, a key of the wrong type or a value out of range is named in
//   `problems` ("writeup.json:3: ...", or the key) and its default is used.
// - Unknown keys are named too (a typo must not silently do nothing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace meshedit {

struct WriteupCamera {
  double yaw = 30.0;    // degrees, the window's three-quarter view
  double pitch = 20.0;  // degrees
  double zoom = 0.0;    // scroll steps from the fitted distance (positive: closer)
};

struct WriteupSettings {
  std::optional<std::filesystem::path> curve;  // part 1's .bzc, resolved against the folder
  double t = 0.5;
  double other_t = 0.3;
  WriteupCamera camera;
  std::optional<std::filesystem::path> mesh;  // parts 4 and 5's mesh file, resolved against the folder
  std::vector<uint32_t> flip_edges;           // empty: the defaults (part 4 picks three diagonals of the grid)
  std::vector<uint32_t> split_edges;          // empty: the defaults
  int levels = 3;
  std::vector<std::string> problems;  // what was not taken from the file, and why
};

inline constexpr const char* kWriteupSettingsFile = "writeup.json";
inline constexpr size_t kMaxWriteupEdges = 16;  // of flip_edges and of split_edges

// The settings of the student folder `folder` (its writeup.json; the defaults when there is none).
WriteupSettings read_writeup_settings(const std::filesystem::path& folder);
// The same from the text of a writeup.json (`name` in the problems).
WriteupSettings parse_writeup_settings(const std::string& text, const std::string& name,
                                       const std::filesystem::path& folder);
// The text of a writeup.json holding `settings` (what File > Use this view in the write-up saves: the
// window's camera, its mesh file and the edges flipped and split in it).
std::string format_writeup_settings(const WriteupSettings& settings, const std::filesystem::path& folder);

}  // namespace meshedit
