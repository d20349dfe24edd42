// LessonMarks: what a lesson lays over the view (its highlight, label and arrow calls), kept by the window's lesson
// host until the next step clears them and drawn by the view (ViewRoom). Ids that are not in the shown mesh are kept
// but draw nothing.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/ids.h"

namespace meshedit {

struct LessonArrow {
  glm::dvec3 from, to;
  glm::vec3 colour;
};

struct LessonMarks {
  std::vector<std::pair<ElementRef, glm::vec3>> highlights;
  std::vector<std::pair<ElementRef, std::string>> labels;
  std::vector<LessonArrow> arrows;
};

}  // namespace meshedit
