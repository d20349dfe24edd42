-- Scripted answers for lessons/2_bezier_patches.lua (meshedit lesson ... --headless --answers THIS). Each question
-- gets at least one likely mistake first, with the words its feedback must contain (the run fails when the lesson
-- does not name that mistake), then the right answer.
return {
  ["From curves to surfaces"] = { {choose = "the four raised middle points", feedback = "stays below them"},
                                  {choose = "the four corners"},
                                  {choose = "10", feedback = "rows and columns swapped"}, {choose = "7"} },
  ["Rows in u"] = { {choose = "4", feedback = "the column"}, {choose = "5"},
                    {answer = "2.25, 1, 1.125", feedback = "u and 1 - u swapped"},
                    {answer = "1.5, 1, 1", feedback = "average"}, {answer = "0.75, 1, 1.125"} },
  ["Then the column in v"] = { {answer = "1.5, 0.75, 0.84375", feedback = "u and v swapped"},
                               {answer = "0.75, 1.5, 0.5625", feedback = "average"},
                               {answer = "0.75, 1.5, 0.84375"} },
  ["The normal at (u, v)"] = { {choose = "Along u, the way the rows run", feedback = "lies in the surface"},
                               {choose = "Straight up"}, {patch_uv = {0.2, 0.6}},
                               {choose = "Toward the top", feedback = "tips back"},
                               {choose = "Away from the top, toward u = 0"} },
  ["The Utah teapot"] = { {choose = "64", feedback = "counts the squares"}, {choose = "81"} },
  ["Where patches meet"] = { {choose = "the first column's four points", feedback = "rows and columns swapped"},
                             {choose = "the first row's four points"},
                             {choose = "Nothing more: a shared edge is smooth", feedback = "3 (P1 - P0)"},
                             {choose = "The points next to the edge, on both sides, in line with it"} },
  ["Your turn"] = { {your_turn = "right"}, {key = "M"} },
}
