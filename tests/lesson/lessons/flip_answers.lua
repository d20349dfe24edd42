-- Answers for the flip lesson written by lesson_headless_test.cpp: select e7, flip it, press F.
return {
  ["Flip it"] = { {selection = "e7"}, {flip = "e7"}, {key = "F"} },
}
