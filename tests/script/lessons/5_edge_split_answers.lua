-- Scripted answers for lessons/5_edge_split.lua: split the diamond's middle edge e0, then the grid's first
-- bottom-row boundary edge, as S would after selecting each.
return {
  ["Split the middle edge"] = { {selection = "e0"}, {split = "e0"} },
  ["Split a boundary edge"] = { {selection = "e0"}, {split = "e0"} },
}
