-- Scripted answers for lessons/3_halfedge_walks.lua. In the boundary step, a vertex and an interior edge are
-- selected first (the condition must stay false), then a boundary edge.
return {
  [1] = { {click = "f5"} },
  [2] = { {selection = "h0"}, {key = "T"}, {key = "N"} },
  [3] = { {selection = "v1"}, {selection = "e1"}, {selection = "e0"} },
  [5] = { {key = "Q"} },
}
