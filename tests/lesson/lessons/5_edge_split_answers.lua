-- Scripted answers for lessons/5_edge_split.lua: each question answered wrong once, with the words its feedback
-- must contain, then right; split the diamond's middle edge e0, then the grid's first bottom-row boundary edge,
-- as S would after selecting each. (The builder stores the diamond's h1 as h3 and h2 as h1, as in part 4.)
return {
  ["What a split does"] = { {choose = "4", feedback = "keeps its id"}, {choose = "2", feedback = "halves is new"},
    {choose = "3"} },
  ["Predict the pointers"] = { {click = "h3", feedback = "twin"}, {click = "f0", feedback = "That is a face"},
    {click = "h0"}, {choose = "n0 (a to m)", feedback = "arrives at m"},
    {choose = "n2 (m to c)", feedback = "a new edge"}, {choose = "n1 (m to a)"} },
  ["Split the middle edge"] = { {selection = "e0"}, {split = "e0"} },
  ["Before and after, pointer by pointer"] = { {choose = "next", feedback = "still h2"}, {choose = "vertex"} },
  ["Split a boundary edge"] = { {choose = "2", feedback = "boundary loop, not a triangle"}, {choose = "1"},
    {selection = "e0"}, {split = "e0"} },
  ["Flip and split together"] = { {answer = 6, feedback = "minus sign"}, {answer = 0} },
  ["Your turn"] = { {your_turn = "right"}, {your_turn = "right"} },
}
