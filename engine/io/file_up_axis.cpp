// A file's up axis (see file_up_axis.h).
#include "io/file_up_axis.h"

#include <algorithm>

#include "io/mesh_file.h"

namespace meshedit {

FileUpAxis collada_up_axis(const DaeAsset& asset) {
  if (std::find(kMistaggedExporters.begin(), kMistaggedExporters.end(), asset.authoring_tool) !=
      kMistaggedExporters.end()) {
    return {UpAxis::Z, UpAxisSource::CourseExporter};
  }
  if (asset.up_axis_tagged) return {asset.up_axis, UpAxisSource::FileTag};
  return {format_up_axis("file.dae").value_or(UpAxis::Y), UpAxisSource::Format};
}

}  // namespace meshedit
