-- Scripted answers for lessons/1_de_casteljau.lua (meshedit lesson ... --headless --answers THIS). Each question
-- gets at least one likely mistake first, with the words its feedback must contain (the run fails when the lesson
-- does not name that mistake), then the right answer. Moves of the curve view's t stand for the slider, curve
-- clicks (points of the curve's plane) for the mouse.
return {
  ["Four points, one curve"] = { {choose = "all four", feedback = "pull it without being reached"},
                                 {choose = "the first and the last"}, {key = "C"} },
  ["One step: level 1"] = { {answer = {0.75, 1.5}, feedback = "t and 1 - t swapped"},
                            {answer = "0.5, 1", feedback = "the average"},
                            {answer = {0.25, 0.5}}, {curve_t = 0.25}, {key = "E"} },
  ["Counting levels"] = { {choose = "4", feedback = "off by one"}, {choose = "2", feedback = "one step too many"},
                          {choose = "3"}, {key = "E"} },
  ["Moving t"] = { {curve_click = {2, 1.5}, feedback = "past C(0.25)"},
                   {curve_click = {0.33, 0.54}, feedback = "short of"},
                   {curve_click = {1.5, 1.8}, feedback = "beside the curve"}, {curve_click = {0.9, 1.13}},
                   {curve_t = 0.25}, {answer = {0.5625, 0.875}, feedback = "level-2 point"},
                   {answer = {2, 1}, feedback = "average"}, {answer = {3.09375, 1.125}, feedback = "swapped"},
                   {answer = {0.90625, 1.125}} },
  ["Six points, every level"] = { {answer = 6, feedback = "one step past"}, {answer = 3, feedback = "cubic"},
                                  {answer = 5}, {key = "E"}, {key = "E"}, {key = "E"}, {key = "E"}, {key = "E"} },
  ["Splitting a curve"] = { {choose = "the last point of every level", feedback = "from t to 1"},
                            {choose = "the first point of every level"}, {curve_t = 0.3} },
  ["The weights"] = { {answer = "1/4", feedback = "average"}, {answer = 0.375}, {curve_t = 0.5},
                      {answer = 0.5, feedback = "where they cross"}, {curve_t = 0.33}, {answer = "0.33"} },
  ["The tangent"] = { {answer = {1, 2}, feedback = "n times"}, {answer = {2, 4}, feedback = "degree"},
                      {answer = {3, 6}}, {choose = "in the middle, t = 0.5", feedback = "shortest"},
                      {choose = "the same length everywhere", feedback = "evenly spaced"},
                      {choose = "at the ends, t = 0 and 1"}, {key = "E"} },
  ["The hodograph"] = { {answer = {6, 0}, feedback = "middle control point"},
                       {answer = {4.125, -3}, feedback = "t and 1 - t swapped"}, {answer = {4.125, 3}},
                       {key = "E"} },
  ["Your turn"] = { {your_turn = "right"}, {key = "M"} },
}
