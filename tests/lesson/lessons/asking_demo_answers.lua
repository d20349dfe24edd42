-- Answers for asking_demo.lua: each question answered wrong once, with the words its feedback must contain, then
-- right.
return {
  ["Choose"] = { { choose = "h2", feedback = "before the flip" }, { choose = "h6", feedback = "twin" },
                 { choose = "h4" } },
  ["Pick"] = { { click = "f0", feedback = "That is a face" }, { click = "h2", feedback = "before the flip" },
               { click = "h4" } },
  ["Weights"] = { { curve_t = 0.25 }, { answer = "1/8", feedback = "end point" }, { answer = "three eighths" },
                  { answer = 0.375 }, { answer = { 2, 1.25 } }, { answer = "(2, 1.5)" } },
}
