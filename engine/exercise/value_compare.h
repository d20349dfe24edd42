// Comparing what a student's function returned with what the reference returned, for the exercises on points or a
// patch (scripted_exercise.h): numbers, points and lists of them, to any depth, within a tolerance. compare() puts
// these messages after the definition's diagnoses.
//
//   compare_values(mine, reference, 1e-9, 20).differences
//     {"point 3 of 5 differs: yours (1, 2, 0), the reference's (1.5, 2, 0)"}
//     {"yours returned 4 points, the reference 3"}        a list of another length (its common items compared too)
//     {"yours returned nil, the reference a list of 3 points"}
//     {"list 2 of 3: yours has 2 numbers, the reference's 3"}   deeper down, named by where it is
//
// Invariants:
// - Two numbers agree when |a - b| <= tolerance, two points when their distance is; NaN agrees with nothing. A list of
//   2 or 3 numbers and a point are compared as points ({1, 2} is (1, 2, 0)); lists item by item, to the shorter's end.
// - `identical` is bit for bit (the same kinds, lengths and doubles); `worst` the largest difference of numbers and
//   points that agreed.
// - At most max_messages are kept; `total` counts them all.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "exercise/exercise_value.h"

namespace meshedit {

struct ValueComparison {
  bool equal = true;
  bool identical = true;
  double worst = 0.0;
  std::vector<std::string> differences;
  size_t total = 0;
};

ValueComparison compare_values(const ExerciseValue& mine, const ExerciseValue& reference, double tolerance,
                               size_t max_messages);

}  // namespace meshedit
