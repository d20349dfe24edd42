-- Part 5: edge split. First an interior edge (the diamond of part 4, with the same names and labels), then an edge
-- on the boundary of a grid. Each step asks the student to predict before it shows: how many edges a split makes,
-- which halfedge runs m to b afterwards, m's halfedge, which of h0's fields change, the boundary split's faces and
-- what a split does to V - E + F. After each split the lesson names the new elements, as engine/core/mesh_ops.h
-- documents them, lists every pointer the split wrote, and checks the mesh on screen. The last step runs the
-- student's own split_edge (your_turn) on a lopsided diamond, where the corners' average is not the midpoint, then
-- on the middle edge of an 80x70 grid (11200 triangles), where one that walks the whole mesh is told so.
-- CI runs it headless:
--   meshedit lesson lessons/5_edge_split.lua --headless --answers tests/lesson/lessons/5_edge_split_answers.lua \
--     --student tests/exercise/solutions
-- Invariants: the checks read the student's mesh through current_mesh() only; the new vertex is found as the
-- one vertex id the mesh did not have before (ids are appended, never reused), and the new edges, faces and
-- halfedges by split's documented order of new ids; the diagram's names are found by walking from h0, as in part 4.

lesson {
  title = { en = "Part 5: Edge split", zh = "第 5 部分：边分裂" },
  summary = {
    en = "Split an edge inside a mesh and one on its boundary: predict what changes, name every new element, "
      .. "read every pointer the split wrote.",
    zh = "分裂网格内部的一条边和边界上的一条边：先预测会改变什么，再说出每个新元素的名字，读懂分裂写下的每个指针。",
  },
}

local function diamond()
  return meshedit.from_polygons(
    { {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} },
    { {1, 2, 3}, {2, 1, 4} })
end

-- The diagram's names, by walking from e's halfedge h0 (as in part 4).
local function names_of(e)
  local n = { e = e }
  n.h0 = e.halfedge
  n.h1 = n.h0.twin
  n.h2 = n.h0.next
  n.h3 = n.h2.next
  n.h4 = n.h1.next
  n.h5 = n.h4.next
  n.h6, n.h7, n.h8, n.h9 = n.h2.twin, n.h3.twin, n.h4.twin, n.h5.twin
  n.a, n.b = n.h0.vertex, n.h1.vertex
  n.c, n.d = n.h3.vertex, n.h5.vertex
  n.f0, n.f1 = n.h0.face, n.h1.face
  return n
end

local order = { "a", "b", "c", "d", "f0", "f1", "h0", "h1", "h2", "h3", "h4", "h5", "h6", "h7", "h8", "h9" }

local shape = diamond()
local e = shape:edge(0)
local names = names_of(e)
local a, b, c, d = names.a, names.b, names.c, names.d

local function label_all()
  for _, name in ipairs(order) do label(names[name], name) end
end

-- The new elements of a split of `before`, in split's documented order (ids appended after the old ones).
local function new_names(before, after)
  local V, E, F, H = before:num_vertices(), before:num_edges(), before:num_faces(), before:num_halfedges()
  local n = { m = after:vertex(V), ea = after:edge(E), ec = after:edge(E + 1), ed = after:edge(E + 2),
    g0 = after:face(F), g1 = after:face(F + 1) }
  for k = 0, 5 do n["n" .. k] = after:halfedge(H + k) end
  return n
end

-- Diagram name of an element id ("v3" -> "d", "h12" -> "n2"), for lists in the student's words.
local function namer(extra)
  local map = {}
  for _, name in ipairs(order) do map[tostring(names[name])] = name end
  map[tostring(e)] = "e"
  for name, element in pairs(extra or {}) do map[tostring(element)] = name end
  return function(id) return map[tostring(id)] or tostring(id) end
end

local grid = meshedit.grid(2, 2)
-- The first boundary edge along the bottom row (y = 0), in id order.
local rim
for edge in grid:edges() do
  local p, q = edge.halfedge.vertex.position, edge.halfedge.twin.vertex.position
  if not rim and edge:is_boundary() and p.y == 0 and q.y == 0 then rim = edge end
end

-- The mesh on screen if it is `before` with one more vertex, and valid; else false.
local function split_done(before)
  local mesh = current_mesh()
  if not mesh or mesh:num_vertices() ~= before:num_vertices() + 1 then return false end
  if not mesh:validate() then return false end
  return mesh
end

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- The same counts in Chinese, for the zh twin of a text that uses counts().
local function counts_zh(mesh)
  return mesh:num_vertices() .. " 个顶点、" .. mesh:num_edges() .. " 条边、" .. mesh:num_faces() .. " 个面"
end

-- An element's kind in Chinese (x.kind), for pick's feedback.
local kind_zh = { vertex = "顶点", edge = "边", face = "面", halfedge = "半边" }

step({ en = "What a split does", zh = "分裂做了什么" }, function()
  show(shape)
  camera { fit = true, pitch = 55 }  -- a flat mesh: seen from above, its faces and arrows have room
  label_all()
  highlight(e, "yellow")
  say {
    en = [[
# Edge split

A split puts a new vertex **m** in the middle of an edge and joins it to the corners across the edge. Each of
the two triangles beside the edge becomes two: the mesh gains detail exactly where you ask for it.]],
    zh = [[
# 边分裂

分裂在一条边的中点放一个新顶点 **m**，再把它与边两侧各自对着这条边的那个顶点连起来。边两侧的两个三角形各自变成两个：网格恰好在你要求的地方多出细节。]],
  }
  say {
    en = [[
Here is the diamond from part 4 with the same names: the yellow edge **e** joins a and b, c is above it and d
below; h0 runs a to b in f0 = (a, b, c), h1 b to a in f1 = (b, a, d), h2 to h5 go round the two faces and
h6 to h9 are their twins on the boundary loop.]],
    zh = [[
这是第 4 部分的那个菱形，名字也一样：黄色的边 **e** 连接 a 和 b，c 在它上方，d 在它下方；h0 在 f0 = (a, b, c) 中从
a 指向 b，h1 在 f1 = (b, a, d) 中从 b 指向 a，h2 到 h5 绕着两个面走，h6 到 h9 是它们在边界环上的孪生半边（twin）。]],
  }
  choose {
    {
      en = "Splitting e puts m at the midpoint of a and b and joins it to c and d. How many edges does the mesh gain?",
      zh = "分裂 e 会把 m 放在 a 和 b 的中点，并把它与 c 和 d 相连。网格会多出几条边？",
    },
    options = { "1", "2", "3", "4" },
    answer = "3",
    feedback = {
      ["1"] = {
        en = "m is joined to c and to d: that is two edges already, and the edge from a to m is a third.",
        zh = "m 与 c 相连，也与 d 相连：这已经是两条边了，而从 a 到 m 的边是第三条。",
      },
      ["2"] = {
        en = "m-c and m-d are two, but e is now two edges, a-m and m-b: one of its halves is new too.",
        zh = "m-c 和 m-d 是两条，但 e 现在变成了 a-m 和 m-b 两条边：它的两半中也有一半是新的。",
      },
      ["4"] = {
        en = "e is not deleted: it keeps its id (and h0, h1) as the half m-b. Only a-m, m-c and m-d are new.",
        zh = "e 没有被删除：它保留自己的 id（以及 h0、h1），成为 m-b 那一半。新的只有 a-m、m-c 和 m-d。",
      },
      ["3"] = {
        en = "Three: ea (a to m), ec (m to c) and ed (m to d). e keeps its id as the half m-b.",
        zh = "三条：ea（a 到 m）、ec（m 到 c）和 ed（m 到 d）。e 保留自己的 id，成为 m-b 那一半。",
      },
    },
    hint = {
      en = "Count the edges at m after the split (four), then ask which of them is the old e.",
      zh = "数一数分裂后连在 m 上的边（四条），再想想其中哪一条是原来的 e。",
    },
  }
  say {
    en = [[
So a split of e gives:

- a new vertex **m** at the midpoint (a + b) / 2
- three new edges: **ea** (a to m), **ec** (m to c) and **ed** (m to d); e itself keeps its id as the half m to b
- two new faces: **g0** = (a, m, c) and **g1** = (m, a, d); f0 becomes (m, b, c) and f1 becomes (b, m, d)
- six new halfedges, **n0** to **n5**: a to m and back, m to c and back, m to d and back]],
    zh = [[
所以分裂 e 会得到：

- 一个新顶点 **m**，位于中点 (a + b) / 2
- 三条新边：**ea**（a 到 m）、**ec**（m 到 c）和 **ed**（m 到 d）；e 本身保留自己的 id，成为从 m 到 b 的那一半
- 两个新面：**g0** = (a, m, c) 和 **g1** = (m, a, d)；f0 变为 (m, b, c)，f1 变为 (b, m, d)
- 六条新半边 **n0** 到 **n5**：a 到 m 及其反向、m 到 c 及其反向、m 到 d 及其反向]],
  }
  say({
    en = "Counts go from " .. counts(shape) .. " to one more vertex, three more edges and two more faces.",
    zh = "网格原来有 " .. counts_zh(shape) .. "；分裂后顶点多一个，边多三条，面多两个。",
  })
end)

step({ en = "Predict the pointers", zh = "预测指针" }, function()
  show(shape)
  camera { fit = true, pitch = 55 }
  label_all()
  highlight(e, "yellow")
  say {
    en = [[
Before the split (as in part 4):

- f0 = (a, b, c): h0.next = h2, h2.next = h3, h3.next = h0
- f1 = (b, a, d): h1.next = h4, h4.next = h5, h5.next = h1
- h0.vertex = a, h1.vertex = b; e.halfedge = h0]],
    zh = [[
分裂之前（与第 4 部分相同）：

- f0 = (a, b, c)：h0.next = h2，h2.next = h3，h3.next = h0
- f1 = (b, a, d)：h1.next = h4，h4.next = h5，h5.next = h1
- h0.vertex = a，h1.vertex = b；e.halfedge = h0]],
  }
  local name = namer()
  pick {
    {
      en = "The split keeps e as the half m-b, with its own two halfedges. Click the halfedge that will run from m "
        .. "to b.",
      zh = "分裂后 e 保留下来，成为 m-b 那一半，并带着它自己的两条半边。点击分裂后将从 m 指向 b 的那条半边。",
    },
    answer = tostring(names.h0),
    feedback = function(x)
      if x.kind ~= "halfedge" then
        return {
          en = "That is a " .. x.kind .. ": click one of the arrows.",
          zh = "这是一个" .. (kind_zh[x.kind] or x.kind) .. "：请点击其中一个箭头。",
        }
      end
      local who = name(x)
      if who == "h1" then
        return {
          en = "h1 is h0's twin: it runs b to a now, and b to m after the split, the other way.",
          zh = "h1 是 h0 的孪生半边：它现在从 b 指向 a，分裂后从 b 指向 m，方向正好相反。",
        }
      elseif who == "h2" or who == "h3" or who == "h4" or who == "h5" then
        return {
          en = who .. " runs round a face from a corner that stays where it is; it does not lie along e.",
          zh = who .. " 从一个留在原处的角出发绕着面走；它不在 e 上。",
        }
      elseif who:match("^h[6-9]$") then
        return {
          en = who .. " lies on the boundary loop, outside both faces; the split does not touch it.",
          zh = who .. " 位于边界环上，在两个面之外；分裂不会动它。",
        }
      end
      return { en = who .. " does not lie along e.", zh = who .. " 不在 e 上。" }
    end,
    hint = {
      en = "e keeps its two halfedges. Which of them runs from a toward b now?",
      zh = "e 保留它的两条半边。其中哪一条现在从 a 指向 b？",
    },
  }
  say {
    en = [[
Yes: **h0** is the half m-b's halfedge toward b, so it stays in f0 (now (m, b, c)), h1 runs b to m in f1, and
the new halfedge n0 takes h0's old place from a to m.]],
    zh = [[
对：**h0** 是 m-b 那一半上指向 b 的半边，所以它仍在 f0 中（f0 现在是 (m, b, c)），h1 在 f1 中从 b 指向 m，而新半边
n0 接替 h0 原来的位置，从 a 指向 m。]],
  }
  choose {
    {
      en = "m needs a halfedge leaving it. Which one does MeshEdit's split give it?",
      zh = "m 需要一条从它出发的半边。MeshEdit 的分裂给它的是哪一条？",
    },
    options = {
      { en = "n0 (a to m)", zh = "n0（a 到 m）" },
      { en = "n1 (m to a)", zh = "n1（m 到 a）" },
      { en = "n2 (m to c)", zh = "n2（m 到 c）" },
      { en = "n3 (c to m)", zh = "n3（c 到 m）" },
    },
    answer = "n1 (m to a)",
    feedback = {
      ["n0 (a to m)"] = {
        en = "n0 runs from a to m: it arrives at m. A vertex's halfedge leaves it (h.vertex is the "
          .. "vertex h leaves).",
        zh = "n0 从 a 指向 m：它是到达 m 的。一个顶点的半边从这个顶点出发（h.vertex 是 h 出发的那个顶点）。",
      },
      ["n3 (c to m)"] = {
        en = "n3 runs from c to m: it arrives at m. A vertex's halfedge leaves it.",
        zh = "n3 从 c 指向 m：它是到达 m 的。一个顶点的半边从这个顶点出发。",
      },
      ["n2 (m to c)"] = {
        en = "n2 leaves m, but along ec, a new edge across f0. MeshEdit's split gives m n1, which "
          .. "runs along the edge it split, toward a; the checker accepts either halfedge leaving m along that edge "
          .. "(n1 toward a, or h0 toward b), and no other.",
        zh = "n2 确实从 m 出发，但它沿着 ec，一条横穿 f0 的新边。MeshEdit 的分裂给 m 的是 n1，它沿着被分裂的边指向 a；"
          .. "检查程序接受沿这条边从 m 出发的任意一条半边（指向 a 的 n1，或指向 b 的 h0），不接受其他半边。",
      },
      ["n1 (m to a)"] = {
        en = "n1 leaves m along the split edge, toward a. That is the reference's choice; the checker "
          .. "also accepts h0, which leaves m along the same edge toward b.",
        zh = "n1 沿着被分裂的边从 m 出发，指向 a。这是参考实现的选择；检查程序也接受 h0，它沿同一条边从 m 出发，指向 b。",
      },
    },
    hint = {
      en = "Two of the four leave m. Of those, one runs along the edge that was split.",
      zh = "四条里有两条从 m 出发。这两条中，有一条沿着被分裂的那条边。",
    },
  }
end)

step({ en = "Split the middle edge", zh = "分裂中间的边" }, function()
  show(shape)
  camera { fit = true, pitch = 55 }
  for element, text in pairs({ [a] = "a", [b] = "b", [c] = "c", [d] = "d" }) do label(element, text) end
  highlight(e, "yellow")
  say({
    en = "Click the yellow edge (`" .. tostring(e) .. "`) to select it.",
    zh = "点击黄色的边（`" .. tostring(e) .. "`）选中它。",
  })
  wait_for { selection = tostring(e), hint = { en = "Click the edge between a and b", zh = "点击 a 和 b 之间的边" } }
  say { en = "Now press **S** to split it.", zh = "现在按 **S** 键分裂它。" }
  local mesh = wait_for {
    condition = function() return split_done(shape) end,
    hint = { en = "Select the edge, press S", zh = "选中这条边，按 S 键" },
  }
  local new = new_names(shape, mesh)
  local m = new.m
  local p = m.position
  local mid = (a.position + b.position) / 2
  if (p - mid):length() > 1e-9 then
    say({
      en = "Hmm: the new vertex is at " .. tostring(p) .. ", not at the midpoint " .. tostring(mid) .. ".",
      zh = "嗯：新顶点在 " .. tostring(p) .. "，而不在中点 " .. tostring(mid) .. "。",
    })
    return
  end
  label(m, "m")
  highlight(m, "yellow")
  highlight({ new.ea, new.ec, new.ed }, "orange")
  for _, n in ipairs({ "ea", "ec", "ed", "g0", "g1" }) do label(new[n], n) end
  say({
    en = "Split. The new vertex **m** is `" .. tostring(m) .. "` at " .. tostring(p) .. ", the midpoint of a and b. "
      .. "It has " .. m:degree() .. " neighbours: a, b, c and d.",
    zh = "分裂完成。新顶点 **m** 是 `" .. tostring(m) .. "`，位于 " .. tostring(p) .. "，即 a 和 b 的中点。"
      .. "它有 " .. m:degree() .. " 个相邻顶点：a、b、c 和 d。",
  })
  say({
    en = "New ids are appended after the old ones: edges ea = `" .. tostring(new.ea) .. "`, ec = `" .. tostring(new.ec)
      .. "`, ed = `" .. tostring(new.ed) .. "`; faces g0 = `" .. tostring(new.g0) .. "` and g1 = `"
      .. tostring(new.g1) .. "`; halfedges n0 to n5 = `" .. tostring(new.n0) .. "` to `" .. tostring(new.n5) .. "`. "
      .. "The mesh now has " .. counts(mesh) .. ", and it passes validation.",
    zh = "新的 id 接在旧 id 之后：边 ea = `" .. tostring(new.ea) .. "`、ec = `" .. tostring(new.ec)
      .. "`、ed = `" .. tostring(new.ed) .. "`；面 g0 = `" .. tostring(new.g0) .. "` 和 g1 = `"
      .. tostring(new.g1) .. "`；半边 n0 到 n5 = `" .. tostring(new.n0) .. "` 到 `" .. tostring(new.n5) .. "`。"
      .. "现在网格有 " .. counts_zh(mesh) .. "，并且通过了验证。",
  })
  local h = mesh:element(tostring(e)).halfedge
  say({
    en = "The old edge e kept its id and now runs from " .. tostring(h.vertex) .. " (m) to "
      .. tostring(h.twin.vertex) .. " (b).",
    zh = "原来的边 e 保留了它的 id，现在从 " .. tostring(h.vertex) .. "（m）指向 "
      .. tostring(h.twin.vertex) .. "（b）。",
  })
end)

step({ en = "Before and after, pointer by pointer", zh = "分裂前后，逐个指针对照" }, function()
  local after = current_mesh()
  if not after or after:num_vertices() ~= shape:num_vertices() + 1 then
    after = shape:copy()
    after:split(after:edge(0))
    show(after)
    say {
      en = "(The mesh on screen was not the split diamond, so here it is split again.)",
      zh = "（屏幕上的网格不是分裂后的菱形，所以这里重新分裂一次。）",
    }
  end
  local new = new_names(shape, after)
  local name = namer(new)
  for _, n in ipairs({ "h0", "h1", "h2", "h3", "h4", "h5" }) do label(after:element(tostring(names[n])), n) end
  for k = 0, 5 do label(new["n" .. k], "n" .. k) end
  label(new.m, "m")
  choose {
    { en = "Which of h0's fields did the split change?", zh = "分裂改变了 h0 的哪个字段？" },
    options = { "next", "twin", "vertex", "face" },
    answer = "vertex",
    feedback = {
      next = {
        en = "h0.next is still h2: f0 is now (m, b, c), h0 -> h2 -> n3, and h2 follows h0 as before.",
        zh = "h0.next 仍是 h2：f0 现在是 (m, b, c)，h0 -> h2 -> n3，h2 和以前一样跟在 h0 后面。",
      },
      twin = {
        en = "h0's twin is still h1: e keeps both its halfedges as the half m-b.",
        zh = "h0 的 twin 仍是 h1：e 成为 m-b 那一半，两条半边都保留了下来。",
      },
      face = {
        en = "h0 stays in f0; it is f0's corners that change, from (a, b, c) to (m, b, c).",
        zh = "h0 仍在 f0 中；变的是 f0 的角，从 (a, b, c) 变为 (m, b, c)。",
      },
      vertex = { en = "Only h0.vertex: it was a, now it is m.", zh = "只有 h0.vertex：原来是 a，现在是 m。" },
    },
    hint = {
      en = "h0 still runs toward b inside f0. What about where it starts?",
      zh = "h0 仍在 f0 内指向 b。那它的起点呢？",
    },
  }
  local changes = after:diff(shape)
  local old_lines, old_lines_zh = {}, {}
  for _, change in ipairs(changes) do
    if not new[name(change.element)] then
      old_lines[#old_lines + 1] = "- " .. name(change.element) .. "." .. change.field .. ": " .. name(change.before)
        .. " to " .. name(change.after)
      old_lines_zh[#old_lines_zh + 1] = "- " .. name(change.element) .. "." .. change.field .. "：由 "
        .. name(change.before) .. " 变为 " .. name(change.after)
    end
  end
  say({
    en = "Every field of an old element the split changed (" .. #old_lines .. "), in the diagram's names:\n\n"
      .. table.concat(old_lines, "\n"),
    zh = "分裂改变的旧元素字段共 " .. #old_lines .. " 个，用图中的名字列出：\n\n" .. table.concat(old_lines_zh, "\n"),
  })
  say {
    en = [[
And the new elements' pointers (twins h0/h1, n0/n1, n2/n3, n4/n5):

- f0 = (m, b, c): h0 -> h2 -> n3
- g0 = (a, m, c): n0 -> n2 -> h3
- f1 = (b, m, d): h1 -> n4 -> h5
- g1 = (m, a, d): n1 -> h4 -> n5
- ea.halfedge = n0, ec.halfedge = n2, ed.halfedge = n4, m.halfedge = n1; a.halfedge = n0 if it was h0]],
    zh = [[
再看新元素的指针（互为 twin 的有 h0/h1、n0/n1、n2/n3、n4/n5）：

- f0 = (m, b, c)：h0 -> h2 -> n3
- g0 = (a, m, c)：n0 -> n2 -> h3
- f1 = (b, m, d)：h1 -> n4 -> h5
- g1 = (m, a, d)：n1 -> h4 -> n5
- ea.halfedge = n0，ec.halfedge = n2，ed.halfedge = n4，m.halfedge = n1；若 a.halfedge 原来是 h0，则改为 n0]],
  }
  say {
    en = [[
When you write `split_edge` (scripts/student/split.lua), read every old element first (h0 to h5, a to d, f0, f1),
make the new ones in this order (m; ea, ec, ed; g0, g1; n0 to n5), then set every pointer above. Select an edge,
press **X** and **Run mine**: the panel puts your pointers beside the reference's.]],
    zh = [[
编写 `split_edge`（scripts/student/split.lua）时，先读出所有旧元素（h0 到 h5、a 到 d、f0、f1），再按这个顺序创建新元素（m；ea、ec、ed；g0、g1；n0 到
n5），然后设置上面列出的每个指针。选中一条边，按 **X** 键再点击 **运行我的代码**：面板会把你的指针和参考实现的指针并排列出。]],
  }
end)

step({ en = "Split a boundary edge", zh = "分裂边界边" }, function()
  show(grid)
  camera { fit = true, pitch = 55 }  -- flat too: seen from above
  highlight(rim, "yellow")
  local p, q = rim.halfedge.vertex, rim.halfedge.twin.vertex
  label(p, "a")
  label(q, "b")
  say {
    en = [[
On the **boundary** of a mesh an edge has a face on one side only; on the other side is the boundary loop
(drawn blue).]],
    zh = [[
在网格的 **边界** 上，一条边只有一侧有面；另一侧是边界环（画成蓝色）。]],
  }
  choose {
    {
      en = "How many new faces does splitting the yellow boundary edge make?",
      zh = "分裂这条黄色的边界边会产生几个新面？",
    },
    options = { "0", "1", "2" },
    answer = "1",
    feedback = {
      ["0"] = {
        en = "The triangle above the edge is still cut in two by the new edge m-c: one new face.",
        zh = "边上方的三角形仍会被新边 m-c 一分为二：多出一个新面。",
      },
      ["2"] = {
        en = "Below the edge is the boundary loop, not a triangle: there is nothing there to cut, so only one "
          .. "face is new.",
        zh = "边的下方是边界环，不是三角形：那里没有可切的东西，所以只有一个新面。",
      },
      ["1"] = { en = "One: only the triangle side is cut.", zh = "一个：只有三角形那一侧被切开。" },
    },
    hint = { en = "Count the triangles beside the edge.", zh = "数一数这条边旁边有几个三角形。" },
  }
  say {
    en = [[
A split there makes fewer new elements: one new vertex, two new edges (ea and ec), one new face (g0)
and four halfedges. The boundary loop gets one halfedge longer (n1, after h1), and **m** lies on it.]],
    zh = [[
在那里分裂产生的新元素更少：一个新顶点、两条新边（ea 和 ec）、一个新面（g0）和四条半边。边界环多了一条半边（n1，接在
h1 之后），而 **m** 就在边界环上。]],
  }
  say({
    en = "This grid has " .. counts(grid) .. ". Click the yellow edge on its bottom row (`" .. tostring(rim)
      .. "`) to select it.",
    zh = "这个网格有 " .. counts_zh(grid) .. "。点击最下面一行中黄色的边（`" .. tostring(rim) .. "`）选中它。",
  })
  wait_for { selection = tostring(rim), hint = { en = "Click the yellow boundary edge", zh = "点击黄色的边界边" } }
  say { en = "Now press **S** to split it.", zh = "现在按 **S** 键分裂它。" }
  local mesh = wait_for {
    condition = function() return split_done(grid) end,
    hint = { en = "Select the edge, press S", zh = "选中这条边，按 S 键" },
  }
  local m = mesh:vertex(grid:num_vertices())
  label(m, "m")
  highlight(m, "yellow")
  local ok = m:is_boundary() and mesh:num_edges() == grid:num_edges() + 2 and mesh:num_faces() == grid:num_faces() + 1
    and mesh:num_boundaries() == 1
  if ok then
    say({
      en = "Split. **m** = `" .. tostring(m) .. "` sits on the boundary at " .. tostring(m.position) .. " with "
        .. m:degree() .. " neighbours. The mesh has " .. counts(mesh) .. ": two more edges and one more face, "
        .. "still one boundary loop, and it passes validation.",
      zh = "分裂完成。**m** = `" .. tostring(m) .. "` 位于边界上的 " .. tostring(m.position) .. "，有 "
        .. m:degree() .. " 个相邻顶点。网格现在有 " .. counts_zh(mesh) .. "：多了两条边和一个面，"
        .. "仍然只有一个边界环，并且通过了验证。",
    })
    say({
      en = "m's halfedge is `" .. tostring(m.halfedge) .. "`, which lies on the boundary loop. MeshEdit's own split "
        .. "keeps a boundary vertex's halfedge on the boundary loop, but the course does not require it: a boundary "
        .. "vertex's halfedge may be any halfedge leaving it. For m, the checker and the grader ask only what they "
        .. "ask on an interior edge: that it run along the split edge (n1 toward a, or h0 toward b).",
      zh = "m 的半边是 `" .. tostring(m.halfedge) .. "`，它位于边界环上。MeshEdit 自己的分裂会让边界顶点的半边"
        .. "留在边界环上，但课程并不要求这一点：边界顶点的半边可以是从它出发的任意一条半边。对于 m，检查程序和"
        .. "评分程序的要求与内部边时相同：它要沿着被分裂的边（指向 a 的 n1，或指向 b 的 h0）。",
    })
  else
    say({
      en = "That split changed more than one boundary edge would. Press **Back** to try again.",
      zh = "这次分裂改变的东西比分裂一条边界边应有的要多。按 **上一步** 再试一次。",
    })
  end
end)

step({ en = "Flip and split together", zh = "翻转与分裂" }, function()
  say {
    en = [[
Split and flip are the two moves of Loop subdivision (part 6): split every edge, then flip the new edges that
join an old vertex to a new one.]],
    zh = [[
分裂和翻转是 Loop 细分（第 6 部分）的两个操作：先分裂每一条边，再翻转那些连接旧顶点与新顶点的新边。]],
  }
  answer {
    {
      en = "An interior split adds 1 vertex, 3 edges and 2 faces. By how much does V - E + F change?",
      zh = "一次内部分裂增加 1 个顶点、3 条边和 2 个面。V - E + F 改变了多少？",
    },
    number = 0,
    tolerance = 1e-9,
    feedback = function(value)
      if value == 6 then
        return {
          en = "6 adds the three counts, but E counts with a minus sign: 1 - 3 + 2.",
          zh = "6 是把三个数直接相加，但 E 要带负号：1 - 3 + 2。",
        }
      end
      if value == -4 or value == -2 or value == 4 then
        return {
          en = string.format("%g: check the signs, V - E + F changes by (+1) - (+3) + (+2).", value),
          zh = string.format("%g：检查一下符号，V - E + F 的变化是 (+1) - (+3) + (+2)。", value),
        }
      end
    end,
    hint = {
      en = "Put the changes into V - E + F: (+1) - (+3) + (+2).",
      zh = "把各项的变化代入 V - E + F：(+1) - (+3) + (+2)。",
    },
  }
  say {
    en = [[
It does not change: V - E + F, the Euler characteristic, is the same before and after every split (a boundary
split adds 1 - 2 + 1 = 0 too) and every flip. Ctrl+Z undoes a split; try splitting and flipping on the grid
until the counts make sense to you.]],
    zh = [[
它不变：V - E + F，即欧拉示性数，在每次分裂（边界分裂增加的是 1 - 2 + 1 = 0，同样不变）和每次翻转的前后都相同。Ctrl+Z
可以撤销一次分裂；在网格上多试几次分裂和翻转，直到这些计数对你来说讲得通为止。]],
  }
end)

step({ en = "Your turn", zh = "轮到你了" }, function()
  -- A lopsided diamond: the average of a, b, c and d is not the midpoint of a-b, so a split that puts m at the
  -- corners' average is told so.
  local lopsided = meshedit.from_polygons(
    { {-1, 0, 0}, {1.2, 0.1, 0}, {0.5, 1.1, 0.1}, {-0.3, -0.9, -0.2} },
    { {1, 2, 3}, {2, 1, 4} })
  show(lopsided)
  camera "fit"
  local n = names_of(lopsided:edge(0))
  for _, name in ipairs(order) do label(n[name], name) end
  -- The names a wrong verdict lists beside the ids: the old elements, and m, the one new vertex (split makes it
  -- first, so its id is the next one); the new edges, faces and halfedges are named by what they join, since a
  -- split that makes them in another order gives them other ids.
  local diagram = { m = "v" .. lopsided:num_vertices() }
  for name, element in pairs(n) do diagram[name] = element end
  say {
    en = [[
# Your code

Open `scripts/student/split.lua` and write `split_edge(mesh, e)`: collect the old elements, make m, the three
new edges, the two new faces and the six new halfedges, then set every pointer (the before-and-after list of the
last steps is the plan). The lesson runs yours on the edge e of this lopsided diamond each time you save the file,
beside the reference, and names what differs: m's position, a pointer that breaks a face cycle, a face that does
not hold its halfedge.]],
    zh = [[
# 你的代码

打开 `scripts/student/split.lua`，编写 `split_edge(mesh, e)`：收集旧元素，创建
m、三条新边、两个新面和六条新半边，然后设置每个指针（前面几步的前后对照列表就是你的计划）。每次保存文件，课程都会在这个歪斜菱形的边
e 上运行你的代码，和参考实现并排比较，并指出不同之处：m 的位置、打断面循环的指针、所指半边不属于自己的面。]],
  }
  your_turn {
    exercise = "split",
    mesh = lopsided,
    element = n.e,
    names = diagram,
    hint = {
      en = "m goes at the midpoint of a and b; after the split every face is a triangle of three halfedges whose "
        .. "next pointers close the cycle, and each one's face is that triangle.",
      zh = "m 放在 a 和 b 的中点；分裂后每个面都是由三条半边组成的三角形，它们的 next 指针首尾相接构成循环，"
        .. "而且每条半边的 face 都是这个三角形。",
    },
  }
  -- A grid of 80 x 70 squares, each cut in two, and its diagonal with its midpoint at (40.5, 35.5), found by
  -- where it is.
  local big = meshedit.grid(80, 70)
  local middle
  for edge in big:edges() do
    local mid = (edge.halfedge.vertex.position + edge.halfedge.twin.vertex.position) * 0.5
    if mid == meshedit.vec3(40.5, 35.5, 0) then middle = edge end
  end
  say({
    en = "Your `split_edge` gives the reference's answer, up to the order you made the new elements in. Last, the "
      .. "middle edge of a grid of " .. big:num_faces() .. " triangles: a split changes a fixed handful of elements "
      .. "whatever the mesh's size, and the lesson counts the elements yours touches (reads or writes), as the "
      .. "Exercises tab and the grader do.",
    zh = "你的 `split_edge` 给出了与参考实现相同的结果（新元素的创建顺序可以不同）。最后来看一个有 " .. big:num_faces()
      .. " 个三角形的网格的中间一条边：无论网格多大，一次分裂只改变固定的少数几个元素；课程会像「练习」标签页和"
      .. "评分程序那样，统计你的代码触及（读或写）的元素个数。",
  })
  your_turn {
    exercise = "split",
    mesh = big,
    element = middle,
    hint = {
      en = "Walk from e.halfedge to the two triangles at e; a loop over the mesh, or a copy or a validate() of the "
        .. "whole mesh, touches every element of it.",
      zh = "从 e.halfedge 出发走到 e 两侧的两个三角形；遍历整个网格的循环，或对整个网格调用 copy 或 validate()，"
        .. "都会触及网格的每一个元素。",
    },
  }
  say {
    en = [[
Your `split_edge` splits the big grid's edge as the reference does, touching only the elements around it.
Splitting a boundary edge is extra credit: the Exercises tab (**X**, **Run mine**) checks it on any boundary edge
you select, and the grading suite's boundary tests count as extra credit.]],
    zh = [[
你的 `split_edge` 和参考实现一样分裂了大网格的这条边，只触及它周围的元素。分裂边界边是附加分：「练习」标签页（**X**，**运行我的代码**）会在你选中的任意一条边界边上检查它，评分测试套件中的边界测试也计入附加分。]],
  }
end)
