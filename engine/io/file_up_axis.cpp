// A file's up axis (see file_up_axis.h).
#include "io/file_up_axis.h"

#include <algorithm>

#include "io/file_access.h"

namespace meshedit {
namespace {

std::optional<UpAxis> table_up_axis(std::string_view extension) {
  for (const FormatUpAxis& entry : kFormatUpAxes) {
    if (entry.extension == extension) return entry.up_axis;
  }
  return std::nullopt;
}

}  // namespace

std::optional<UpAxis> format_up_axis(const std::filesystem::path& path) {
  return table_up_axis(lowercase_extension(path));
}

FileUpAxis collada_up_axis(const DaeAsset& asset) {
  if (std::find(kMistaggedExporters.begin(), kMistaggedExporters.end(), asset.authoring_tool) !=
      kMistaggedExporters.end()) {
    return {UpAxis::Z, UpAxisSource::CourseExporter};
  }
  if (asset.up_axis_tagged) return {asset.up_axis, UpAxisSource::FileTag};
  return {table_up_axis(".dae").value_or(UpAxis::Y), UpAxisSource::Format};
}

}  // namespace meshedit
