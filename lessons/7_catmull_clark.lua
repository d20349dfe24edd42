-- Part 7: Catmull-Clark subdivision, beside part 6 (Loop). On a cube of six quads the student predicts a face
-- point, an edge point and where a corner goes by the vertex rule (F + 2R + (n - 3) P) / n, then the counts
-- after one level, what the rule makes of triangles (a tetrahedron), the boundary rules on a grid of quads, how
-- linear subdivision differs (nothing moves), and the student's own level (scripts/exercises/catmull_clark.lua:
-- linear subdivision, then the rules; run by your_turn on the cube). Every step asks before it tells: where the
-- face point goes, which points the edge point averages and which way a corner moves come before each rule; each
-- likely wrong answer is named in its feedback. Every number the lesson prints comes from the core:
-- mesh:catmull_clark() and mesh:subdivision_phases("catmull-clark") on copies (engine/core/catmull_clark.h),
-- positions read back. The student runs the window's Subdivide menu twice: the whole level, and then its three
-- phases one at a time, each checked against the lesson's own phases.
-- CI runs it headless (tests/lesson/lessons_b_test.cpp):
--   meshedit lesson lessons/7_catmull_clark.lua --headless --answers tests/lesson/lessons/7_catmull_clark_answers.lua
-- Invariants: every step builds its meshes afresh (Back runs a step again); the core numbers a level's new
-- vertices after the old ones, one per edge in edge id order, then one per face in face id order, so on a fresh
-- mesh (ids dense) the point of edge e is vertex V + e and the point of face f is vertex V + E + f.

lesson {
  title = { en = "Part 7: Catmull-Clark subdivision", zh = "第 7 部分：Catmull-Clark 细分" },
  summary = {
    en = "Face, edge and vertex points on a cube of quads, the counts after one level, triangles into quads, "
      .. "the boundary rules, and linear subdivision beside it.",
    zh = "四边形立方体上的面点、边点和顶点点，细分一层后的数目，三角形变为四边形，边界规则，以及与之对照的线性细分。",
  },
}

-- The cube's six sides as counter-clockwise quads seen from outside (1-based corners of meshedit.cube()).
local CUBE_QUADS = { { 1, 3, 4, 2 }, { 5, 6, 8, 7 }, { 1, 2, 6, 5 }, { 3, 7, 8, 4 }, { 1, 5, 7, 3 }, { 2, 4, 8, 6 } }

-- The unit cube centred at 0 (meshedit.cube()'s corners, v0 at (-0.5, -0.5, -0.5)) as six quads.
local function quad_cube()
  local corners = meshedit.cube()
  local positions = {}
  for i = 0, 7 do positions[i + 1] = corners:vertex(i).position end
  return meshedit.from_polygons(positions, CUBE_QUADS)
end

-- An n by n grid of unit quads in the z = 0 plane, v0 at (0, 0), row by row.
local function quad_grid(n)
  local positions, quads = {}, {}
  for y = 0, n do
    for x = 0, n do positions[#positions + 1] = { x, y, 0 } end
  end
  for y = 0, n - 1 do
    for x = 0, n - 1 do
      local a = y * (n + 1) + x + 1
      quads[#quads + 1] = { a, a + 1, a + n + 2, a + n + 1 }
    end
  end
  return meshedit.from_polygons(positions, quads)
end

-- One level of the core's Catmull-Clark on a copy.
local function catmull_clark(mesh)
  local copy = mesh:copy()
  assert(copy:catmull_clark())
  return copy
end

-- The core's new points, read back from one level on a copy (ids as the header comment says).
local function face_point(mesh, f)
  return catmull_clark(mesh):vertex(mesh:num_vertices() + mesh:num_edges() + f.id).position
end
local function edge_point(mesh, e) return catmull_clark(mesh):vertex(mesh:num_vertices() + e.id).position end
local function vertex_point(mesh, v) return catmull_clark(mesh):vertex(v.id).position end

-- A number with at most four decimals, trailing zeros dropped ("0.5", "-0.2778", "0"); never "-0".
local function num(x)
  local text = string.format("%.4f", x + 0.0):gsub("0+$", ""):gsub("%.$", "")
  if text == "-0" then return "0" end
  return text
end
local function point(p) return "(" .. num(p.x) .. ", " .. num(p.y) .. ", " .. num(p.z) .. ")" end

-- x as a fraction p/q with the smallest q up to 100, or nil.
local function fraction(x)
  for q = 1, 100 do
    local p = x * q
    if math.abs(p - math.floor(p + 0.5)) < 1e-9 then return string.format("%d/%d", math.floor(p + 0.5), q) end
  end
end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- counts(mesh) in Chinese: "26 个顶点、48 条边、24 个面".
local function counts_zh(mesh)
  return mesh:num_vertices() .. " 个顶点、" .. mesh:num_edges() .. " 条边、" .. mesh:num_faces() .. " 个面"
end

-- How many faces of each number of sides: "24 quads", "12 triangles and 3 quads".
local function face_kinds(mesh)
  local by_sides = {}
  for f in mesh:faces() do by_sides[f:degree()] = (by_sides[f:degree()] or 0) + 1 end
  local names = { [3] = "triangles", [4] = "quads" }
  local parts = {}
  for sides = 3, 12 do
    if by_sides[sides] then parts[#parts + 1] = by_sides[sides] .. " " .. (names[sides] or (sides .. "-gons")) end
  end
  return table.concat(parts, " and ")
end

-- face_kinds(mesh) in Chinese: "24 个四边形", "12 个三角形和 3 个四边形".
local function face_kinds_zh(mesh)
  local by_sides = {}
  for f in mesh:faces() do by_sides[f:degree()] = (by_sides[f:degree()] or 0) + 1 end
  local names = { [3] = "三角形", [4] = "四边形" }
  local parts = {}
  for sides = 3, 12 do
    if by_sides[sides] then
      parts[#parts + 1] = by_sides[sides] .. (names[sides] and (" 个" .. names[sides]) or (" 个 " .. sides .. " 边形"))
    end
  end
  return table.concat(parts, "和 ")
end

-- The mean of a list of points.
local function mean(points)
  local sum = meshedit.vec3(0, 0, 0)
  for _, p in ipairs(points) do sum = sum + p end
  return sum / #points
end

local function centroid(f)
  local corners = {}
  for v in f:vertices() do corners[#corners + 1] = v.position end
  return mean(corners)
end

-- The edge joining vertices a and b.
local function edge_between(mesh, a, b)
  for e in mesh:edges() do
    local h = e.halfedge
    if (h.vertex.id == a and h.twin.vertex.id == b) or (h.vertex.id == b and h.twin.vertex.id == a) then return e end
  end
end

local function near(p, q, tolerance) return (p - q):length() < (tolerance or 1e-3) end

-- One mesh holding `a` and `b` side by side, b moved by `offset`: a's vertex k is vertex k, b's is #a + k.
local function side_by_side(a, b, offset)
  local positions, polygons = {}, {}
  for _, part in ipairs({ { a, meshedit.vec3(0, 0, 0) }, { b, offset } }) do
    local base = #positions
    for v in part[1]:vertices() do positions[base + v.id + 1] = v.position + part[2] end
    for f in part[1]:faces() do
      local polygon = {}
      for v in f:vertices() do polygon[#polygon + 1] = base + v.id + 1 end
      polygons[#polygons + 1] = polygon
    end
  end
  return meshedit.from_polygons(positions, polygons)
end


step({ en = "Face points", zh = "面点" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local top = cube:face(1)
  highlight(top, "yellow")
  local half = cube:vertex(7).position
  say {
    en = [[
# Catmull-Clark subdivision

Loop subdivision (part 6) needs triangles. **Catmull-Clark** takes any polygons: every face of n corners becomes
n quads. From the old mesh it makes a **face point** per face, an **edge point** per edge and a **vertex point**
per old vertex (where that vertex moves). The window's **Subdivide** menu runs it whole, or a phase at a time.]],
    zh = [[
# Catmull-Clark 细分

Loop 细分（第 6 部分）只适用于三角形。**Catmull-Clark** 细分接受任意多边形：每个有 n 个角点的面都变成 n 个四边形。
它由旧网格为每个面算出一个 **面点**（face point），为每条边算出一个 **边点**（edge point），为每个旧顶点算出一个
**顶点点**（vertex point，即该顶点要移到的位置）。窗口的 **细分** 菜单可以一次运行整个细分，也可以一次只运行一个阶段。]],
  }
  say({ en = "On screen: the unit cube centred at 0 as **six quads** (" .. counts(cube) .. "), its corners at (±"
    .. num(half.x) .. ", ±" .. num(half.y) .. ", ±" .. num(half.z) .. "). The yellow face is the top, where z = "
    .. num(centroid(top).z) .. ".",
    zh = "屏幕上是以 0 为中心的单位立方体，由 **六个四边形** 组成（" .. counts_zh(cube) .. "），角点位于 (±"
      .. num(half.x) .. ", ±" .. num(half.y) .. ", ±" .. num(half.z) .. ")。黄色的面是顶面，位于 z = "
      .. num(centroid(top).z) .. " 处。" })
  local right = face_point(cube, top)
  local sum = centroid(top) * top:degree()
  answer {
    { en = "A face point stands for its whole face, and no corner of the face counts more than another. Where would "
      .. "you put the yellow face's? Give x, y, z.",
      zh = "面点代表它的整个面，面上没有哪个角点比别的更重要。你会把黄色面的面点放在哪里？请给出 x, y, z。" },
    point = { right.x, right.y, right.z },
    feedback = function(p)
      if p:length() < 1e-3 then
        return { en = "(0, 0, 0) is the centre of the whole cube, the mean of all 8 corners; the face point is the "
          .. "mean of this face's corners only.",
          zh = "(0, 0, 0) 是整个立方体的中心，即全部 8 个角点的平均；面点只是这个面的各角点的平均。" }
      end
      if near(p, sum) then
        return { en = point(sum) .. " is the sum of the four corners: divide it by 4.",
          zh = point(sum) .. " 是四个角点之和：还要除以 4。" }
      end
      for v in top:vertices() do
        if near(p, v.position) then
          return { en = "That is a corner of the face; the face point is the mean of all four.",
            zh = "这是面的一个角点；面点是全部四个角点的平均。" }
        end
      end
    end,
    hint = { en = "Add up the four corners and divide by four.", zh = "把四个角点相加，再除以四。" },
  }
  label(top, { en = "face point", zh = "面点" })
  say({ en = "The core puts it at " .. point(right) .. ": the centre of the top. That is the rule: a face point is "
    .. "the **centroid** of the face's corners, their sum divided by their number. Every face gets one; on the cube "
    .. "they are the centres of the six sides.",
    zh = "核心代码把它放在 " .. point(right) .. "：顶面的中心。规则就是这样：面点是面上各角点的 **形心**，"
      .. "即它们的和除以它们的个数。每个面都有一个面点；在立方体上，它们就是六个侧面的中心。" })
end)

step({ en = "Edge points", zh = "边点" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = false }  -- the lesson's own labels only: the edge, the two face points
  local e = edge_between(cube, 0, 1)
  local h = e.halfedge
  local a, b = h.vertex.position, h.twin.vertex.position
  local f0, f1 = centroid(h.face), centroid(h.twin.face)
  highlight(e, "orange")
  label(e, tostring(e))
  label(h.face, { en = "face point", zh = "面点" })
  label(h.twin.face, { en = "face point", zh = "面点" })
  say({ en = "Each edge gets an **edge point**, a new vertex near the edge. The orange edge " .. tostring(e) .. " runs "
    .. "from " .. point(a) .. " to " .. point(b) .. "; the two faces beside it have the face points "
    .. point(f0) .. " and " .. point(f1) .. ".",
    zh = "每条边都有一个 **边点**：边附近的一个新顶点。橙色的边 " .. tostring(e) .. " 从 " .. point(a) .. " 到 "
      .. point(b) .. "；它两侧的两个面的面点是 " .. point(f0) .. " 和 " .. point(f1) .. "。" })
  local both = "The two ends and the two face points"
  choose {
    { en = "The edge point should lie near the edge, but also feel the two faces beside it, so that the new mesh is "
      .. "smoother than the old. Which points would you average?",
      zh = "边点应当在边附近，但也要受到它两侧两个面的影响，这样新网格才比旧网格更光滑。你会对哪些点取平均？" },
    options = { { en = "The two ends: the midpoint", zh = "两个端点：即中点" },
      { en = both, zh = "两个端点和两个面点" }, { en = "The two face points only", zh = "只用两个面点" },
      { en = "Every corner of the two faces", zh = "两个面的所有角点" } },
    answer = both,
    feedback = {
      ["The two ends: the midpoint"] = { en = "The midpoint feels only the edge: a sharp edge between two faces "
        .. "would stay exactly as sharp. (That is the rule on a boundary edge, where there is only one face.)",
        zh = "中点只受边本身的影响：两个面之间的一条尖锐的棱会保持原样，一样尖锐。（这是边界边上的规则，那里只有一个面。）" },
      ["The two face points only"] = { en = "The face points alone forget where the edge itself is: every edge of a "
        .. "face would feel the same two points and lose its place.",
        zh = "只用面点，就忘了边本身在哪里：一个面的每条边都会受到同样两个点的影响，失去自己的位置。" },
      ["Every corner of the two faces"] = { en = "The faces' corners are what their face points already sum up; "
        .. "counting them again weighs the far corners as much as the edge's own ends.",
        zh = "面点已经概括了各面的角点；再把角点算一次，远处的角点就和边自己的两个端点一样重了。" },
      [both] = { en = "Yes: the edge point is the mean of those four points, (a + b + f0 + f1) / 4.",
        zh = "对：边点是这四个点的平均，(a + b + f0 + f1) / 4。" },
    },
    hint = { en = "It must depend on the edge and on each face beside it. Which points stand for those?",
      zh = "它必须既取决于这条边，又取决于边两侧的每个面。哪些点代表它们？" },
  }
  local right = edge_point(cube, e)
  local midpoint = (a + b) / 2
  answer {
    { en = "Where is the orange edge's edge point? Give x, y, z.", zh = "橙色边的边点在哪里？请给出 x, y, z。" },
    point = { right.x, right.y, right.z },
    feedback = function(p)
      if near(p, midpoint) then
        return { en = point(midpoint) .. " is the edge's midpoint: that forgets the two face points, which pull the "
          .. "edge point inwards. (The midpoint is the rule only on a boundary edge.)",
          zh = point(midpoint) .. " 是边的中点：这忘了两个面点，它们会把边点往里拉。（只有在边界边上，规则才是取中点。）" }
      end
      if near(p, (f0 + f1) / 2) then
        return { en = "That is the mean of the two face points alone; the edge's own two ends count as well.",
          zh = "这只是两个面点的平均；边自己的两个端点也要算进去。" }
      end
      if near(p, (midpoint + f0 + f1) / 3) then
        return { en = "That averages the midpoint with the two face points, counting the edge's ends once between "
          .. "them. Each of the four points, a, b and the two face points, weighs 1/4.",
          zh = "这是把中点和两个面点取平均，两个端点合起来只算了一次。四个点（a、b 和两个面点）的权重都是 1/4。" }
      end
    end,
    hint = { en = "(a + b + f0 + f1) / 4, with a and b the edge's ends and f0, f1 the two faces' face points.",
      zh = "(a + b + f0 + f1) / 4，其中 a 和 b 是边的两个端点，f0、f1 是两个面的面点。" },
  }
  arrow(midpoint, right, "blue")
  say({ en = "The core puts it at " .. point(right) .. ". The blue arrow goes from the midpoint " .. point(midpoint)
    .. " to it: the two face points pull it " .. num((midpoint - right):length()) .. " in, towards the "
    .. "faces' centres.",
    zh = "核心代码把它放在 " .. point(right) .. "。蓝色箭头从中点 " .. point(midpoint) .. " 指向它："
      .. "两个面点把它朝两个面的中心往里拉了 " .. num((midpoint - right):length()) .. "。" })
end)

step({ en = "Vertex points", zh = "顶点点" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = false }
  local v = cube:vertex(0)
  local n = v:degree()
  local P = v.position
  local faces, midpoints, neighbours = {}, {}, {}
  for h in v:halfedges() do
    if h.face.kind == "face" then faces[#faces + 1] = centroid(h.face) end
    midpoints[#midpoints + 1] = (P + h.twin.vertex.position) / 2
    neighbours[#neighbours + 1] = h.twin.vertex.position
  end
  local F, R = mean(faces), mean(midpoints)
  highlight(v, "yellow")
  label(v, "v0, n = " .. n)
  local inwards = "Towards the centre, along the diagonal"
  choose {
    { en = "Catmull-Clark moves every old vertex too, to its vertex point, an average of points around it. Where "
      .. "will the yellow corner v0 go?",
      zh = "Catmull-Clark 细分也会移动每个旧顶点，把它移到它的顶点点，即它周围一些点的平均。黄色角点 v0 会去哪里？" },
    options = { { en = "It stays where it is", zh = "留在原处" }, { en = inwards, zh = "沿对角线朝中心移动" },
      { en = "Away from the centre", zh = "远离中心" },
      { en = "Onto one of its faces' face points", zh = "移到它某个面的面点上" } },
    answer = inwards,
    feedback = {
      ["It stays where it is"] = { en = "Then the cube's corners would stay sharp at every level. Catmull-Clark "
        .. "approximates: the averages pull every old vertex in.",
        zh = "那样立方体的角在每一层都会保持尖锐。Catmull-Clark 细分是逼近型的：这些平均会把每个旧顶点往里拉。" },
      ["Away from the centre"] = { en = "Every point around v0, its faces' face points and its edges' midpoints, "
        .. "lies inside the corner; an average of them cannot move it out.",
        zh = "v0 周围的每个点，即它各面的面点和各边的中点，都在这个角的内侧；它们的平均不可能把它往外移。" },
      ["Onto one of its faces' face points"] = { en = "v0 has three faces alike; an average treats them the same, "
        .. "so it cannot pick one. And it would jump much too far.",
        zh = "v0 的三个面彼此一样；平均对它们一视同仁，所以不会偏向其中一个。而且那样它会跳得太远。" },
      [inwards] = { en = "Yes: the points it averages all lie inside the corner, and the cube's symmetry keeps it on "
        .. "the diagonal. How far it goes is what the rule below says.",
        zh = "对：它所平均的点都在这个角的内侧，而立方体的对称性让它留在对角线上。它移动多远，由下面的规则给出。" },
    },
    hint = { en = "An average of points can only land among them. Where are the points around v0?",
      zh = "一组点的平均只能落在它们之间。v0 周围的点在哪里？" },
  }
  say {
    en = [[
An old vertex P with n edges moves to its **vertex point**

  (F + 2R + (n - 3) P) / n

where F is the mean of the face points of its n faces and R the mean of the **midpoints** of its n edges.]],
    zh = [[
有 n 条边的旧顶点 P 移到它的 **顶点点**

  (F + 2R + (n - 3) P) / n

其中 F 是它的 n 个面的面点的平均，R 是它的 n 条边的 **中点** 的平均。]],
  }
  say({ en = "The yellow corner v0 has n = " .. n .. " edges, and\n\n"
    .. "- P, where it is: " .. point(P) .. "\n"
    .. "- F, the mean of its faces' face points: " .. point(F) .. "\n"
    .. "- R, the mean of its edges' midpoints: " .. point(R),
    zh = "黄色角点 v0 有 n = " .. n .. " 条边，并且\n\n"
      .. "- P，它现在的位置：" .. point(P) .. "\n"
      .. "- F，它各面的面点的平均：" .. point(F) .. "\n"
      .. "- R，它各边的中点的平均：" .. point(R) })
  local right = vertex_point(cube, v)
  local mistakes = {
    { P, { en = "It moves: Catmull-Clark approximates, every old vertex goes to its vertex point.",
      zh = "它会移动：Catmull-Clark 细分是逼近型的，每个旧顶点都会移到它的顶点点。" } },
    { (F + 2 * R + P) / n, { en = "That weighs P once; its weight is n - 3, which is 0 at a corner of degree 3.",
      zh = "这把 P 算了一次；它的权重是 n - 3，在度数为 3 的角点上为 0。" } },
    { (F + R + P) / 3, { en = "That is the plain mean of F, R and P. The rule counts R twice and P n - 3 times, "
      .. "over n.", zh = "这是 F、R 和 P 的简单平均。规则把 R 算两次、P 算 n - 3 次，再除以 n。" } },
    { (F + 2 * mean(neighbours)) / n, { en = "That uses the mean of the neighbouring vertices for R; R is the mean "
      .. "of the edges' midpoints, halfway to the neighbours.",
      zh = "这把相邻顶点的平均当成了 R；R 是各边中点的平均，而中点只在通往邻点的半路上。" } },
    { F, { en = "That is F alone; add 2R and (n - 3) P, then divide by n.",
      zh = "这只是 F；还要加上 2R 和 (n - 3) P，再除以 n。" } },
  }
  if near(mistakes[4][1], F) then  -- the same point on the cube: one answer, both mistakes named
    mistakes[4][2] = { en = mistakes[4][2].en .. " (Here that is also F alone, which leaves out 2R and (n - 3) P.)",
      zh = mistakes[4][2].zh .. "（在这里它也恰好就是 F，漏掉了 2R 和 (n - 3) P。）" }
  end
  answer {
    { en = "Where does the corner v0 go? Give x, y, z.", zh = "角点 v0 移到哪里？请给出 x, y, z。" },
    point = { right.x, right.y, right.z },
    feedback = function(p)
      for _, mistake in ipairs(mistakes) do
        if near(p, mistake[1]) then return mistake[2] end
      end
    end,
    hint = { en = "With n = 3 the (n - 3) P term is zero: (F + 2R) / 3.",
      zh = "n = 3 时 (n - 3) P 这一项为零：(F + 2R) / 3。" },
  }
  arrow(P, right, "blue")
  local ratio = right:length() / P:length()
  local share = fraction(ratio) or num(ratio)
  say({ en = "The core moves v0 to " .. point(right) .. " (blue arrow): " .. share .. " of its "
    .. "distance from the centre, along the same diagonal. Every corner of the cube does the same, so one level "
    .. "already rounds the cube off.",
    zh = "核心代码把 v0 移到 " .. point(right) .. "（蓝色箭头）：沿同一条对角线，到中心的距离变为原来的 " .. share
      .. "。立方体的每个角点都是这样，所以细分一层就已经把立方体变圆了。" })
end)

step({ en = "Counting after one level", zh = "细分一层后的数目" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local V, E, F = cube:num_vertices(), cube:num_edges(), cube:num_faces()
  local after = catmull_clark(cube)
  local sides = 0
  for f in cube:faces() do sides = sides + f:degree() end
  say({ en = "One level keeps every old vertex, moved to its vertex point. The cube has V = " .. V .. ", E = " .. E
    .. " and F = " .. F .. ".",
    zh = "细分一层会保留每个旧顶点，只是把它移到它的顶点点。立方体有 V = " .. V .. "、E = " .. E .. " 和 F = " .. F
      .. "。" })
  local right = (V + E + F) .. " = V + E + F"
  assert(after:num_vertices() == V + E + F, "the core's vertex count is not V + E + F")
  local options = { right, (V + E) .. " = V + E", (V + F) .. " = V + F", (4 * F) .. " = 4F" }
  choose {
    { en = "How many vertices will the cube have after one level?", zh = "细分一层之后，立方体有多少个顶点？" },
    options = options,
    answer = right,
    feedback = {
      [options[2]] = { en = "V + E is Loop's count: it adds a vertex per edge only. Catmull-Clark adds one per face "
        .. "too.", zh = "V + E 是 Loop 细分的数目：它只为每条边加一个顶点。Catmull-Clark 细分还为每个面加一个。" },
      [options[3]] = { en = "That leaves out the edge points: every edge gets a new vertex as well.",
        zh = "这漏掉了边点：每条边也会得到一个新顶点。" },
      [options[4]] = { en = "4F counts every quad's corners separately, but faces share their corners.",
        zh = "4F 把每个四边形的角点分开来数，但相邻的面共用角点。" },
      [right] = { en = "Yes: the old vertices stay, plus one new vertex per edge and one per face.",
        zh = "对：旧顶点保留，再加上每条边一个、每个面一个新顶点。" },
    },
    hint = { en = "Which of the three kinds of points become new vertices, and how many of each are there?",
      zh = "三种点中哪几种会成为新顶点？每种各有多少个？" },
  }
  answer {
    { en = "Each face of n corners becomes n quads. How many faces after one level?",
      zh = "每个有 n 个角点的面变成 n 个四边形。细分一层之后有多少个面？" },
    number = after:num_faces(),
    tolerance = 0.5,
    feedback = function(value)
      if value == F then
        return { en = "The faces are not kept: each one is cut into quads, one per corner.",
          zh = "旧面不会保留：每个面都被切成四边形，每个角点一个。" }
      end
      if value == 2 * F * 4 then
        return { en = "That is Loop's count on the cube of " .. 2 * F .. " triangles; here each quad gives 4 quads.",
          zh = "这是 Loop 细分在由 " .. 2 * F .. " 个三角形组成的立方体上的数目；这里每个四边形给出 4 个四边形。" }
      end
      if value == V + E + F then
        return { en = "That is the number of vertices; each face gives one quad per corner.",
          zh = "这是顶点的个数；每个面为它的每个角点给出一个四边形。" }
      end
    end,
    hint = { en = "The cube has " .. F .. " faces of 4 corners each.",
      zh = "立方体有 " .. F .. " 个面，每个面有 4 个角点。" },
  }
  say { en = "Now do it: **Subdivide > Catmull-Clark subdivision** (the menu above the view) on the cube on screen.",
    zh = "现在动手：对屏幕上的立方体运行 **细分 > Catmull-Clark 细分**（视图上方的菜单）。" }
  wait_for {
    condition = function()
      local mesh = current_mesh()
      return mesh ~= nil and mesh:num_faces() == after:num_faces() and mesh:num_vertices() == after:num_vertices()
    end,
    hint = { en = "Subdivide > Catmull-Clark subdivision", zh = "细分 > Catmull-Clark 细分" },
  }
  camera "fit"
  view { labels = false }  -- 26 vertices and 48 edges: their ids would hide the quads
  local yours = current_mesh()
  say({ en = "Your level: " .. counts(yours) .. ", all " .. face_kinds(yours) .. ". Every new quad joins an old "
    .. "vertex, an edge point, a face point and the next edge point, so the " .. sides .. " corners of the old faces "
    .. "give " .. after:num_faces() .. " quads and E' = 2E + " .. sides .. " = " .. after:num_edges() .. " edges.",
    zh = "你的这一层：" .. counts_zh(yours) .. "，全部为 " .. face_kinds_zh(yours) .. "。每个新四边形连接一个旧顶点、"
      .. "一个边点、一个面点和下一个边点，所以旧面的 " .. sides .. " 个角点给出 " .. after:num_faces()
      .. " 个四边形，以及 E' = 2E + " .. sides .. " = " .. after:num_edges() .. " 条边。" })
end)

-- Whether `mesh` (the mesh on screen) is `expected`: the same counts and every vertex at the same place by id (the
-- window's phases and the lesson's are the core's, so a vertex keeps its id in both).
local function same_mesh(mesh, expected)
  if not mesh or mesh:num_vertices() ~= expected:num_vertices() or mesh:num_faces() ~= expected:num_faces()
    or mesh:num_edges() ~= expected:num_edges() then
    return false
  end
  for v in expected:vertices() do
    local ok, same = pcall(function() return near(mesh:vertex(v.id).position, v.position, 1e-9) end)
    if not ok or not same then return false end
  end
  return true
end

-- The Subdivide menu's Catmull-Clark phase items in Chinese, by the core's English label (assets/translations/zh).
local PHASE_LABELS_ZH = {
  ["Catmull-Clark 1/3: compute face, edge and vertex points"] = "Catmull-Clark 1/3：计算面点、边点和顶点的新位置",
  ["Catmull-Clark 2/3: split every face into quads (nothing moves yet)"] =
    "Catmull-Clark 2/3：把每个面分裂成四边形（此时还没有点移动）",
  ["Catmull-Clark 3/3: move every vertex to its point"] = "Catmull-Clark 3/3：把每个顶点移到它的新位置",
}

step({ en = "The app's phases", zh = "应用中的各阶段" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local e = edge_between(cube, 0, 1)
  local a, b = cube:vertex(0).position, cube:vertex(1).position
  highlight(e, "yellow")
  say {
    en = [[
The **Subdivide** menu also runs Catmull-Clark **one phase at a time**, as Shift+L does for Loop:
1. **compute** every face, edge and vertex point from the cube as it is; nothing changes yet;
2. **split** every face into quads, with a new vertex on every edge and in every face;
3. **move** every vertex to its point.]],
    zh = [[
**细分** 菜单也能 **一次一个阶段** 地运行 Catmull-Clark 细分，就像 Shift+L 对 Loop 细分那样：
1. **计算**：由立方体现在的样子算出每个面点、边点和顶点点；此时什么都不改变；
2. **分裂**：把每个面分裂成四边形，在每条边上和每个面内各放一个新顶点；
3. **移动**：把每个顶点移到它的点。]],
  }
  local midpoint = "At the edge's midpoint " .. point((a + b) / 2)
  local edge_point_option = "At its edge point " .. point(edge_point(cube, e))
  local corner = "On v0, until phase 3 moves it"
  choose {
    { en = "After phase 2, where is the new vertex on the yellow edge " .. tostring(e) .. "?",
      zh = "阶段 2 之后，黄色边 " .. tostring(e) .. " 上的新顶点在哪里？" },
    options = { { en = edge_point_option, zh = "在它的边点 " .. point(edge_point(cube, e)) },
      { en = midpoint, zh = "在边的中点 " .. point((a + b) / 2) },
      { en = corner, zh = "在 v0 上，直到阶段 3 才移开" } },
    answer = midpoint,
    feedback = {
      [edge_point_option] = { en = "Phase 2 only changes the connectivity. The edge point is where phase 3 moves it "
        .. "to.", zh = "阶段 2 只改变连接关系。边点是阶段 3 把它移到的位置。" },
      [corner] = { en = "A new vertex is made on its edge, between v0 and v1, never on top of a corner.",
        zh = "新顶点建在它的边上，位于 v0 和 v1 之间，从不与角点重合。" },
      [midpoint] = { en = "Yes: phase 2 places it halfway, so the shape has not changed yet. Linear subdivision "
        .. "stops there.", zh = "对：阶段 2 把它放在正中间，所以形状还没有变。线性细分就停在这一步。" },
    },
    hint = { en = "Phase 2 splits faces; which phase moves vertices?", zh = "阶段 2 分裂面；哪个阶段移动顶点？" },
  }
  local expected = cube:copy()
  local phases = expected:subdivision_phases("catmull-clark")
  local new_vertex = cube:num_vertices() + e.id  -- the core numbers edge points after the old vertices
  local computed
  say { en = "Now run **Subdivide > Catmull-Clark** one phase at a time, three times; the menu item names the next "
    .. "phase.", zh = "现在一次一个阶段地运行 **细分 > Catmull-Clark**，共三次；菜单项会写出下一个阶段的名称。" }
  local phase = 1
  while phase <= 3 do
    wait_for { command = "catmull-clark-phase", hint = { en = "Subdivide > " .. phases.next_label,
      zh = "细分 > " .. (PHASE_LABELS_ZH[phases.next_label] or phases.next_label) } }
    assert(phases:step())
    if phase == 1 then computed = phases:points() end
    local mesh = current_mesh()
    if not same_mesh(mesh, expected) then
      expected = quad_cube()
      phases = expected:subdivision_phases("catmull-clark")
      show(quad_cube())
      highlight(e, "yellow")
      say({ en = "That is not the cube after phase " .. phase .. " (did another command change the mesh?). Here is "
        .. "a fresh cube: from phase 1 again.",
        zh = "这不是阶段 " .. phase .. " 之后的立方体（是不是别的命令改动了网格？）。这是一个新的立方体："
          .. "从阶段 1 重新开始。" })
      phase = 1
    else
      if phase == 1 then
        say({ en = "**Phase 1** computed " .. cube:num_faces() .. " face points, " .. cube:num_edges() .. " edge "
          .. "points and " .. cube:num_vertices() .. " vertex points, and nothing moved: the edge point of "
          .. tostring(e) .. " is " .. point(computed.edges[e.id]) .. ", the vertex point of v0 "
          .. point(computed.vertices[0]) .. ".",
          zh = "**阶段 1** 算出了 " .. cube:num_faces() .. " 个面点、" .. cube:num_edges() .. " 个边点和 "
            .. cube:num_vertices() .. " 个顶点点，什么也没有移动：" .. tostring(e) .. " 的边点是 "
            .. point(computed.edges[e.id]) .. "，v0 的顶点点是 " .. point(computed.vertices[0]) .. "。" })
      elseif phase == 2 then
        label("v" .. new_vertex, { en = "new on " .. tostring(e), zh = tostring(e) .. " 上的新顶点" })
        say({ en = "**Phase 2** split the " .. cube:num_faces() .. " faces into " .. mesh:num_faces() .. " quads. The "
          .. "new vertex v" .. new_vertex .. " sits at " .. point(mesh:vertex(new_vertex).position) .. ", the "
          .. "midpoint, and v0 is still at " .. point(mesh:vertex(0).position) .. ".",
          zh = "**阶段 2** 把 " .. cube:num_faces() .. " 个面分裂成了 " .. mesh:num_faces() .. " 个四边形。新顶点 v"
            .. new_vertex .. " 位于 " .. point(mesh:vertex(new_vertex).position) .. "，即中点，而 v0 仍在 "
            .. point(mesh:vertex(0).position) .. "。" })
      else
        say({ en = "**Phase 3** moved every vertex to its point: v" .. new_vertex .. " to "
          .. point(mesh:vertex(new_vertex).position) .. ", the edge point, and v0 to "
          .. point(mesh:vertex(0).position) .. ", its vertex point. One level done: " .. counts(mesh) .. ".",
          zh = "**阶段 3** 把每个顶点移到了它的点：v" .. new_vertex .. " 移到边点 "
            .. point(mesh:vertex(new_vertex).position) .. "，v0 移到它的顶点点 " .. point(mesh:vertex(0).position)
            .. "。一层完成：" .. counts_zh(mesh) .. "。" })
      end
      phase = phase + 1
    end
  end
end)

step({ en = "Triangles become quads", zh = "三角形变为四边形" }, function()
  local tetrahedron = meshedit.tetrahedron()
  show(tetrahedron)
  camera "fit"
  view { halfedges = false, labels = true }
  local after = catmull_clark(tetrahedron)
  local right = after:num_faces() .. " quads"
  local loop = tetrahedron:copy()
  assert(loop:loop_subdivide())
  local options = { right, loop:num_faces() .. " triangles", tetrahedron:num_faces() .. " triangles and "
    .. after:num_faces() .. " quads" }
  say({ en = "Catmull-Clark does not need quads. Here is a tetrahedron: " .. counts(tetrahedron) .. ", all "
    .. face_kinds(tetrahedron) .. ".",
    zh = "Catmull-Clark 细分并不要求四边形。这是一个四面体：" .. counts_zh(tetrahedron) .. "，全部为 "
      .. face_kinds_zh(tetrahedron) .. "。" })
  choose {
    { en = "What faces does one level of Catmull-Clark make of it?",
      zh = "对它做一层 Catmull-Clark 细分，会得到哪些面？" },
    options = { { en = options[1], zh = after:num_faces() .. " 个四边形" },
      { en = options[2], zh = loop:num_faces() .. " 个三角形" },
      { en = options[3], zh = tetrahedron:num_faces() .. " 个三角形和 " .. after:num_faces() .. " 个四边形" } },
    answer = right,
    feedback = {
      [options[2]] = { en = "That is Loop subdivision: each triangle into four triangles. Catmull-Clark cuts a face "
        .. "of n corners into n quads, one at each corner.",
        zh = "这是 Loop 细分：每个三角形变成四个三角形。Catmull-Clark 细分把有 n 个角点的面切成 n 个四边形，每个角点一个。" },
      [options[3]] = { en = "No old face survives: every triangle is cut into quads, one per corner.",
        zh = "没有旧面会留下来：每个三角形都被切成四边形，每个角点一个。" },
      [right] = { en = "Yes: each triangle gives three quads, one at each corner.",
        zh = "对：每个三角形给出三个四边形，每个角点一个。" },
    },
    hint = { en = "A face of n corners gives n faces. What kind of faces?",
      zh = "有 n 个角点的面给出 n 个面。是什么样的面？" },
  }
  show(after)
  camera "fit"
  view { labels = false }
  say({ en = "The core's level: " .. counts(after) .. ", all " .. face_kinds(after) .. ". After one level every face "
    .. "is a quad whatever the input was, so from then on Catmull-Clark works on quads only. The vertices that were "
    .. "triangles' face points have 3 edges: those, like the old corners, are the **extraordinary** vertices "
    .. "(not 4 edges), and their number never grows.",
    zh = "核心代码的这一层：" .. counts_zh(after) .. "，全部为 " .. face_kinds_zh(after) .. "。无论输入是什么，"
      .. "细分一层之后每个面都是四边形，所以从此 Catmull-Clark 细分只处理四边形。原先是三角形面点的那些顶点有 3 条边："
      .. "它们和旧角点一样，是 **奇异** 顶点（边数不是 4），而且它们的个数永远不会增加。" })
end)

step({ en = "Boundary rules", zh = "边界规则" }, function()
  local grid = quad_grid(2)
  show(grid)
  camera { fit = true, pitch = 70 }  -- a flat mesh: seen from above
  view { halfedges = false, labels = true }
  local corner = grid:vertex(0)
  local e = edge_between(grid, 0, 1)
  local a, b = corner.position, grid:vertex(1).position
  local inside = centroid(e.halfedge.face.kind == "face" and e.halfedge.face or e.halfedge.twin.face)
  highlight(e, "orange")
  highlight(corner, "yellow")
  label(corner, { en = "corner v0", zh = "角点 v0" })
  say({ en = "On a mesh with a **boundary** the border gets rules of its own, so it stays a curve of its own. This "
    .. "grid of quads has " .. counts(grid) .. " and " .. grid:num_boundaries() .. " boundary loop. The orange edge "
    .. "runs along the boundary from " .. point(a) .. " to " .. point(b) .. "; it has one face beside it, whose "
    .. "face point is " .. point(inside) .. ".",
    zh = "在带 **边界** 的网格上，边界有它自己的规则，因而它保持为一条独立的曲线。这个四边形网格有 "
      .. counts_zh(grid) .. "，以及 " .. grid:num_boundaries() .. " 个边界环。橙色的边沿着边界从 " .. point(a)
      .. " 到 " .. point(b) .. "；它旁边只有一个面，该面的面点是 " .. point(inside) .. "。" })
  local right_edge = edge_point(grid, e)
  answer {
    { en = "Where is the orange boundary edge's edge point? Give x, y.", zh = "橙色边界边的边点在哪里？请给出 x, y。" },
    point = { right_edge.x, right_edge.y },
    feedback = function(p)
      if near(p, (a + b + inside) / 3) then
        return { en = "That is the interior rule with the one face point it has. A boundary edge ignores the faces: "
          .. "its point is the midpoint, so the border depends only on the border.",
          zh = "这是用它仅有的一个面点套用内部规则。边界边不管面：它的点就是中点，所以边界只取决于边界本身。" }
      end
      if near(p, (a + b + 2 * inside) / 4) or near(p, (a + b + inside) / 4) then
        return { en = "That applies the interior rule, with a face point that is not there. A boundary edge's point "
          .. "is simpler.", zh = "这套用了内部规则，还用上了一个并不存在的面点。边界边的点要简单得多。" }
      end
    end,
    hint = { en = "A boundary edge has only one face. Which point of the edge needs no face at all?",
      zh = "边界边只有一个面。边上哪个点完全不需要面？" },
  }
  say({ en = "The core puts it at the **midpoint**, " .. point(right_edge) .. ".",
    zh = "核心代码把它放在 **中点** " .. point(right_edge) .. "。" })
  local left, right = nil, nil
  for h in corner:halfedges() do
    local other = h.twin.vertex
    if h.edge:is_boundary() then
      if left then right = other.position else left = other.position end
    end
  end
  local along = "Itself and its two neighbours along the boundary"
  choose {
    { en = "The yellow corner is on the boundary too. Which points should its rule use, so that the border stays a "
      .. "curve of its own?",
      zh = "黄色角点也在边界上。它的规则应当用哪些点，才能让边界保持为一条独立的曲线？" },
    options = { { en = along, zh = "它自己和沿边界的两个邻点" },
      { en = "Itself and all its neighbours", zh = "它自己和所有邻点" },
      { en = "Itself, its neighbours and its face's face point", zh = "它自己、它的邻点和它所在面的面点" } },
    answer = along,
    feedback = {
      ["Itself and all its neighbours"] = { en = "A neighbour inside the mesh would pull the border inwards, and the "
        .. "border would depend on the inside. Only the points on the border itself may count.",
        zh = "网格内部的邻点会把边界往里拉，边界就会取决于内部。只有边界本身上的点才能算进去。" },
      ["Itself, its neighbours and its face's face point"] = { en = "The face point lies inside the mesh: the border "
        .. "would then depend on the faces, as the edge point you just found does not.",
        zh = "面点在网格内部：那样边界就会取决于面，而你刚才求出的边点并不取决于面。" },
      [along] = { en = "Yes: the same rule as a curve's, from the points of the border alone.",
        zh = "对：和曲线的规则一样，只用边界上的点。" },
    },
    hint = { en = "The edge point of a boundary edge used the edge alone. Do the same for a vertex.",
      zh = "边界边的边点只用了边本身。对顶点也这样做。" },
  }
  say({ en = "A boundary vertex P moves to 3/4 P + 1/8 of its two neighbours **along the boundary**. The yellow "
    .. "corner's are " .. point(left) .. " and " .. point(right) .. ".",
    zh = "边界顶点 P 移到 3/4 P 加上它 **沿边界** 的两个邻点各自的 1/8。黄色角点的这两个邻点是 " .. point(left)
      .. " 和 " .. point(right) .. "。" })
  local right_vertex = vertex_point(grid, corner)
  answer {
    { en = "Where does the yellow corner go? Give x, y.", zh = "黄色角点移到哪里？请给出 x, y。" },
    point = { right_vertex.x, right_vertex.y },
    feedback = function(p)
      if near(p, a) then
        return { en = "A boundary vertex moves too, by the boundary's own rule.",
          zh = "边界顶点也会移动，按的是边界自己的规则。" }
      end
      if near(p, a * 0.5 + (left + right) * 0.25) then
        return { en = "That gives each neighbour 1/4; the rule keeps 3/4 of the corner and gives each neighbour 1/8.",
          zh = "这给了每个邻点 1/4；规则保留角点的 3/4，给每个邻点 1/8。" }
      end
      if near(p, (a + left + right) / 3) then
        return { en = "That is the plain mean of the corner and its two neighbours; the rule keeps 3/4 of the corner.",
          zh = "这是角点和它两个邻点的简单平均；规则保留角点的 3/4。" }
      end
    end,
    hint = { en = "3/4 of the corner plus 1/8 of each of its two boundary neighbours.",
      zh = "角点的 3/4，加上它两个边界邻点各自的 1/8。" },
  }
  local after = catmull_clark(grid)
  show(after)
  clear()
  view { labels = false }
  highlight(after:vertex(0), "yellow")
  label(after:vertex(0), { en = "corner", zh = "角点" })
  arrow(a, right_vertex, "blue")
  say({ en = "The core's level: " .. counts(after) .. ", still " .. after:num_boundaries() .. " boundary loop. The "
    .. "corner went from " .. point(a) .. " to " .. point(right_vertex) .. " (blue arrow), cut off as a closed mesh's "
    .. "corners are.",
    zh = "核心代码的这一层：" .. counts_zh(after) .. "，仍是 " .. after:num_boundaries() .. " 个边界环。角点从 "
      .. point(a) .. " 移到了 " .. point(right_vertex) .. "（蓝色箭头），像封闭网格的角一样被削掉了。" })
end)

step({ en = "Linear subdivision beside it", zh = "对照：线性细分" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = true }
  local linear = cube:copy()
  assert(linear:linear_subdivide())
  local smooth = catmull_clark(cube)
  say({ en = "The Subdivide menu also has **Linear subdivision**: the same new vertices and the same quads as "
    .. "Catmull-Clark (" .. counts(linear) .. " on the cube), but every new vertex stays at its edge's midpoint or "
    .. "its face's centroid.",
    zh = "「细分」菜单里还有 **线性细分**：新顶点和四边形都与 Catmull-Clark 细分相同（在立方体上是 "
      .. counts_zh(linear) .. "），但每个新顶点都留在它所在边的中点或所在面的形心上。" })
  local ratio = smooth:vertex(0).position:length() / cube:vertex(0).position:length()
  local right = "Where it was"
  local travelled = fraction(1 - ratio) or num(1 - ratio)
  local options = { right, travelled .. " of the way to the centre", "At a face centroid" }
  choose {
    { en = "After one level of linear subdivision, where is the corner v0?",
      zh = "线性细分一层之后，角点 v0 在哪里？" },
    options = { { en = right, zh = "在原处" }, { en = options[2], zh = "朝中心走了 " .. travelled .. " 的路程" },
      { en = options[3], zh = "在某个面的形心上" } },
    answer = right,
    feedback = {
      [options[2]] = { en = "That is where Catmull-Clark's vertex point takes it; linear subdivision moves no old "
        .. "vertex.", zh = "那是 Catmull-Clark 细分的顶点点把它带到的地方；线性细分不移动任何旧顶点。" },
      [options[3]] = { en = "The face centroids are new vertices (the face points); the old corner is still there "
        .. "too.", zh = "面的形心是新顶点（即面点）；旧角点也仍在那里。" },
      [right] = { en = "Yes: linear subdivision only adds vertices; the shape stays the cube.",
        zh = "对：线性细分只增加顶点；形状仍是那个立方体。" },
    },
    hint = { en = "Linear subdivision only places new vertices at midpoints and centroids. What does it do to the old "
      .. "ones?", zh = "线性细分只在中点和形心处放置新顶点。它对旧顶点做了什么？" },
  }
  local moved = 0
  for v in cube:vertices() do moved = math.max(moved, (linear:vertex(v.id).position - v.position):length()) end
  local width = 0
  for v in cube:vertices() do width = math.max(width, v.position.x) end
  local both = side_by_side(linear, smooth, meshedit.vec3(4 * width, 0, 0))
  show(both)
  camera "fit"
  view { labels = false }
  label(both:vertex(0), { en = "linear", zh = "线性" })
  label(both:vertex(linear:num_vertices()), { en = "Catmull-Clark", zh = "Catmull-Clark" })
  highlight(both:vertex(0), "yellow")
  highlight(both:vertex(linear:num_vertices()), "yellow")
  say({ en = "Left, linear: " .. (moved == 0 and "not one old vertex moved" or ("its old vertices moved by at most "
    .. num(moved))) .. ", and v0 is still at " .. point(linear:vertex(0).position) .. ". Right, Catmull-Clark: "
    .. "v0 went to " .. point(smooth:vertex(0).position)
    .. ". Both have " .. counts(smooth) .. ".",
    zh = "左边是线性细分：" .. (moved == 0 and "没有一个旧顶点移动" or ("它的旧顶点最多移动了 " .. num(moved)))
      .. "，v0 仍在 " .. point(linear:vertex(0).position) .. "。右边是 Catmull-Clark 细分：v0 移到了 "
      .. point(smooth:vertex(0).position) .. "。两者都有 " .. counts_zh(smooth) .. "。" })
  local levels = smooth:copy()
  assert(levels:catmull_clark())
  assert(levels:catmull_clark())
  say({ en = "Linear subdivision gives a finer mesh of the same shape; Catmull-Clark's rules move every vertex, and "
    .. "level after level the mesh converges to a smooth surface (v0 starts "
    .. num(cube:vertex(0).position:length()) .. " from the centre; after three levels it is "
    .. num(levels:vertex(0).position:length()) .. " from it, and there are " .. levels:num_faces()
    .. " quads). Try both in the window's **Subdivide** menu.",
    zh = "线性细分给出形状不变、更细密的网格；Catmull-Clark 细分的规则会移动每个顶点，一层又一层，网格收敛到一张光滑曲面"
      .. "（v0 起初到中心的距离是 " .. num(cube:vertex(0).position:length()) .. "；三层之后是 "
      .. num(levels:vertex(0).position:length()) .. "，共有 " .. levels:num_faces()
      .. " 个四边形）。在窗口的 **细分** 菜单里把两种都试一试。" })
end)

step({ en = "Your own Catmull-Clark", zh = "你自己的 Catmull-Clark" }, function()
  local cube = quad_cube()
  show(cube)
  camera "fit"
  view { halfedges = false, labels = false }
  local linear = cube:copy()
  assert(linear:linear_subdivide())
  local right = "Linear subdivision first, then move every vertex"
  choose {
    { en = "You have seen that linear subdivision makes Catmull-Clark's quads with every new vertex at a midpoint or "
      .. "a centroid. How could your own code do one level of Catmull-Clark?",
      zh = "你已经看到，线性细分生成的四边形与 Catmull-Clark 细分的相同，只是每个新顶点都在中点或形心上。"
        .. "你自己的代码怎样才能完成一层 Catmull-Clark 细分？" },
    options = { { en = right, zh = "先线性细分，再移动每个顶点" },
      { en = "Move the old vertices first, then subdivide", zh = "先移动旧顶点，再细分" },
      { en = "Subdivide, then move only the old vertices", zh = "先细分，再只移动旧顶点" } },
    answer = right,
    feedback = {
      ["Move the old vertices first, then subdivide"] = { en = "Then the midpoints and centroids linear subdivision "
        .. "places would come from the moved corners, and the edge and face points would be wrong: the rules read the "
        .. "mesh before anything moves.",
        zh = "那样线性细分放置的中点和形心就会来自移动过的角点，边点和面点都会出错：规则读取的是任何点移动之前的网格。" },
      ["Subdivide, then move only the old vertices"] = { en = "The edge vertices move too: from the midpoint to the "
        .. "edge point, pulled toward the two faces. Only the face vertices stay, at their faces' centroids.",
        zh = "边上的新顶点也要移动：从中点移到边点，被拉向两侧的两个面。只有面上的新顶点留在原处，即各自面的形心上。" },
      [right] = { en = "Yes: mesh:linear_subdivide() makes the quads, and each vertex's rule can be read from its "
        .. "neighbours in the refined mesh, as long as every new position is computed before any moves.",
        zh = "对：mesh:linear_subdivide() 生成这些四边形，而每个顶点的规则都可以从它在细化后网格中的邻点读出，"
          .. "只要在移动任何顶点之前先算好每个新位置。" },
    },
    hint = { en = "Which phase of the Subdivide menu's Catmull-Clark is exactly linear subdivision?",
      zh = "「细分」菜单中 Catmull-Clark 细分的哪个阶段恰好就是线性细分？" },
  }
  say({ en = "Linear subdivision gives " .. counts(linear) .. ", every vertex where phase 2 put it. Now write it: open "
    .. "**scripts/student/catmull_clark.lua**. It gives the rules as they read in the refined mesh (an edge vertex "
    .. "goes to the mean of its four neighbours, an old vertex to (F + 2R + (n - 3) P) / n with R the mean of its "
    .. "neighbours). The lesson runs your `catmull_clark_level` on a copy of this cube each time you save the file "
    .. "and compares every vertex with the core's level.",
    zh = "线性细分给出 " .. counts_zh(linear) .. "，每个顶点都在阶段 2 放下它的位置上。现在来写代码：打开 "
      .. "**scripts/student/catmull_clark.lua**。它给出了这些规则在细化后网格中的写法（边上的顶点移到它四个邻点的平均处，"
      .. "旧顶点移到 (F + 2R + (n - 3) P) / n，其中 R 是它各邻点的平均）。每次你保存文件，本课都会在这个立方体的副本上运行你的 "
      .. "`catmull_clark_level`，并把每个顶点与核心代码的这一层比较。" })
  your_turn {
    exercise = "catmull_clark",
    mesh = cube,
    hint = { en = "Remember the old ids, call mesh:linear_subdivide(), compute every new position into a table, then "
      .. "move them all.",
      zh = "记下旧的 id，调用 mesh:linear_subdivide()，把每个新位置算好存进一张表，然后把它们全部移过去。" },
  }
  say {
    en = [[
Your level is the core's. The **Exercises** tab (**X**, choose **catmull_clark**, **Run mine**) runs it on any
mesh without triangles that you open (File > Open); try one with a boundary for the boundary rules. From a
terminal, the exercise's own suite grades it:

    meshedit grade --suite scripts/exercises/catmull_clark.lua --submission scripts/student]],
    zh = [[
你的这一层与核心代码的相同。**练习** 标签页（按 **X**，选择 **catmull_clark**，再点 **运行我的代码**）可以在你打开的
任何不含三角形的网格上运行它（文件 > 打开）；试试带边界的网格，检验边界规则。在终端中，这个练习自己的测试套件会给它评分：

    meshedit grade --suite scripts/exercises/catmull_clark.lua --submission scripts/student]],
  }
end)
