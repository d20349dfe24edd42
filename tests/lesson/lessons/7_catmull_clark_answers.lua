-- Scripted answers for lessons/7_catmull_clark.lua: each question answered wrong once or more, with the words its
-- feedback must contain (the likely mistakes: the cube's centre or the corners' sum for the face point, the
-- midpoint or the faces' corners as what an edge point averages and the midpoint for the edge point, a corner that
-- stays or moves out, P kept or weighed wrongly for the vertex point, Loop's counts, the interior rule on
-- the boundary), then right. The quad cube's edge from v0 (-0.5, -0.5, -0.5) to v1 (0.5, -0.5, -0.5) is e3.
return {
  ["Face points"] = { {answer = {0, 0, 0}, feedback = "centre of the whole cube"},
    {answer = {0, 0, 2}, feedback = "divide it by 4"}, {answer = "0, 0, 0.5"} },
  ["Edge points"] = { {choose = "The two ends: the midpoint", feedback = "stay exactly as sharp"},
    {choose = "Every corner of the two faces", feedback = "already sum up"},
    {choose = "The two ends and the two face points"},
    {answer = {0, -0.5, -0.5}, feedback = "forgets the two face points"},
    {answer = {0, -0.25, -0.25}, feedback = "face points alone"},
    {answer = "0, -1/3, -1/3", feedback = "weighs 1/4"}, {answer = {0, -0.375, -0.375}} },
  ["Vertex points"] = { {choose = "It stays where it is", feedback = "stay sharp"},
    {choose = "Away from the centre", feedback = "cannot move it out"},
    {choose = "Towards the centre, along the diagonal"},
    {answer = {-0.5, -0.5, -0.5}, feedback = "approximates"},
    {answer = "-4/9, -4/9, -4/9", feedback = "weighs P once"},
    {answer = "-1/3, -1/3, -1/3", feedback = "plain mean"},
    {answer = "-1/6, -1/6, -1/6", feedback = "neighbouring vertices"},
    {answer = "-5/18, -5/18, -5/18"} },
  ["Counting after one level"] = { {choose = "20 = V + E", feedback = "Loop's count"},
    {choose = "24 = 4F", feedback = "share their corners"}, {choose = "26 = V + E + F"},
    {answer = 6, feedback = "not kept"}, {answer = 48, feedback = "Loop's count"}, {answer = 24},
    {subdivide = "catmull-clark"} },
  ["The app's phases"] = {
    {choose = "At its edge point (0, -0.375, -0.375)", feedback = "only changes the connectivity"},
    {choose = "On v0, until phase 3 moves it", feedback = "never on top of a corner"},
    {choose = "At the edge's midpoint (0, -0.5, -0.5)"},
    {subdivide_phase = "catmull-clark"}, {subdivide_phase = "catmull-clark"}, {subdivide_phase = "catmull-clark"} },
  ["Triangles become quads"] = { {choose = "16 triangles", feedback = "Loop subdivision"},
    {choose = "4 triangles and 12 quads", feedback = "No old face"}, {choose = "12 quads"} },
  ["Boundary rules"] = { {answer = "0.5, 1/6", feedback = "interior rule"}, {answer = {0.5, 0}},
    {choose = "Itself and all its neighbours", feedback = "pull the border inwards"},
    {choose = "Itself and its two neighbours along the boundary"},
    {answer = {0, 0}, feedback = "moves too"}, {answer = {0.25, 0.25}, feedback = "1/8"},
    {answer = "0.125, 0.125"} },
  ["Your own Catmull-Clark"] = {
    {choose = "Move the old vertices first, then subdivide", feedback = "read the mesh before anything moves"},
    {choose = "Linear subdivision first, then move every vertex"}, {your_turn = "right"} },
  ["Linear subdivision beside it"] = { {choose = "4/9 of the way to the centre", feedback = "vertex point"},
    {choose = "At a face centroid", feedback = "new vertices"}, {choose = "Where it was"} },
}
