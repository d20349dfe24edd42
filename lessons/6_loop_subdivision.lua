-- Part 6: Loop subdivision, phase by phase. The lesson runs the four phases itself in Lua (the same phases the
-- app's Shift+L steps through, engine/core/loop_subdivision.h), telling old from new by flags set as it splits,
-- as scripts/student/upsample.lua asks. Each phase step asks first: the vertex count, u at degree 6, which edges
-- to split, which edge to flip (a pick on the split cube: the halves of a split edge are the trap), why the
-- positions come first. Then the student runs the app's phases with Shift+L, each checked against the Lua ones;
-- explains the cube's lopsided result and predicts which corners end nearer the centre before the lesson says
-- why; makes every corner's degree the same with flips and splits of their own (told when a flip makes it worse)
-- before the diagonal pre-split is shown; keeps a corner sharp to a target distance by editing near it before the
-- lesson says how; predicts where a boundary corner goes; and ends with their own upsample.lua run by your_turn on
-- a cube and a tetrahedron (every vertex of degree 3).
-- CI runs it headless:
--   meshedit lesson lessons/6_loop_subdivision.lua --headless \
--     --answers tests/lesson/lessons/6_loop_subdivision_answers.lua --student tests/exercise/solutions
-- Invariants: every step rebuilds its meshes from scratch (Back runs a step again, and must not subdivide
-- twice); the Lua phases use the course weights and split edges in id order, so their ids match the core's.

lesson {
  title = { en = "Part 6: Loop subdivision", zh = "第 6 部分：Loop 细分" },
  summary = {
    en = "Loop subdivision in four phases, the cube's asymmetry and the pre-split fix, sharp corners, "
      .. "a mesh with a boundary, and your own upsample.",
    zh = "分四个阶段的 Loop 细分、立方体的不对称及预分裂修正、尖角、带边界的网格，以及你自己的 upsample。",
  },
}

local function index(element) return element.id end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- counts(mesh) in Chinese: "26 个顶点、72 条边、48 个面".
local function counts_zh(mesh)
  return mesh:num_vertices() .. " 个顶点、" .. mesh:num_edges() .. " 条边、" .. mesh:num_faces() .. " 个面"
end

local function fmt(x) return string.format("%.4f", x) end

-- The degrees a mesh's vertices have, smallest first: "4 or 6", "3"; `sep` and `last` join them (", " and " or "
-- unless given: "、" and " 或 " for the Chinese).
local function degrees_of(mesh, sep, last)
  local seen, list = {}, {}
  for v in mesh:vertices() do
    if not seen[v:degree()] then
      seen[v:degree()] = true
      list[#list + 1] = v:degree()
    end
  end
  table.sort(list)
  if #list == 1 then return tostring(list[1]) end
  return table.concat(list, sep or ", ", 1, #list - 1) .. (last or " or ") .. list[#list]
end

-- ---- the four phases, on a closed triangle mesh, course weights ----

-- Phase 1: positions from the original mesh; nothing changes yet.
local function phase1(mesh)
  local state = { V = mesh:num_vertices(), E = mesh:num_edges(), vertex = {}, edge = {}, u = {} }
  for v in mesh:vertices() do
    local n = v:degree()
    local u = n == 3 and 3 / 16 or 3 / (8 * n)
    local sum = meshedit.vec3(0, 0, 0)
    for w in v:neighbors() do sum = sum + w.position end
    state.vertex[v.id] = v.position * (1 - n * u) + sum * u
    state.u[v.id] = u
  end
  for e in mesh:edges() do
    local h = e.halfedge
    local a, b = h.vertex.position, h.twin.vertex.position
    local c, d = h.next.next.vertex.position, h.twin.next.next.vertex.position
    state.edge[e.id] = (a + b) * (3 / 8) + (c + d) * (1 / 8)
  end
  return state
end

-- Phase 2: split every original edge (listed before the first split), in id order. Flags, by id: is_new_vertex
-- for each m, is_new_edge for the two edges from m to the corners across (m-c, m-d); the halves of the split edge
-- (a-m, m-b) stay unmarked. state.cross lists the new edges in the order the splits made them.
local function phase2(mesh, state)
  state.new_position = {}
  for i, p in pairs(state.vertex) do state.new_position[i] = p end
  state.is_new_vertex, state.is_new_edge, state.cross = {}, {}, {}
  local originals = {}
  for e in mesh:edges() do originals[#originals + 1] = e.id end
  for _, id in ipairs(originals) do
    local e = mesh:edge(id)
    local a, b = e.halfedge.vertex.id, e.halfedge.twin.vertex.id
    local m = assert(mesh:split(e))
    state.is_new_vertex[m.id] = true
    state.new_position[m.id] = state.edge[id]
    -- Around m (clockwise from m.halfedge): to a, c, b, d. The edges to c and d are the new ones.
    for h in m:halfedges() do
      local far = h.twin.vertex.id
      if far ~= a and far ~= b then
        state.is_new_edge[h.edge.id] = true
        state.cross[#state.cross + 1] = h.edge.id
      end
    end
  end
end

-- Whether edge `e` joins an old vertex and a new one, by the flags.
local function old_to_new(state, e)
  local h = e.halfedge
  return (state.is_new_vertex[h.vertex.id] or false) ~= (state.is_new_vertex[h.twin.vertex.id] or false)
end

-- Phase 3: flip every new edge (flagged) that joins an old vertex and a new one.
local function phase3(mesh, state)
  state.flipped = {}
  for _, i in ipairs(state.cross) do
    if old_to_new(state, mesh:edge(i)) then
      assert(mesh:flip(mesh:edge(i)))
      state.flipped[#state.flipped + 1] = i
    end
  end
end

-- Phase 4: every vertex to its computed position.
local function phase4(mesh, state)
  for v in mesh:vertices() do v.position = state.new_position[v.id] end
end

-- A fresh cube after the first `phases` phases.
local function cube_after(phases)
  local mesh = meshedit.cube()
  local state = phase1(mesh)
  if phases >= 2 then phase2(mesh, state) end
  if phases >= 3 then phase3(mesh, state) end
  if phases >= 4 then phase4(mesh, state) end
  return mesh, state
end

-- Distances of the 8 corners (ids 0..7 survive subdivision) from the centre: smallest and largest.
local function corner_range(mesh)
  local lo, hi = math.huge, 0
  for i = 0, 7 do
    local r = mesh:vertex(i).position:length()
    lo, hi = math.min(lo, r), math.max(hi, r)
  end
  return lo, hi
end

-- The six face diagonals of the 12-triangle cube: the edges longer than 1.
local function diagonals(mesh)
  local list = {}
  for e in mesh:edges() do
    local h = e.halfedge
    if (h.vertex.position - h.twin.vertex.position):length() > 1.01 then list[#list + 1] = e end
  end
  return list
end


step({ en = "Four phases", zh = "四个阶段" }, function()
  show(meshedit.cube())
  camera "fit"
  say {
    en = [[
# Loop subdivision

Loop subdivision turns a coarse triangle mesh into a smoother one: every triangle becomes four, and every vertex
moves to a weighted average of its neighbours. Repeat it and the mesh converges to a smooth surface.]],
    zh = [[
# Loop 细分

Loop 细分把一个粗糙的三角形网格变得更光滑：每个三角形变成四个，每个顶点移到其邻点的加权平均处。反复细分，网格就收敛到一张光滑曲面。]],
  }
  say {
    en = [[
It is done in four phases, and the app's **Shift+L** runs them one at a time (L runs all four):

- **1. new positions**: compute where every old vertex goes, and where a new vertex on each edge will go
- **2. split every edge** of the original mesh (never the new ones)
- **3. flip** every new edge that joins an old vertex to a new one
- **4. move** every vertex to the position computed in phase 1]],
    zh = [[
它分四个阶段完成，应用中的 **Shift+L** 每次运行一个阶段（L 一次运行全部四个）：

- **1. 新位置**：算出每个旧顶点要去的位置，以及每条边上新顶点将在的位置
- **2. 分裂每条边**：只分裂原网格的边（从不分裂新边）
- **3. 翻转**：翻转每条连接旧顶点与新顶点的新边
- **4. 移动**：把每个顶点移到阶段 1 算出的位置]],
  }
  answer {
    { en = "The cube on screen has " .. counts(meshedit.cube()) .. ". How many vertices will it have after one step?",
      zh = "屏幕上的立方体有 " .. counts_zh(meshedit.cube()) .. "。细分一步之后它有多少个顶点？" },
    number = 26,
    tolerance = 0.5,
    feedback = function(value)
      if value == 8 then
        return { en = "8 counts only the old vertices, which stay; every edge split adds one more.",
          zh = "8 只数了旧顶点，它们会保留；每次边分裂还会再加一个。" }
      end
      if value == 32 then
        return { en = "Faces are multiplied by four, vertices are not: the old ones stay and each edge adds one.",
          zh = "乘以四的是面数，不是顶点数：旧顶点保留，每条边再加一个。" }
      end
      if value == 20 then
        return { en = "20 = 8 + 12 counts a new vertex per face; phase 2 splits edges, one vertex each.",
          zh = "20 = 8 + 12 是每个面算一个新顶点；而阶段 2 分裂的是边，每条边一个顶点。" }
      end
      if value == 44 then
        return { en = "44 = 8 + 36 counts two new vertices per edge: a split adds one.",
          zh = "44 = 8 + 36 是每条边算两个新顶点：一次分裂只加一个。" }
      end
    end,
    hint = { en = "The old vertices stay; phase 2 adds one vertex per original edge.",
      zh = "旧顶点保留；阶段 2 在每条原有边上加一个顶点。" },
  }
  say({ en = "Yes: V' = V + E. And E' = 2E + 3F, F' = 4F. The cube has " .. counts(meshedit.cube())
    .. ", so one step gives 26 vertices, 72 edges and 48 faces. Press **Next** to watch each phase.",
    zh = "对：V' = V + E。并且 E' = 2E + 3F，F' = 4F。立方体有 " .. counts_zh(meshedit.cube())
      .. "，所以细分一步得到 26 个顶点、72 条边和 48 个面。按 **下一步** 逐个观察每个阶段。" })
end)

step({ en = "Phase 1: new positions", zh = "阶段 1：新位置" }, function()
  local mesh, state = cube_after(1)
  show(mesh)
  local v0 = mesh:vertex(0)
  local e0 = mesh:edge(0)
  highlight(v0, "yellow")
  highlight(e0, "orange")
  label(v0, { en = "degree " .. v0:degree(), zh = "度数 " .. v0:degree() })
  say {
    en = [[
Every position is computed from the **original** mesh, before anything changes (that is why this phase
only stores numbers):

- an old vertex p with n neighbours q1..qn moves to (1 - n u) p + u (q1 + ... + qn),
  with u = 3/16 when n = 3 and u = 3/(8n) otherwise
- the new vertex on an edge a-b, with c and d the corners opposite it, goes to 3/8 (a + b) + 1/8 (c + d)]],
    zh = [[
每个位置都由 **原始** 网格算出，在任何改动之前（所以这个阶段只存下数字）：

- 有 n 个邻点 q1..qn 的旧顶点 p 移到 (1 - n u) p + u (q1 + ... + qn)，其中 n = 3 时 u = 3/16，否则 u = 3/(8n)
- 边 a-b 上的新顶点（c 和 d 是与它相对的两个角点）位于 3/8 (a + b) + 1/8 (c + d)]],
  }
  answer {
    { en = "The yellow vertex v0 has 6 neighbours. What is u for it?",
      zh = "黄色顶点 v0 有 6 个邻点。它的 u 是多少？" },
    number = 1 / 16,
    feedback = function(value)
      if math.abs(value - 3 / 16) < 1e-3 then
        return { en = "3/16 is u for n = 3 only. For every n > 3, u = 3/(8n).",
          zh = "3/16 只是 n = 3 时的 u。对每个 n > 3，u = 3/(8n)。" }
      end
      if math.abs(value - 1 / 6) < 1e-3 then
        return { en = "1/6 = 1/n would make n u = 1: v0's own weight 1 - n u would be 0, and it would jump to the "
          .. "plain average of its neighbours. Loop keeps part of the vertex itself: u = 3/(8n).",
          zh = "1/6 = 1/n 会使 n u = 1：v0 自身的权重 1 - n u 就成了 0，它会直接跳到邻点的简单平均处。"
            .. "Loop 细分保留顶点自身的一部分：u = 3/(8n)。" }
      end
      if math.abs(value - 3 / 8) < 1e-3 then
        return { en = "3/8 is n u, what all six neighbours weigh together; each one gets u = 3/(8n).",
          zh = "3/8 是 n u，即全部六个邻点合起来的权重；每个邻点得到 u = 3/(8n)。" }
      end
      if math.abs(value - 5 / 8) < 1e-3 then
        return { en = "5/8 = 1 - n u is the weight v0 keeps for itself.", zh = "5/8 = 1 - n u 是 v0 留给自己的权重。" }
      end
    end,
    hint = { en = "u = 3/(8n) for n > 3: put in n = 6.", zh = "n > 3 时 u = 3/(8n)：代入 n = 6。" },
  }
  say({ en = "u = 3/48 = 1/16, and n u = 6/16 = **3/8**. That is so for every n > 3: n u = 3n/(8n) = 3/8, "
    .. "whatever the degree. The vertex keeps 5/8 of its own position and its neighbours share the other 3/8, "
    .. "however many they are; the weights always sum to 1, so a flat patch stays flat. (n = 3 is the exception: "
    .. "u = 3/16, n u = 9/16.)",
    zh = "u = 3/48 = 1/16，而 n u = 6/16 = **3/8**。对每个 n > 3 都是如此：n u = 3n/(8n) = 3/8，"
      .. "与度数无关。顶点保留自身位置的 5/8，其余 3/8 由邻点分摊，不论邻点有多少个；权重之和总是 1，"
      .. "所以平坦的一片仍然平坦。（n = 3 是例外：u = 3/16，n u = 9/16。）" })
  plot {
    title = { en = "n u, the neighbours' total weight", zh = "n u：邻点的总权重" },
    x = { 3, 12 }, y = { 0, 1 }, samples = 90,
    curves = {
      { label = { en = "course: n u, with u = 3/(8n) (3/16 at n = 3)",
        zh = "本课程：n u，其中 u = 3/(8n)（n = 3 时为 3/16）" }, colour = "blue",
        fn = function(n) return n < 3.5 and 9 / 16 or 3 / 8 end },
      { label = { en = "Loop's own: n beta(n)", zh = "Loop 原始的：n beta(n)" }, colour = "orange",
        fn = function(n) return 5 / 8 - (3 / 8 + 1 / 4 * math.cos(2 * math.pi / n)) ^ 2 end },
      { label = { en = "n u with u = 1/n (no weight kept)", zh = "u = 1/n 时的 n u（不保留自身权重）" },
        colour = "grey", fn = function() return 1 end },
    },
  }
  say({ en = "The yellow vertex `v0` has " .. v0:degree() .. " neighbours, so u = " .. fmt(state.u[0])
    .. ": it will go from " .. tostring(v0.position) .. " to " .. tostring(state.vertex[0])
    .. ". The new vertex on the orange edge `e0` will sit at " .. tostring(state.edge[0]) .. ".",
    zh = "黄色顶点 `v0` 有 " .. v0:degree() .. " 个邻点，所以 u = " .. fmt(state.u[0]) .. "：它将从 "
      .. tostring(v0.position) .. " 移到 " .. tostring(state.vertex[0]) .. "。橙色边 `e0` 上的新顶点将位于 "
      .. tostring(state.edge[0]) .. "。" })
  say { en = "Nothing on screen has moved yet: phase 1 only computes.", zh = "屏幕上还什么都没动：阶段 1 只做计算。" }
end)

step({ en = "Phase 2: split every edge", zh = "阶段 2：分裂每条边" }, function()
  show(meshedit.cube())
  choose {
    { en = "Phase 2 splits edges. Which ones?", zh = "阶段 2 分裂边。分裂哪些？" },
    options = { { en = "The 18 original edges", zh = "原有的 18 条边" },
      { en = "Every edge, new ones too", zh = "每条边，包括新边" },
      { en = "Only the edges phase 3 flips", zh = "只分裂阶段 3 要翻转的边" } },
    answer = "The 18 original edges",
    feedback = {
      ["Every edge, new ones too"] = { en = "Each split adds three edges; if those were split too, "
        .. "the loop would never end (and each face would be cut far more than into four).",
        zh = "每次分裂增加三条边；如果这些边也被分裂，循环就永远不会结束（每个面也会被切成远多于四块）。" },
      ["Only the edges phase 3 flips"] = { en = "The edges phase 3 flips do not exist yet: splits make them. "
        .. "Phase 2 splits every edge of the mesh as it was before phase 2.",
        zh = "阶段 3 要翻转的边现在还不存在：它们是分裂产生的。阶段 2 分裂的是阶段 2 开始之前网格上的每条边。" },
      ["The 18 original edges"] = { en = "Only those: list them before the first split.",
        zh = "只分裂这些：在第一次分裂之前把它们列出来。" },
    },
    hint = { en = "Each split adds edges. What happens if the loop visits them too?",
      zh = "每次分裂都会增加边。如果循环也访问这些边，会发生什么？" },
  }
  local mesh, state = cube_after(2)
  show(mesh)
  for v in mesh:vertices() do if state.is_new_vertex[v.id] then highlight(v, "yellow") end end
  for _, i in ipairs(state.cross) do highlight(mesh:edge(i), "orange") end
  say({ en = "Every one of the " .. state.E .. " original edges has been split with the same split as part 5. The mesh "
    .. "now has " .. counts(mesh) .. ": the new vertices (yellow) still sit at the edge midpoints.",
    zh = "原有的 " .. state.E .. " 条边都已分裂，用的就是第 5 部分的边分裂。网格现在有 " .. counts_zh(mesh)
      .. "：新顶点（黄色）仍在各边的中点上。" })
  say {
    en = [[
As it splits, the lesson's phase 2 **flags** what is new: the vertex m of each split (yellow), and the two
edges from m to the corners across, m-c and m-d (orange). The two halves of the split edge, a-m and m-b, are
not new: they lie along an original edge. Flags, not ids: split keeps e's id for the half m-b and gives the
half a-m a new id, so "an id past the original count" does not mean "a new edge".]],
    zh = [[
本课的阶段 2 在分裂的同时用 **标记** 记下哪些是新的：每次分裂的顶点 m（黄色），以及从 m 连到对面两个角点的两条边
m-c 和 m-d（橙色）。被分裂边的两段 a-m 和 m-b 不是新的：它们沿着一条原有边。要靠标记，而不是 id：split 让
m-b 这一段保留 e 的 id，给 a-m 这一段一个新 id，所以「id 超出原有数目」并不意味着「新边」。]],
  }
end)

step({ en = "Phase 3: which edges flip", zh = "阶段 3：翻转哪些边" }, function()
  local mesh, state = cube_after(2)
  show(mesh)
  view { halfedges = false, wireframe = true }  -- edges drawn, no arrows over them: a click picks an edge
  for v in mesh:vertices() do if state.is_new_vertex[v.id] then highlight(v, "yellow") end end
  say {
    en = [[
Here is the cube after phase 2 again; the new vertices are yellow, the old ones (the cube's corners) are not.
Phase 3 flips every **new** edge that joins an old vertex and a new one.]],
    zh = [[
这又是阶段 2 之后的立方体；新顶点是黄色的，旧顶点（立方体的角点）不是。阶段 3 翻转每条连接旧顶点与新顶点的 **新** 边。]],
  }
  pick {
    { en = "Which of these edges should be flipped? Click one.", zh = "这些边中哪一条应当翻转？点击一条。" },
    answer = function(x)
      if x.kind == "halfedge" then x = x.edge end  -- an arrow stands for its edge
      if x.kind ~= "edge" then
        local kinds = { vertex = "顶点", face = "面", halfedge = "半边", edge = "边" }
        return false, { en = "That is a " .. x.kind .. ": click an edge.",
          zh = "这是一个" .. (kinds[x.kind] or (" " .. x.kind)) .. "：请点击一条边。" }
      end
      if state.is_new_edge[x.id] and old_to_new(state, x) then
        return true, { en = "Yes: a new edge from a corner across an old face to a new vertex.",
          zh = "对：这是一条新边，从一个角点穿过一个旧面连到一个新顶点。" }
      end
      if state.is_new_edge[x.id] then
        return false, { en = "Both ends of this edge are new vertices: it is an edge of an old triangle's middle "
          .. "triangle, and stays as it is.",
          zh = "这条边的两端都是新顶点：它是某个旧三角形中间那个小三角形的边，保持不变。" }
      end
      return false, { en = "This edge joins an old corner to a new vertex, but it is a half of a split original edge "
        .. "(a-m or m-b), not a new edge. Subdivision keeps the original edges, in two halves; flipping a half "
        .. "would swap it for an edge across two old triangles, and those would no longer be four triangles "
        .. "each. Only the flags tell the halves from the new edges.",
        zh = "这条边连接一个旧角点和一个新顶点，但它是一条被分裂的原有边的一段（a-m 或 m-b），不是新边。"
          .. "细分保留原有边，只是分成两段；翻转其中一段会把它换成一条横跨两个旧三角形的边，"
          .. "那两个旧三角形就不再各自被分成四个三角形了。只有标记能把这些段和新边区分开。" }
    end,
    hint = { en = "Look for an edge that cuts across one of the cube's old triangles, from a corner to a yellow "
      .. "vertex.",
      zh = "找一条横穿立方体某个旧三角形、从一个角点连到一个黄色顶点的边。" },
  }
  mesh, state = cube_after(3)
  show(mesh)
  clear()
  for _, i in ipairs(state.flipped) do highlight(mesh:edge(i), "orange") end
  say({ en = "Of the " .. #state.cross .. " edges the splits made across faces, " .. #state.flipped .. " joined an old "
    .. "vertex to a new one; those are flipped (orange). Now every old triangle is cut into four: three at its "
    .. "corners and one in the middle, whose edges join new vertices only.",
    zh = "分裂在面内产生的 " .. #state.cross .. " 条边中，有 " .. #state.flipped .. " 条连接旧顶点与新顶点；"
      .. "这些边被翻转了（橙色）。现在每个旧三角形都被分成四个：三个在角上，一个在中间，"
      .. "中间那个的边只连接新顶点。" })
  say({ en = "The counts have not changed (" .. counts(mesh) .. "): a flip creates nothing. The mesh passes "
    .. "validation: " .. tostring(mesh:validate()) .. ".",
    zh = "数目没有变（" .. counts_zh(mesh) .. "）：翻转不产生任何元素。网格通过验证："
      .. tostring(mesh:validate()) .. "。" })
end)

step({ en = "Phase 4: move", zh = "阶段 4：移动" }, function()
  local mesh = cube_after(3)
  show(mesh)
  view { halfedges = true }  -- back on after phase 3's question turned them off
  choose {
    { en = "Phase 4 moves every vertex to a position phase 1 computed. Why compute them in phase 1, before any split, "
      .. "and not now?",
      zh = "阶段 4 把每个顶点移到阶段 1 算出的位置。为什么要在阶段 1、在任何分裂之前算出这些位置，而不是现在才算？" },
    options = { { en = "The neighbours have changed", zh = "邻点已经变了" },
      { en = "Splits would move stored positions", zh = "分裂会改动存下的位置" },
      { en = "It is only faster", zh = "只是为了更快" } },
    answer = "The neighbours have changed",
    feedback = {
      ["Splits would move stored positions"] = { en = "Splits and flips change pointers, and "
        .. "a split only places m at a midpoint; the stored positions are numbers, nothing moves them. The "
        .. "question is what the weights would read now.",
        zh = "分裂和翻转改的是指针，而分裂只是把 m 放在中点；存下的位置只是数字，什么也不会改动它们。"
          .. "问题在于：现在计算的话，权重读到的会是哪些点。" },
      ["It is only faster"] = { en = "It is not about speed: computed now, the result would be wrong. Look at "
        .. "v0's neighbours on screen.",
        zh = "这与速度无关：现在才算，结果会是错的。看看屏幕上 v0 的邻点。" },
      ["The neighbours have changed"] = { en = "Right: the weights are "
        .. "defined on the original mesh; after phase 2 an old vertex is joined only to new vertices.",
        zh = "对：权重是在原始网格上定义的；阶段 2 之后，旧顶点只与新顶点相连。" },
    },
    hint = { en = "Select v0 and look at what it is joined to now.", zh = "选中 v0，看看它现在与哪些顶点相连。" },
  }
  mesh = cube_after(4)
  show(mesh)
  local reference = meshedit.cube()
  reference:loop_subdivide()
  local worst = 0
  for v in reference:vertices() do
    worst = math.max(worst, (v.position - mesh:vertex(index(v)).position):length())
  end
  say({ en = "Every vertex moves to its phase-1 position: the cube turns into a rounder blob of "
    .. counts(mesh) .. ".",
    zh = "每个顶点都移到了它在阶段 1 算出的位置：立方体变成了一个更圆的团块，有 " .. counts_zh(mesh) .. "。" })
  if worst < 1e-9 and reference:num_faces() == mesh:num_faces() then
    say({ en = "These four phases, written in Lua in this lesson, give exactly the mesh the app's **L** gives: "
      .. "the same counts, and every vertex at the same place. Your `upsample` must do the same.",
      zh = "本课用 Lua 写的这四个阶段，得到的网格与应用中 **L** 得到的完全相同：数目相同，每个顶点的位置也相同。"
        .. "你的 `upsample` 也必须做到这一点。" })
  else
    say({ en = "The Lua phases differ from the app's L by " .. fmt(worst) .. ".",
      zh = "Lua 写的各阶段与应用中的 L 相差 " .. fmt(worst) .. "。" })
  end
end)

local PHASE_NAMES = { "compute new positions", "split every original edge",
  "flip new edges joining an old and a new vertex", "move every vertex to its new position" }
local PHASE_NAMES_ZH = { "计算新位置", "分裂每条原有边", "翻转连接旧顶点与新顶点的新边", "把每个顶点移到新位置" }

-- Whether `mesh` is `expected`: the same counts, every vertex at the same place and every edge between the same
-- two vertices (ids compared, as the app's phases and the Lua ones number alike). False for anything else.
local function same_mesh(mesh, expected)
  if not mesh or mesh:num_vertices() ~= expected:num_vertices() or mesh:num_edges() ~= expected:num_edges()
    or mesh:num_faces() ~= expected:num_faces() then
    return false
  end
  local ok, same = pcall(function()
    for v in expected:vertices() do
      if (mesh:vertex(index(v)).position - v.position):length() > 1e-9 then return false end
    end
    for e in expected:edges() do
      local h, g = e.halfedge, mesh:edge(index(e)).halfedge
      local a, b, c, d = index(h.vertex), index(h.twin.vertex), index(g.vertex), index(g.twin.vertex)
      if not ((a == c and b == d) or (a == d and b == c)) then return false end
    end
    return true
  end)
  return ok and same
end

-- What phase `phase` did to the cube on screen (`mesh`), with the elements it touched marked; { en =, zh = }.
local function phase_report(phase, mesh, state)
  clear()
  if phase == 1 then
    return { en = "Phase 1 computed every new position and changed nothing: the cube still has " .. counts(mesh) .. ".",
      zh = "阶段 1 算出了每个新位置，什么也没改：立方体仍有 " .. counts_zh(mesh) .. "。" }
  elseif phase == 2 then
    for v in mesh:vertices() do if state.is_new_vertex[v.id] then highlight(v, "yellow") end end
    return { en = "Phase 2 split all " .. state.E .. " original edges: now " .. counts(mesh) .. ", the new vertices "
      .. "(yellow) still at the midpoints.",
      zh = "阶段 2 分裂了全部 " .. state.E .. " 条原有边：现在有 " .. counts_zh(mesh) .. "，新顶点（黄色）仍在中点上。" }
  elseif phase == 3 then
    for _, i in ipairs(state.flipped) do highlight(mesh:edge(i), "orange") end
    return { en = "Phase 3 flipped the " .. #state.flipped .. " new edges joining an old and a new vertex (orange): "
      .. "still " .. counts(mesh) .. ".",
      zh = "阶段 3 翻转了 " .. #state.flipped .. " 条连接旧顶点与新顶点的新边（橙色）：仍是 " .. counts_zh(mesh)
        .. "。" }
  end
  highlight(mesh:vertex(0), "yellow")
  return { en = "Phase 4 moved every vertex: v0 went from " .. tostring(meshedit.cube():vertex(0).position) .. " to "
    .. tostring(mesh:vertex(0).position) .. ".",
    zh = "阶段 4 移动了每个顶点：v0 从 " .. tostring(meshedit.cube():vertex(0).position) .. " 移到了 "
      .. tostring(mesh:vertex(0).position) .. "。" }
end

step({ en = "The app's phases: Shift+L", zh = "应用中的各阶段：Shift+L" }, function()
  show(meshedit.cube())
  camera "fit"
  say {
    en = [[
Now run the four phases yourself on a fresh cube: press **Shift+L** four times (the status bar names each phase).
After each press this lesson compares the mesh on screen with its own Lua phases.]],
    zh = [[
现在在一个新的立方体上亲自运行这四个阶段：按四次 **Shift+L**（状态栏会显示每个阶段的名称）。每按一次，本课都会把屏幕上的网格与它自己用 Lua 写的各阶段比较。]],
  }
  local phase, mesh = 1, nil
  while phase <= 4 do
    wait_for { key = "shift+L", hint = { en = "Press Shift+L: phase " .. phase .. " of 4, " .. PHASE_NAMES[phase],
      zh = "按 Shift+L：第 " .. phase .. " 阶段（共 4 个），" .. PHASE_NAMES_ZH[phase] } }
    mesh = current_mesh()
    local expected, state = cube_after(phase)
    if same_mesh(mesh, expected) then
      say(phase_report(phase, mesh, state))
      phase = phase + 1
    else
      show(meshedit.cube())
      clear()
      say({ en = "That is not the cube after phase " .. phase .. " (did another key change the mesh?). Here is a fresh "
        .. "cube: press **Shift+L** again, from phase 1.",
        zh = "这不是阶段 " .. phase .. " 之后的立方体（是不是按了别的键改动了网格？）。这是一个新的立方体："
          .. "从阶段 1 开始，再按 **Shift+L**。" })
      phase = 1
    end
  end
  say({ en = "One step done: " .. counts(mesh) .. ", " .. (mesh:validate() and "valid" or "NOT valid") .. ". "
    .. "Press **L** to run all four phases at once, again and again, to watch the surface converge; "
    .. "each step multiplies the faces by four, so stop after four or five.",
    zh = "一步完成：" .. counts_zh(mesh) .. "，" .. (mesh:validate() and "有效" or "无效") .. "。按 **L** "
      .. "一次运行全部四个阶段，一再地按，观察曲面收敛；每一步都把面数乘以四，所以按四五次就停下。" })
end)

-- The degrees of corners v0..v7 of `mesh`, and the smallest and largest of them.
local function corner_degrees(mesh)
  local degrees, lo, hi = {}, math.huge, 0
  for i = 0, 7 do
    local n = mesh:vertex(i):degree()
    degrees[i] = n
    lo, hi = math.min(lo, n), math.max(hi, n)
  end
  return degrees, lo, hi
end

-- The mean distance from the centre, after two steps of L, of the corners whose degree on `mesh` is `n`.
local function mean_corner_distance(mesh, subdivided, n)
  local sum, count = 0, 0
  for i = 0, 7 do
    if mesh:vertex(i):degree() == n then
      sum, count = sum + subdivided:vertex(i).position:length(), count + 1
    end
  end
  return sum / count
end

step({ en = "The cube's lopsided result", zh = "立方体不对称的结果" }, function()
  local mesh = meshedit.cube()
  local subdivided = mesh:copy()
  subdivided:loop_subdivide()
  subdivided:loop_subdivide()
  show(subdivided)
  camera "fit"
  local lo, hi = corner_range(subdivided)
  say({ en = "Here is the cube after two steps of L. A cube is symmetric, yet the result is **lopsided**: after two "
    .. "steps the 8 corners are between " .. fmt(lo) .. " and " .. fmt(hi) .. " from the centre. A symmetric "
    .. "input would put them all at the same distance.",
    zh = "这是按两次 L 之后的立方体。立方体是对称的，结果却 **不对称**：两步之后，8 个角点到中心的距离在 "
      .. fmt(lo) .. " 到 " .. fmt(hi) .. " 之间。对称的输入本应让它们的距离全都相同。" })
  local right = "Corners differ in degree"
  choose {
    { en = "Why is it lopsided? (degree: a vertex's number of neighbours)",
      zh = "为什么会不对称？（度数：一个顶点的邻点个数）" },
    options = { { en = "Rounding error", zh = "舍入误差" }, { en = "Splitting in id order", zh = "按 id 顺序分裂" },
      { en = right, zh = "各角点的度数不同" }, { en = "Corners at different distances", zh = "角点到中心的距离不同" } },
    answer = right,
    feedback = {
      ["Rounding error"] = { en = string.format("The corners differ by %.3f; rounding in double "
        .. "precision is about 1e-16. Something in the mesh itself differs from corner to corner.", hi - lo),
        zh = string.format("各角点相差 %.3f；双精度的舍入误差约为 1e-16。是网格本身有某样东西因角点而异。", hi - lo) },
      ["Splitting in id order"] = { en = "Phase 1 computes every "
        .. "position from the original mesh before the first split, so the order of the splits cannot move "
        .. "anything; it only decides the new ids.",
        zh = "阶段 1 在第一次分裂之前就由原始网格算出了每个位置，所以分裂的顺序不会让任何点移动；"
          .. "它只决定新的 id。" },
      ["Corners at different distances"] = { en = "They are not: every corner of the "
        .. "cube is " .. fmt(mesh:vertex(0).position:length()) .. " from the centre before subdividing. Look at "
        .. "how each corner is connected instead.",
        zh = "并非如此：细分之前，立方体的每个角点到中心的距离都是 " .. fmt(mesh:vertex(0).position:length())
          .. "。不妨看看每个角点是怎样连接的。" },
      [right] = { en = "Right: the cube's 12 triangles cut each square face along one diagonal.",
        zh = "对：立方体的 12 个三角形是把每个正方形面沿一条对角线切开得到的。" },
    },
    hint = { en = "The rule for an old vertex depends on one number per vertex. Is it the same at every corner?",
      zh = "旧顶点的规则取决于每个顶点的一个数。这个数在每个角点都相同吗？" },
  }
  local degrees, low, high = corner_degrees(mesh)
  for i = 0, 7 do label(subdivided:vertex(i), { en = "degree " .. degrees[i], zh = "度数 " .. degrees[i] }) end
  local at_high, at_low = mean_corner_distance(mesh, subdivided, high), mean_corner_distance(mesh, subdivided, low)
  local high_option, low_option = "The degree-" .. high .. " corners", "The degree-" .. low .. " corners"
  local high_text = { en = high_option, zh = "度数为 " .. high .. " 的角点" }
  local low_text = { en = low_option, zh = "度数为 " .. low .. " 的角点" }
  local nearer, farther = high_option, low_option
  if at_low < at_high then nearer, farther = low_option, high_option end
  local pull = meshedit.vec3(0, 0, 0)
  for w in mesh:vertex(0):neighbors() do pull = pull + w.position end
  pull = pull / mesh:vertex(0):degree()
  choose {
    { en = "Each corner is labelled with its degree on the cube before subdividing. After the two steps, which corners "
      .. "are nearer the centre?",
      zh = "每个角点都标出了它在细分之前的立方体上的度数。两步之后，哪些角点离中心更近？" },
    options = { high_text, low_text, { en = "All at the same distance", zh = "距离全都相同" } },
    answer = nearer,
    feedback = {
      [farther] = { en = "They stay farther out. Corner v0 (degree " .. degrees[0] .. ") is joined to three "
        .. "corners along "
        .. "the cube's edges and to others across the faces' diagonals, and its neighbours average to "
        .. tostring(pull) .. ": how far is that from the centre?",
        zh = "它们留在更外面。角点 v0（度数 " .. degrees[0] .. "）沿立方体的棱与三个角点相连，"
          .. "又沿面的对角线与另一些角点相连，它的邻点平均下来是 " .. tostring(pull) .. "：这个点离中心有多远？" },
      ["All at the same distance"] = { en = "They are not: the corners are between " .. fmt(lo) .. " and " .. fmt(hi)
        .. " from the centre, and the degrees on their labels differ.",
        zh = "并非如此：各角点到中心的距离在 " .. fmt(lo) .. " 到 " .. fmt(hi) .. " 之间，标签上的度数也各不相同。" },
      [nearer] = { en = "Yes: after two steps the degree-" .. high .. " corners are " .. fmt(at_high) .. " from "
        .. "the centre "
        .. "on average, the degree-" .. low .. " ones " .. fmt(at_low) .. ".",
        zh = "对：两步之后，度数为 " .. high .. " 的角点到中心的平均距离是 " .. fmt(at_high) .. "，度数为 " .. low
          .. " 的是 " .. fmt(at_low) .. "。" },
    },
    hint = { en = "A corner moves towards the average of its neighbours. Where is that average for v0, and where for a "
      .. "corner of degree " .. low .. "?",
      zh = "角点会朝其邻点的平均位置移动。对 v0 来说这个平均位置在哪里？对度数为 " .. low .. " 的角点又在哪里？" },
  }
  for i = 0, 7 do highlight(subdivided:vertex(i), degrees[i] == high and "orange" or "yellow") end
  local list = {}
  for i = 0, 7 do list[#list + 1] = tostring(degrees[i]) end
  say({ en = "Its 12 triangles come from cutting each square face along one diagonal, so the corners do not all "
    .. "have the "
    .. "same number of neighbours: the degrees of v0 to v7 are " .. table.concat(list, ", ") .. ". The weights "
    .. "depend on that number, and so does what they average: v0's " .. degrees[0] .. " neighbours average to "
    .. tostring(pull) .. ", the centre itself, so it is pulled straight in (orange: degree " .. high .. ", yellow: "
    .. "degree " .. low .. ").",
    zh = "立方体的 12 个三角形来自把每个正方形面沿一条对角线切开，所以各角点的邻点个数并不都相同："
      .. "v0 到 v7 的度数依次是 " .. table.concat(list, ", ") .. "。权重取决于这个数，被平均的点也是："
      .. "v0 的 " .. degrees[0] .. " 个邻点平均下来是 " .. tostring(pull) .. "，恰好就是中心，"
      .. "所以它被直接拉向中心（橙色：度数 " .. high .. "，黄色：度数 " .. low .. "）。" })
end)

-- What the student's last edit did to the corners' degrees: a line for the live text, { en =, zh = }.
local function degree_report(degrees, lo, hi, before_spread, flips_only)
  local list = {}
  for i = 0, 7 do list[#list + 1] = "v" .. i .. " " .. degrees[i] end
  local now = "Degrees now: " .. table.concat(list, ", ") .. "."
  local now_zh = "现在的度数：" .. table.concat(list, ", ") .. "。"
  if hi - lo > before_spread then
    return { en = now .. " That made it worse: the corners now range from " .. lo .. " to " .. hi .. ", against "
      .. before_spread .. " apart before. A flip takes one neighbour from each end of the edge and gives one to each "
      .. "corner across.",
      zh = now_zh .. "这样更糟了：各角点的度数现在从 " .. lo .. " 到 " .. hi .. "，之前只相差 " .. before_spread
        .. "。一次翻转让边的两端各少一个邻点，让对面的两个角点各多一个。" }
  end
  if flips_only >= 3 then
    return { en = now .. " Flips alone cannot do it: they keep 8 vertices and 18 edges, so the degrees always "
      .. "add up to "
      .. "36, which is 4.5 per corner. Something must add a vertex.",
      zh = now_zh .. "只靠翻转做不到：翻转保持 8 个顶点和 18 条边，所以度数之和总是 36，"
        .. "即每个角点 4.5。必须有操作增加一个顶点。" }
  end
  return { en = now, zh = now_zh }
end

step({ en = "Make every corner alike", zh = "让每个角点都一样" }, function()
  local cube = meshedit.cube()
  show(cube)
  camera "fit"
  view { halfedges = false, wireframe = true }  -- edges to select, no arrows over them
  local degrees, lo, hi = corner_degrees(cube)
  local function label_corners(mesh)
    clear()
    for i = 0, 7 do label(mesh:vertex(i), { en = "degree " .. degrees[i], zh = "度数 " .. degrees[i] }) end
  end
  label_corners(cube)
  say {
    en = [[
Fix the input, not the rules: change the cube so that **all 8 corners have the same degree**. Select an edge and
press **F** to flip it or **S** to split it, as in parts 4 and 5, as often as you like. The labels give each
corner's degree, and they and the line below follow your edits.]],
    zh = [[
要改的是输入，不是规则：修改立方体，使 **全部 8 个角点的度数相同**。像第 4、5 部分那样，选中一条边，按
**F** 翻转它，或按 **S** 分裂它，次数不限。标签显示每个角点的度数，标签和下面那一行都会随你的编辑更新。]],
  }
  local status = { en = "Degrees now: the corners range from " .. lo .. " to " .. hi .. ".",
    zh = "现在的度数：各角点从 " .. lo .. " 到 " .. hi .. "。" }
  live(function() return status end)
  local last, spread, flips_only = cube, hi - lo, 0
  while true do
    local mesh = wait_for {
      hint = { en = "Flip (F) or split (S) edges until every corner has the same degree",
        zh = "翻转（F）或分裂（S）边，直到每个角点的度数都相同" },
      condition = function()
        local m = current_mesh()
        if m and m:num_vertices() >= 8 and #m:diff(last) > 0 then return m end
        return false
      end,
    }
    last = mesh
    if mesh:num_vertices() == 8 then flips_only = flips_only + 1 else flips_only = 0 end
    degrees, lo, hi = corner_degrees(mesh)
    label_corners(mesh)
    if lo == hi then break end
    status = degree_report(degrees, lo, hi, spread, flips_only)
    spread = hi - lo
  end
  status = { en = "Every corner has degree " .. lo .. ": " .. counts(last) .. ".",
    zh = "每个角点的度数都是 " .. lo .. "：" .. counts_zh(last) .. "。" }
  say {
    en = [[
Done: no corner is special any more. The next step shows one way that treats every face alike.]],
    zh = [[
完成：再没有哪个角点是特殊的了。下一步展示一种对每个面一视同仁的做法。]],
  }
end)

step({ en = "The pre-split fix", zh = "预分裂修正" }, function()
  local cube = meshedit.cube()
  show(cube)
  local list = diagonals(cube)
  local ids = {}
  for _, e in ipairs(list) do
    highlight(e, "yellow")
    ids[#ids + 1] = "`" .. tostring(e) .. "`"
  end
  say({ en = "A fix that treats every face alike: split each of the six yellow diagonals ("
    .. table.concat(ids, ", ") .. "): select one, press **S**, and repeat. Each square face then has a vertex in "
    .. "its middle joined to all four of its corners, and every corner has 6 neighbours.",
    zh = "一种对每个面一视同仁的修正：分裂六条黄色对角线中的每一条（" .. table.concat(ids, ", ")
      .. "）：选中一条，按 **S**，再重复。这样每个正方形面的中间都有一个顶点，与该面的四个角点全都相连，"
      .. "每个角点都有 6 个邻点。" })
  local split = wait_for {
    hint = { en = "Split all six diagonals with S", zh = "用 S 分裂全部六条对角线" },
    condition = function()
      local m = current_mesh()
      if not m or m:num_vertices() ~= 14 or not m:validate() then return false end
      for i = 0, 7 do if m:vertex(i):degree() ~= 6 then return false end end
      return m
    end,
  }
  say({ en = "All six split: " .. counts(split) .. ", and every corner has degree 6. Now press **L** twice.",
    zh = "六条都已分裂：" .. counts_zh(split) .. "，每个角点的度数都是 6。现在按两次 **L**。" })
  local mesh = wait_for {
    hint = { en = "Press L twice", zh = "按两次 L" },
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 16 * split:num_faces() and m:validate() and m
    end,
  }
  local lo, hi = corner_range(mesh)
  if hi - lo < 1e-9 then
    say({ en = "After two steps: " .. counts(mesh) .. ". All 8 corners are " .. fmt(hi) .. " from the centre: the same "
      .. "distance, a symmetric shape.",
      zh = "两步之后：" .. counts_zh(mesh) .. "。全部 8 个角点到中心的距离都是 " .. fmt(hi)
        .. "：距离相同，形状对称。" })
  else
    say({ en = "After two steps: " .. counts(mesh) .. ". The corners are between " .. fmt(lo) .. " and " .. fmt(hi)
      .. " from the centre: still not symmetric. Did every face get its middle vertex?",
      zh = "两步之后：" .. counts_zh(mesh) .. "。各角点到中心的距离在 " .. fmt(lo) .. " 到 " .. fmt(hi)
        .. " 之间：仍不对称。每个面都有了中间的顶点吗？" })
  end
end)

-- The cube after three steps, optionally with every edge at corner v7 split first; and v7's distance from the
-- centre after each step.
local function corner_run(presplit)
  local mesh = meshedit.cube()
  if presplit then
    local edges = {}
    for h in mesh:vertex(7):halfedges() do edges[#edges + 1] = h.edge end
    for _, e in ipairs(edges) do assert(mesh:split(e)) end
  end
  local radii = {}
  for level = 1, 3 do
    mesh:loop_subdivide()
    radii[level] = mesh:vertex(7).position:length()
  end
  return mesh, radii
end

-- The distance to aim for in "Sharp corners": halfway between where v7 ends on the plain cube and where it ends
-- with its edges split first, after three steps, rounded down to a hundredth.
local function sharp_target(plain, presplit) return math.floor((plain + presplit) / 2 * 100) / 100 end

step({ en = "Sharp corners", zh = "尖角" }, function()
  local cube = meshedit.cube()
  local _, plain = corner_run(false)
  local _, sharp = corner_run(true)
  local target = sharp_target(plain[3], sharp[3])
  show(cube)
  camera "fit"
  view { halfedges = false, wireframe = true }
  highlight(cube:vertex(7), "yellow")
  label(cube:vertex(7), { en = "corner v7", zh = "角点 v7" })
  say {
    en = [[
Loop subdivision **approximates**: old vertices move toward their neighbours, so a cube's sharp corners are
rounded away, and the mesh shrinks inside its control mesh.]],
    zh = [[
Loop 细分是 **逼近** 型的：旧顶点会朝邻点移动，所以立方体的尖角会被磨圆，网格也会缩到它的控制网格之内。]],
  }
  say({ en = "Every corner starts " .. fmt(cube:vertex(7).position:length()) .. " from the centre. On the plain cube, "
    .. "corner `v7` is " .. fmt(plain[1]) .. ", " .. fmt(plain[2]) .. " and " .. fmt(plain[3])
    .. " away after one, two and three steps.",
    zh = "起初每个角点到中心的距离都是 " .. fmt(cube:vertex(7).position:length()) .. "。在普通的立方体上，"
      .. "细分一步、两步、三步之后，角点 `v7` 到中心的距离分别是 " .. fmt(plain[1]) .. "、" .. fmt(plain[2])
      .. " 和 " .. fmt(plain[3]) .. "。" })
  say({ en = "Your goal: change the cube so that after **three** steps of L, corner `v7` is still at least **"
    .. string.format("%.2f", target) .. "** from the centre. Flip (F) and split (S) edges of the cube, without "
    .. "pressing L, then press **Check**: the lesson subdivides a copy three times and measures v7.",
    zh = "你的目标：修改立方体，使按 **三** 次 L 之后，角点 `v7` 到中心的距离仍至少为 **"
      .. string.format("%.2f", target) .. "**。翻转（F）和分裂（S）立方体的边，不要按 L，然后按 **检查**："
      .. "本课会把一份副本细分三次，再测量 v7。" })
  local status = { en = "Press Check when your edits are done.", zh = "编辑完成后按「检查」。" }
  live(function() return status end)
  local reached
  while not reached do
    wait_for { button = { en = "Check", zh = "检查" }, hint = { en = "Edit the cube near v7, then press Check",
      zh = "编辑 v7 附近的立方体，然后按「检查」" } }
    local mesh = current_mesh()
    if not mesh or mesh:num_faces() > 200 or not mesh:validate() then
      status = { en = "That is not an edited cube (was L pressed?): press Back for a fresh one.",
        zh = "这不是编辑过的立方体（是不是按了 L？）：按「上一步」换一个新的。" }
    else
      local copy = mesh:copy()
      for _ = 1, 3 do copy:loop_subdivide() end
      local r = copy:vertex(7).position:length()
      if r >= target then
        reached = copy
        status = { en = "Reached: after three steps v7 is " .. fmt(r) .. " from the centre.",
          zh = "达到了：三步之后 v7 到中心的距离是 " .. fmt(r) .. "。" }
      elseif #mesh:diff(cube) == 0 then
        status = { en = "That is the plain cube: v7 ends " .. fmt(r) .. " from the centre. What would keep v7's "
          .. "neighbours close to it?",
          zh = "这是普通的立方体：v7 最终到中心的距离是 " .. fmt(r) .. "。怎样才能让 v7 的邻点靠近它？" }
      else
        status = { en = "After three steps v7 is " .. fmt(r) .. " from the centre (the plain cube's: " .. fmt(plain[3])
          .. "); the goal is " .. string.format("%.2f", target) .. ". Which of your edits touch v7's neighbours?",
          zh = "三步之后 v7 到中心的距离是 " .. fmt(r) .. "（普通立方体上是 " .. fmt(plain[3]) .. "）；目标是 "
            .. string.format("%.2f", target) .. "。你的哪些编辑动到了 v7 的邻点？" }
      end
    end
  end
  show(reached)
  camera "fit"
  clear()
  highlight(reached:vertex(7), "yellow")
  label(reached:vertex(7), { en = "corner v7", zh = "角点 v7" })
  local right = "Its neighbours are nearer to it"
  choose {
    { en = "Why does v7 stay farther out now?", zh = "为什么 v7 现在留得更靠外？" },
    options = { { en = right, zh = "它的邻点离它更近了" }, { en = "Its degree went up", zh = "它的度数变大了" },
      { en = "The splits gave it a weight of its own", zh = "分裂给了它一个专属的权重" } },
    answer = right,
    feedback = {
      ["Its degree went up"] = { en = "Its degree is not what moves it: for any degree above 3 its neighbours "
        .. "weigh 3/8 "
        .. "together, however many there are (a split of an edge at v7 even keeps v7's degree: it joins v7 to the "
        .. "new vertex instead of the far end). What changed is where its neighbours are.",
        zh = "让它移动的不是度数：度数大于 3 时，无论邻点有多少个，它们合起来的权重都是 3/8"
          .. "（分裂 v7 上的一条边甚至不改变 v7 的度数：它让 v7 连到新顶点，而不再连到远端）。"
          .. "变化的是邻点所在的位置。" },
      ["The splits gave it a weight of its own"] = { en = "The rules are the same for every vertex; only what they "
        .. "average changed.",
        zh = "规则对每个顶点都一样；变的只是被平均的那些点。" },
      [right] = { en = "Yes: v7 moves toward the average of its neighbours, and they now sit close to it.",
        zh = "对：v7 朝其邻点的平均位置移动，而这些邻点现在就在它附近。" },
    },
    hint = { en = "A vertex moves toward the average of its neighbours. Where are v7's neighbours after your splits?",
      zh = "顶点会朝其邻点的平均位置移动。你分裂之后，v7 的邻点在哪里？" },
  }
  say({ en = "With every edge at v7 split first, v7 ends " .. fmt(sharp[3]) .. " from the centre after three steps, "
    .. "against " .. fmt(plain[3]) .. " on the plain cube.",
    zh = "先把 v7 上的每条边都分裂，三步之后 v7 到中心的距离是 " .. fmt(sharp[3]) .. "，而普通立方体上是 "
      .. fmt(plain[3]) .. "。" })
  say {
    en = [[
To keep a corner sharper, give the mesh more vertices near it before subdividing: the averages near it then run
over points close to it, so it rounds off less. Real creases need an extension of the rules (crease edges with
their own weights), which is beyond this assignment.]],
    zh = [[
要让一个角保持得更尖，就在细分之前给网格在它附近多加一些顶点：这样它附近的平均就取在离它很近的点上，它被磨圆得也就更少。真正的折痕需要扩展规则（带有自己权重的折痕边），这超出了本次作业的范围。]],
  }
end)

step({ en = "A mesh with a boundary", zh = "带边界的网格" }, function()
  local grid = meshedit.grid(2, 2)
  show(grid)
  camera "fit"
  highlight(grid:vertex(0), "yellow")
  label(grid:vertex(0), { en = "corner (0, 0)", zh = "角点 (0, 0)" })
  say {
    en = [[
On a mesh with a **boundary** the rules change along the border, so it stays a curve of its own:

- a boundary edge's new vertex is its midpoint, (a + b) / 2
- a boundary vertex moves to 3/4 p + 1/8 (left + right), using only its two neighbours along the boundary]],
    zh = [[
在带 **边界** 的网格上，沿边界的规则有所不同，使边界自成一条曲线：

- 边界边上的新顶点就是它的中点 (a + b) / 2
- 边界顶点移到 3/4 p + 1/8 (left + right)，只用它沿边界的两个邻点]],
  }
  say({ en = "This grid has " .. counts(grid) .. " and one boundary loop. The yellow corner is at (0, 0); its "
    .. "neighbours "
    .. "along the boundary are (1, 0) and (0, 1).",
    zh = "这个网格有 " .. counts_zh(grid) .. "，以及一个边界环。黄色角点位于 (0, 0)；它沿边界的邻点是 "
      .. "(1, 0) 和 (0, 1)。" })
  answer {
    { en = "Where will the yellow corner be after one step? Give x, y.",
      zh = "细分一步之后，黄色角点会在哪里？请给出 x, y。" },
    point = { 0.125, 0.125 },
    feedback = function(p)
      if p:length() < 1e-3 then
        return { en = "A boundary vertex moves too, along the boundary's own rule: 3/4 of itself plus 1/8 of each "
          .. "boundary neighbour.",
          zh = "边界顶点也会移动，按边界自己的规则：自身的 3/4 加上每个边界邻点的 1/8。" }
      end
      if (p - meshedit.vec3(0.25, 0.25)):length() < 1e-3 then
        return { en = "That gives each neighbour 1/4; the boundary rule gives each 1/8 and the corner 3/4.",
          zh = "这样每个邻点得到 1/4；边界规则给每个邻点 1/8，给角点自身 3/4。" }
      end
      if (p - meshedit.vec3(1 / 3, 1 / 3)):length() < 1e-2 then
        return { en = "That is the plain average of the corner and its two neighbours; the rule keeps 3/4 of the "
          .. "corner.",
          zh = "这是角点和它两个邻点的简单平均；规则保留角点自身的 3/4。" }
      end
    end,
    hint = { en = "3/4 (0, 0) + 1/8 ((1, 0) + (0, 1)).", zh = "3/4 (0, 0) + 1/8 ((1, 0) + (0, 1))。" },
  }
  say { en = "Now press **L** and check.", zh = "现在按 **L** 验证一下。" }
  local mesh = wait_for {
    hint = { en = "Press L", zh = "按 L" },
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 4 * grid:num_faces() and m:validate() and m
    end,
  }
  local p = mesh:vertex(0).position
  highlight(mesh:vertex(0), "yellow")
  label(mesh:vertex(0), { en = "corner", zh = "角点" })
  say({ en = "Now " .. counts(mesh) .. ", still " .. mesh:num_boundaries() .. " boundary loop. The corner moved from "
    .. "(0, 0, 0) to " .. tostring(p) .. ": 3/4 of itself plus 1/8 of each boundary neighbour, (1, 0, 0) and "
    .. "(0, 1, 0). The corner of the grid is cut off, as corners are on a closed mesh.",
    zh = "现在有 " .. counts_zh(mesh) .. "，仍是 " .. mesh:num_boundaries() .. " 个边界环。角点从 (0, 0, 0) 移到了 "
      .. tostring(p) .. "：自身的 3/4 加上两个边界邻点 (1, 0, 0) 和 (0, 1, 0) 各自的 1/8。"
      .. "网格的这个角被削掉了，就像封闭网格上的角一样。" })
end)

step({ en = "Your own upsample", zh = "你自己的 upsample" }, function()
  local cube = meshedit.cube()
  show(cube)
  camera "fit"
  local right = "Flags set while splitting"
  choose {
    { en = "In your upsample, how will phase 3 tell the edges to flip from the others?",
      zh = "在你的 upsample 里，阶段 3 怎样把要翻转的边和其他边区分开？" },
    options = { { en = "Ids past the original count", zh = "id 超出原有数目" },
      { en = "One old end and one new end", zh = "一端是旧顶点、一端是新顶点" },
      { en = right, zh = "分裂时设置的标记" } },
    answer = right,
    feedback = {
      ["Ids past the original count"] = { en = "split keeps e's id for the half m-b and gives the "
        .. "half a-m a new id (ea): ids past the original count include halves of original edges, which must "
        .. "not be flipped.",
        zh = "split 让 m-b 这一段保留 e 的 id，给 a-m 这一段一个新 id（ea）：超出原有数目的 id "
          .. "也包括原有边的分段，而它们不能翻转。" },
      ["One old end and one new end"] = { en = "The halves of a split edge join an old vertex and a new "
        .. "one too: that test alone flips them, the trap of phase 3. Only new edges with one old and one new end.",
        zh = "被分裂边的两段同样连接一个旧顶点和一个新顶点：只用这个判断会把它们也翻转，这正是阶段 3 的陷阱。"
          .. "只翻转一端旧、一端新的新边。" },
      [right] = { en = "Yes: flag them as you split, then flip the flagged edges with one old end and one new end.",
        zh = "对：分裂时给它们打上标记，然后翻转带标记、且一端旧一端新的边。" },
    },
    hint = { en = "Think back to the edges you could click in phase 3 that were not the answer.",
      zh = "回想一下阶段 3 中那些可以点击、却不是答案的边。" },
  }
  say {
    en = [[
Now write it: open **scripts/student/upsample.lua** in your editor. It lists the same work in five steps (its
steps 1 and 2 are phase 1 here), with the flags (is_new[v.id], is_new_edge[e.id]) and the boundary rules as extra
credit. The lesson runs your `upsample` on a copy of this cube each time you save the file and compares the
result with the reference's: it names the vertices that moved to the wrong place, the weight they moved with (a
weight like 3 // 16 is 0 in Lua), the edges flipped wrongly, and how many of the new edges you flipped against how
many the reference flips. An upsample that never ends is stopped, at the line it was running.]],
    zh = [[
现在来写代码：在编辑器中打开 **scripts/student/upsample.lua**。它把同样的工作列成五步（它的第 1、2 步就是这里的阶段
1），并附有标记（is_new[v.id]、is_new_edge[e.id]），边界规则作为附加分。每次你保存文件，本课都会在这个立方体的副本上运行你的
`upsample`，并把结果与参考实现的比较：它会指出移到错误位置的顶点、它们移动时用的权重（像
3 // 16 这样的权重在 Lua 中是 0）、翻转错的边，以及你翻转了多少条新边、参考实现又翻转了多少条。永不结束的 upsample
会被停止，并指出它当时运行到的那一行。]],
  }
  your_turn {
    exercise = "upsample",
    mesh = cube,
    hint = { en = "Compute every new position first, split only the original edges, flip only flagged new edges "
      .. "with one "
      .. "old and one new end, and write the positions last.",
      zh = "先算出每个新位置，只分裂原有边，只翻转带标记且一端旧一端新的新边，最后写入位置。" },
  }
  local tetrahedron = meshedit.tetrahedron()
  show(tetrahedron)
  camera "fit"
  say({ en = "Right on the cube, whose vertices have " .. degrees_of(cube) .. " neighbours. Every vertex of a "
    .. "tetrahedron "
    .. "has " .. degrees_of(tetrahedron) .. ", the one degree where u is not 3 / (8n): the lesson runs yours on it "
    .. "next.",
    zh = "在立方体上对了，立方体的顶点有 " .. degrees_of(cube, "、", " 或 ") .. " 个邻点。四面体的每个顶点都有 "
      .. degrees_of(tetrahedron, "、", " 或 ") .. " 个邻点，这正是 u 不等于 3 / (8n) 的那个度数：本课接下来在它上面运行你的代码。" })
  your_turn {
    exercise = "upsample",
    mesh = tetrahedron,
    hint = { en = "u = 3/16 when n = 3, and 3 / (8n) otherwise.", zh = "n = 3 时 u = 3/16，否则 u = 3 / (8n)。" },
  }
  say {
    en = [[
Your `upsample` gives the reference's mesh, up to the order you made the new elements in. The **Exercises** tab
(**X**, choose **upsample**, **Run mine**) runs it on any mesh on screen and replays its writes one by one; try it
on a mesh with a boundary for the extra credit.]],
    zh = [[
除了新元素的创建顺序外，你的 `upsample` 得到的网格与参考实现的相同。**练习** 标签页（按
**X**，选择 **upsample**，再点 **运行我的代码**）可以在屏幕上的任何网格上运行它，并逐条回放它的写入；在带边界的网格上试试，争取附加分。]],
  }
end)
