-- Scripted answers for lessons/3_halfedge_walks.lua: each question answered wrong (with the words its feedback
-- must contain), then right. The cube's f5 has f5.halfedge = h15, h15.next = h16, h15.next.next = h17 and
-- h15.twin = h14 (in f4); v5.halfedge = h7, h7.next = h8, h7.twin.next = h35. v5 is in 4 triangles. In the
-- boundary step, a vertex and an interior edge are selected first (the condition must stay false), then a
-- boundary edge.
return {
  ["Around a face"] = { {click = "h14", feedback = "h.twin"}, {click = "h17", feedback = "h.next.next"},
                        {click = "f5", feedback = "not a halfedge"}, {click = "h16"}, {click = "f5"} },
  ["Why half-edges at all"] = { {answer = 4, feedback = "which 4"}, {answer = 12} },
  ["Around a vertex"] = { {click = "h8", feedback = "h.next"}, {click = "h16", feedback = "steps round the walk"},
                          {click = "h35"}, {selection = "h0"}, {key = "T"}, {key = "N"} },
  ["Along a boundary"] = { {selection = "v1"}, {selection = "e1"}, {selection = "e0"} },
  ["Area-weighted normals"] = { {choose = "Straight up, as the blue one", feedback = "same area"},
                                {choose = "Leaning left, towards the small faces", feedback = "counts for less"},
                                {choose = "Leaning right, towards the big faces"} },
  ["Flat or smooth"] = { {key = "Q"} },
  ["Your turn"] = { {your_turn = "right"} },
}
