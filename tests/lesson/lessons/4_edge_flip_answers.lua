-- Scripted answers for lessons/4_edge_flip.lua (run with --student tests/exercise/solutions, whose flip_edge is
-- right: the last step expects your_turn = "right", on the diamond, its boundary edge and the big grid): each
-- question answered wrong (with the words its feedback must contain), then right. The builder's ids for the
-- diagram's names: h0 = h0, h1 = h3, h2 = h1, h3 = h2, h4 = h4, h5 = h5, h6 = h6, h7 = h9, h8 = h8, h9 = h7;
-- a, b, c, d = v0..v3; e = e0.
return {
  ["The diamond"] = { {click = "h3", feedback = "h0.twin"}, {click = "h2", feedback = "before h0"},
                      {click = "h4", feedback = "other face"}, {click = "e0", feedback = "not a halfedge"},
                      {click = "h1"} },
  ["The course's letters"] = { {click = "h0", feedback = "not an edge"}, {click = "e1", feedback = "handout calls"},
                               {click = "e0"},
                               {choose = "f0", feedback = "handout's (d, a, b): its (a, b, d), not (a, d, c)"},
                               {choose = "f1"} },
  ["Predict the flip"] = { {choose = "h2", feedback = "before the flip"}, {choose = "h1", feedback = "twin"},
                           {choose = "h4", feedback = "must start at c"}, {choose = "h3"},
                           {click = "h1", feedback = "other way"}, {click = "h4"} },
  ["The pointers that are easy to forget"] = { {click = "h1", feedback = "classic bug"},
                                               {click = "h3", feedback = "in f1"}, {click = "h2"},
                                               {choose = "h0", feedback = "leaves d"},
                                               {choose = "h3", feedback = "must leave the vertex"}, {choose = "h4"} },
  ["One flip in a big mesh"] = { {answer = 2, feedback = "but so do the next pointers"},
                                 {answer = 33600,
                                  feedback = "a rebuild of the face list rewrites every face's corners"},
                                 {answer = 10} },
  ["Flip it yourself"] = { {selection = "e0"}, {flip = "e0"} },
  ["Before and after, pointer by pointer"] = { {answer = 2, feedback = "traded faces"}, {answer = 4},
                                               {your_turn = "right"}, {your_turn = "right"}, {your_turn = "right"} },
}
