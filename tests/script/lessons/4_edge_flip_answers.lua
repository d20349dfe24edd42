-- Scripted answers for lessons/4_edge_flip.lua: select e0 (the diamond's middle edge), then flip it as F would.
return {
  ["Flip it yourself"] = { {selection = "e0"}, {flip = "e0"} },
}
