-- Part 4: edge flip, on the smallest mesh where a flip means something: two triangles sharing one edge (the
-- "diamond"). Every element gets the name the core's diagram gives it (engine/core/mesh_ops.h). Each step asks
-- before it tells: the student clicks h0.next, finds the course's edge, predicts the pointers a flip sets (on a
-- diamond whose faces and vertices point at the halfedges the flip moves, so the classic "forgot f0.halfedge" bug
-- shows), predicts how many fields a flip changes in an 80x70 grid of 11200 triangles (then sees the count the core's
-- flip gives, by m:diff, against the 3 x 11200 corners a rebuild of the face list writes), flips the edge with F, and
-- the lesson checks every answer on the mesh on screen. The last step runs the student's own flip_edge
-- (scripts/student/flip.lua) with your_turn on that diamond, on its boundary edge and on the big grid's edge (where
-- the Exercises tab's locality check applies), and waits until each is right.
-- CI runs it headless, with the correct solutions and with buggy ones (tests/lesson/lesson_student_test.cpp):
--   meshedit lesson lessons/4_edge_flip.lua --headless --answers tests/lesson/lessons/4_edge_flip_answers.lua \
--     --student tests/exercise/solutions
-- Invariants: every name is found by walking from h0 = e0.halfedge, never assumed from storage order, so the
-- labels stay right whatever order the builder numbers halfedges in; the big grid's edge is found by where it is;
-- every count the text gives is counted at run time (the question asks before the count is said).

lesson {
  title = { en = "Part 4: Edge flip", zh = "第 4 部分：边翻转" },
  summary = {
    en = "Two triangles, every element named; predict what a flip rewrites, then flip the edge yourself.",
    zh = "两个三角形，每个元素都有名字；先预测一次翻转会改写什么，再亲手翻转这条边。",
  },
}

-- a, b, c, d as in the diagram: a-b is the shared edge, c above it, d below it.
local function diamond()
  return meshedit.from_polygons(
    { {-1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0} },
    { {1, 2, 3}, {2, 1, 4} })
end

-- The diagram's names, by walking from e's halfedge h0.
local function names_of(e)
  local n = {}
  n.e = e
  n.h0 = e.halfedge
  n.h1 = n.h0.twin
  n.h2 = n.h0.next
  n.h3 = n.h2.next
  n.h4 = n.h1.next
  n.h5 = n.h4.next
  -- The four outer halfedges run along the boundary loop, opposite h2..h5.
  n.h6, n.h7, n.h8, n.h9 = n.h2.twin, n.h3.twin, n.h4.twin, n.h5.twin
  n.a, n.b = n.h0.vertex, n.h1.vertex
  n.c, n.d = n.h3.vertex, n.h5.vertex
  n.f0, n.f1 = n.h0.face, n.h1.face
  return n
end

local order = { "a", "b", "c", "d", "f0", "f1", "h0", "h1", "h2", "h3", "h4", "h5", "h6", "h7", "h8", "h9" }

local function label_all(n)
  for _, name in ipairs(order) do label(n[name], name) end
end

-- "h2 is `h1`": the diagram's name and the id the app shows for the same element, in each language.
local function id_list(n, names)
  local parts, parts_zh = {}, {}
  for _, name in ipairs(names) do
    parts[#parts + 1] = name .. " is `" .. tostring(n[name]) .. "`"
    parts_zh[#parts_zh + 1] = name .. " 是 `" .. tostring(n[name]) .. "`"
  end
  return { en = table.concat(parts, ", "), zh = table.concat(parts_zh, "，") }
end

-- Diagram name of an element id ("v3" -> "d"), for describing changes in the student's words.
local function name_by_id(n)
  local map = {}
  for _, name in ipairs(order) do map[tostring(n[name])] = name end
  map[tostring(n.e)] = "e"
  return function(id) return map[id] or id end
end

local shape = diamond()
local names = names_of(shape:edge(0))
local name = name_by_id(names)

-- The same diamond with the faces and a, b pointing at the halfedges a flip takes away from them: f0.halfedge =
-- h2 (which the flip moves into f1), f1.halfedge = h4 (moves into f0), a.halfedge = h0 (will leave d),
-- b.halfedge = h1 (will leave c). Every one of these is allowed (any halfedge of the face, any halfedge leaving
-- the vertex); the flip has to change all four. Same ids as `shape`, so `names` and `name` hold for it too.
local function rigged_diamond()
  local m = diamond()
  local n = names_of(m:edge(0))
  n.f0.halfedge, n.f1.halfedge = n.h2, n.h4
  n.a.halfedge, n.b.halfedge = n.h0, n.h1
  return m
end
local rigged = rigged_diamond()

-- A grid of 80 x 70 squares, each cut in two by a diagonal: 11200 triangles. `big_edge` is the diagonal from the
-- vertex at (40, 35) to the one at (41, 36), found by where it is.
local function diagonal_at(mesh, x, y)
  for edge in mesh:edges() do
    local p, q = edge.halfedge.vertex.position, edge.halfedge.twin.vertex.position
    if p.x > q.x then p, q = q, p end
    if p.x == x and p.y == y and q.x == x + 1 and q.y == y + 1 then return edge end
  end
end
local big = meshedit.grid(80, 70)
local big_edge = diagonal_at(big, 40, 35)

-- The clicked element in the diagram's words, for feedback: "a halfedge (h4)", "an edge (b-c)"; in each language.
local kind_zh = { halfedge = "半边", vertex = "顶点", edge = "边", face = "面" }
local function what(element)
  if element.kind == "edge" then
    local h = element.halfedge
    local ends = name(tostring(h.vertex)) .. "-" .. name(tostring(h.twin.vertex))
    return { en = "an edge (" .. ends .. ")", zh = "一条边（" .. ends .. "）" }
  end
  local n = name(tostring(element))
  return { en = "a " .. element.kind .. " (" .. n .. ")",
           zh = "一个" .. (kind_zh[element.kind] or element.kind) .. "（" .. n .. "）" }
end

-- Feedback for a click that should have been a halfedge inside a face; nil when it is one.
local function not_a_halfedge(element)
  if element.kind ~= "halfedge" then
    local w = what(element)
    return { en = "That is " .. w.en .. ", not a halfedge: click one of the arrows beside the edges.",
             zh = "这是" .. w.zh .. "，不是半边：请点击边旁边的某个箭头。" }
  end
  local n = name(tostring(element))
  if n == "h6" or n == "h7" or n == "h8" or n == "h9" then
    return { en = n .. " runs around the outside, on the boundary loop: it is in no face.",
             zh = n .. " 沿外侧绕行，位于边界环上：它不属于任何面。" }
  end
end

step({ en = "The diamond", zh = "菱形" }, function()
  show(shape)
  camera { fit = true, pitch = 55 }  -- a flat mesh: seen from above, its faces and arrows have room
  view { labels = true, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  say {
    en = [[
# Edge flip

A flip works on two triangles that share an edge. On screen is exactly that: the **diamond**, four
vertices and two faces. The yellow edge in the middle is the one we will flip; call it **e**.]],
    zh = [[
# 边翻转

翻转作用于共享一条边的两个三角形。屏幕上正是这样的网格：**菱形**，四个顶点、两个面。中间那条黄色的边就是我们要翻转的边，记作
**e**。]],
  }
  local ids = id_list(names, { "h0", "h1", "h2", "h3", "h4", "h5" })
  say {
    en = "Two kinds of label are on screen. The **names** (a to d, f0, f1, h0 to h9) are the core's diagram's "
      .. "(engine/core/mesh_ops.h), found by walking from h0 = e.halfedge; this lesson uses them. The **ids** "
      .. "(v0, e0, h3...) are the mesh's storage numbers, which the inspector and the pointer tables show; they "
      .. "need not match: " .. ids.en
      .. ". From the next step on only the names are drawn.",
    zh = "屏幕上有两种标签。**名字**（a 到 d、f0、f1、h0 到 h9）取自核心代码中的示意图（engine/core/mesh_ops.h），"
      .. "从 h0 = e.halfedge 出发沿指针走一遍得到；本课使用的就是这些名字。**编号**（v0、e0、h3……）是网格的存储编号，"
      .. "检查器和指针表显示的都是编号；两者不必一致：" .. ids.zh .. "。从下一步起，屏幕上只画名字。",
  }
  say {
    en = [[
**h0** runs from a to b inside face **f0**; **h1** is its twin, b to a, inside **f1**.]],
    zh = [[
**h0** 在面 **f0** 内从 a 指向 b；**h1** 是它的孪生半边（twin），在 **f1** 内从 b 指向 a。]],
  }
  pick {
    { en = "Click the halfedge that is h0.next.", zh = "点击 h0.next 所指的那条半边。" },
    answer = function(element)
      if tostring(element) == tostring(names.h2) then
        return true, {
          en = "The arrow named h2 (its id is " .. tostring(names.h2) .. ") runs b to c, after h0 in f0.",
          zh = "名为 h2 的箭头（编号为 " .. tostring(names.h2) .. "）从 b 指向 c，在 f0 中紧接在 h0 之后。",
        }
      end
      return false
    end,
    feedback = function(element)
      local wrong = not_a_halfedge(element)
      if wrong then return wrong end
      local n = name(tostring(element))
      if n == "h0" then
        return { en = "That is h0 itself; h0.next is the halfedge after it.",
                 zh = "这就是 h0 本身；h0.next 是它后面的那条半边。" }
      end
      if n == "h1" then
        return { en = "That is h1 = h0.twin: the same edge the other way, in the other face. next stays in h0's face.",
                 zh = "这是 h1 = h0.twin：同一条边的反方向，位于另一个面中。next 始终留在 h0 所在的面内。" }
      end
      if n == "h3" then
        return { en = "That is h3, the halfedge before h0 (h3.next = h0): next starts where h0 ends, at b.",
                 zh = "这是 h3，h0 前面的那条半边（h3.next = h0）：next 从 h0 的终点 b 出发。" }
      end
      if n == "h4" or n == "h5" then
        return { en = n .. " is in f1, the other face; h0.next stays in f0 with h0.",
                 zh = n .. " 在另一个面 f1 中；h0.next 和 h0 一样在 f0 中。" }
      end
    end,
    hint = { en = "h0 ends at b. Its next starts at b and stays in f0.",
             zh = "h0 终止于 b。它的 next 从 b 出发，并且仍在 f0 中。" },
  }
  say {
    en = [[
Yes: h0.next is **h2**. The rest of the names follow the same walk:

- **a** and **b** are the ends of e, **c** is the corner above it, **d** the corner below
- around f0 = (a, b, c): h0, then **h2** (b to c), then **h3** (c to a), back to h0
- around f1 = (b, a, d): h1, then **h4** (a to d), then **h5** (d to b), back to h1
- **h6** to **h9** are the twins of h2 to h5: they run around the outside, on the boundary loop]],
    zh = [[
没错：h0.next 是 **h2**。其余的名字也按同样的走法得到：

- **a** 和 **b** 是 e 的两个端点，**c** 是它上方的顶点，**d** 是下方的顶点
- 绕 f0 = (a, b, c) 一圈：h0，然后是 **h2**（b 到 c），然后是 **h3**（c 到 a），回到 h0
- 绕 f1 = (b, a, d) 一圈：h1，然后是 **h4**（a 到 d），然后是 **h5**（d 到 b），回到 h1
- **h6** 到 **h9** 是 h2 到 h5 的孪生半边：它们沿外侧绕行，位于边界环上]],
  }
  say {
    en = [[
Click any element and press **I**: the inspector shows every field it stores (for a halfedge: next, twin, vertex,
edge and face).]],
    zh = [[
点击任意一个元素，再按 **I** 键：检查器会显示它存储的每个字段（对半边而言：next、twin、vertex、edge 和 face）。]],
  }
end)

step({ en = "The course's letters", zh = "课程讲义的字母" }, function()
  show(shape)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = false }  -- no arrows: a click on an edge's line picks the edge
  local course = { a = "b", b = "c", c = "a", d = "d" }  -- ours -> the handout's (flip.lua's table)
  for _, v in ipairs { "a", "b", "c", "d" } do
    label(names[v], { en = v .. ", course " .. course[v], zh = v .. "，讲义 " .. course[v] })
  end
  label(names.f0, "f0")
  label(names.f1, "f1")
  for edge in shape:edges() do highlight(edge, "grey") end  -- the lines to click, all alike
  say {
    en = [[
The CS184 handout draws the same diamond with other letters. Each corner is labelled with our name, then the
handout's. The handout flips the edge **b-c** between its triangles (a, b, c) and (c, b, d).]],
    zh = [[
CS184 的讲义用另一套字母画了同一个菱形。每个顶点的标签先写我们的名字，再写讲义里的名字。讲义翻转的是它的三角形
(a, b, c) 和 (c, b, d) 之间的边 **b-c**。]],
  }
  pick {
    { en = "Click the edge the handout calls b-c.", zh = "点击讲义中称为 b-c 的那条边。" },
    answer = names.e,
    feedback = function(element)
      if element.kind == "halfedge" then
        return { en = "That is a halfedge, not an edge: click the middle of an edge's line.",
                 zh = "这是半边，不是边：请点击边线的中间部分。" }
      end
      if element.kind ~= "edge" then
        local w = what(element)
        return { en = "That is " .. w.en .. ": click an edge's line.", zh = "这是" .. w.zh .. "：请点击一条边的线。" }
      end
      local h = element.halfedge
      local p, q = name(tostring(h.vertex)), name(tostring(h.twin.vertex))
      return {
        en = "That edge joins our " .. p .. " and " .. q .. ", which the handout calls " .. course[p] .. "-"
          .. course[q] .. ". Read the second letter of each label.",
        zh = "这条边连接我们的 " .. p .. " 和 " .. q .. "，讲义称之为 " .. course[p] .. "-" .. course[q]
          .. "。请看每个标签中的第二个字母。",
      }
    end,
    hint = { en = "Find the corners labelled course b and course c.",
             zh = "找到标着「讲义 b」和「讲义 c」的两个顶点。" },
  }
  choose {
    { en = "After the flip the handout has the triangles (a, d, c) and (a, b, d). Which of our faces is its (a, d, c)?",
      zh = "翻转之后，讲义中的三角形是 (a, d, c) 和 (a, b, d)。它的 (a, d, c) 是我们的哪个面？" },
    options = { "f0", "f1" },
    answer = "f1",
    feedback = {
      f0 = { en = "Our f0 ends up as (d, c, a), which is the handout's (d, a, b): its (a, b, d), not (a, d, c).",
             zh = "我们的 f0 最后是 (d, c, a)，也就是讲义的 (d, a, b)：即它的 (a, b, d)，而不是 (a, d, c)。" },
      f1 = { en = "Its (a, d, c) is our (c, d, b): f1 after the flip.",
             zh = "它的 (a, d, c) 就是我们的 (c, d, b)：翻转之后的 f1。" },
    },
    hint = { en = "Turn each of the handout's letters into ours first: its a is our c, its d our d, its c our b.",
             zh = "先把讲义的每个字母换成我们的：它的 a 是我们的 c，它的 d 是我们的 d，它的 c 是我们的 b。" },
  }
  say {
    en = [[
Letter by letter:

- course a, b, c, d = our c, a, b, d
- course edge b-c = our e, a-b; after the flip, course a-d = our c-d
- course (a, b, c), (c, b, d) = our f0, f1; after the flip, course (a, d, c), (a, b, d) = our f1, f0

Your template scripts/student/flip.lua has the same table.]],
    zh = [[
逐个字母对照：

- 讲义的 a, b, c, d = 我们的 c, a, b, d
- 讲义的边 b-c = 我们的 e，即 a-b；翻转之后，讲义的 a-d = 我们的 c-d
- 讲义的 (a, b, c)、(c, b, d) = 我们的 f0、f1；翻转之后，讲义的 (a, d, c)、(a, b, d) = 我们的 f1、f0

你的模板 scripts/student/flip.lua 里也有同样的对照表。]],
  }
end)

step({ en = "Predict the flip", zh = "预测翻转" }, function()
  show(shape)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  say {
    en = [[
Flipping e turns it inside the quad a, d, b, c, so that it joins **d** and **c** instead of a and b. No element
is created or deleted: the same two faces, the same six inner halfedges, only their pointers change. After
the flip h0 runs from **d to c** inside f0, and h1 from c to d inside f1. Predict the rest.]],
    zh = [[
翻转 e，就是让它在四边形 a, d, b, c 内转过去，改为连接 **d** 和 **c**，而不再连接
a 和 b。不新建也不删除任何元素：还是那两个面、那六条内部半边，变的只是它们的指针。翻转之后 h0 在
f0 内的方向是 **d 到 c**，h1 在 f1 内是 c 到 d。其余的请你来预测。]],
  }
  choose {
    { en = "After the flip, which halfedge is h0.next?", zh = "翻转之后，h0.next 是哪条半边？" },
    options = { "h1", "h2", "h3", "h4", "h5" },
    answer = "h3",
    feedback = {
      h1 = { en = "h1 is h0's twin, and a flip changes no twin: next is a different pointer.",
             zh = "h1 是 h0 的孪生半边，而翻转不会改变任何 twin：next 是另一个指针。" },
      h2 = { en = "h2 is h0.next now, before the flip. After it h2 runs b to c inside f1, and h0 is in f0.",
             zh = "h2 是翻转之前的 h0.next。翻转之后 h2 在 f1 内从 b 指向 c，而 h0 在 f0 中。" },
      h4 = { en = "h4 runs a to d, but h0 will end at c: its next must start at c.",
             zh = "h4 从 a 指向 d，但 h0 将终止于 c：它的 next 必须从 c 出发。" },
      h5 = { en = "h5 stays in f1 (it runs d to b); h0.next is in f0, with h0.",
             zh = "h5 留在 f1 中（它从 d 指向 b）；h0.next 和 h0 一样在 f0 中。" },
      h3 = { en = "h0 ends at c, and h3 runs c to a inside f0.", zh = "h0 终止于 c，而 h3 在 f0 内从 c 指向 a。" },
    },
    hint = { en = "After the flip h0 ends at c. Which halfedge of f0 starts at c?",
             zh = "翻转之后 h0 终止于 c。f0 的哪条半边从 c 出发？" },
  }
  pick {
    { en = "One halfedge of f1 moves into f0. Click it.", zh = "f1 中有一条半边会移到 f0 中。点击它。" },
    answer = function(element)
      if tostring(element) == tostring(names.h4) then
        return true, { en = "h4 (a to d) becomes a side of f0 = (d, c, a).",
                       zh = "h4（a 到 d）成为 f0 = (d, c, a) 的一条边。" }
      end
      return false
    end,
    feedback = function(element)
      local wrong = not_a_halfedge(element)
      if wrong then return wrong end
      local n = name(tostring(element))
      if n == "h2" then
        return { en = "h2 moves the other way: out of f0 into f1.", zh = "h2 的移动方向正相反：从 f0 移到 f1。" }
      end
      if n == "h0" or n == "h1" then
        return { en = n .. " is a halfedge of e: it keeps its face, only its ends change.",
                 zh = n .. " 是 e 的半边：它所在的面不变，只有端点会变。" }
      end
      if n == "h3" then
        return { en = "h3 is in f0 already, and stays there.", zh = "h3 本来就在 f0 中，并且留在那里。" }
      end
      if n == "h5" then
        return { en = "h5 stays in f1: f1 becomes (c, d, b) = h1, h5, h2.",
                 zh = "h5 留在 f1 中：f1 变成 (c, d, b) = h1, h5, h2。" }
      end
    end,
    hint = { en = "f0 becomes the triangle (d, c, a). Which of its sides is in f1 now?",
             zh = "f0 会变成三角形 (d, c, a)。它的哪条边现在在 f1 中？" },
  }
  say {
    en = [[
The whole *after* list:

- f0 = (d, c, a): h0.next = h3, h3.next = h4, h4.next = h0
- f1 = (c, d, b): h1.next = h5, h5.next = h2, h2.next = h1
- h0.vertex = d, h1.vertex = c
- **h4** moves into f0 and **h2** into f1 (h4.face = f0, h2.face = f1)

Twins, edges and everything outside the two triangles stay as they were. A flip is refused on a boundary
edge (there is only one triangle) and when c and d are already joined (the flip would duplicate an edge).]],
    zh = [[
完整的 *翻转后* 清单：

- f0 = (d, c, a): h0.next = h3, h3.next = h4, h4.next = h0
- f1 = (c, d, b): h1.next = h5, h5.next = h2, h2.next = h1
- h0.vertex = d, h1.vertex = c
- **h4** 移入 f0，**h2** 移入 f1（h4.face = f0，h2.face = f1）

twin 和 edge 指针，以及两个三角形之外的一切，都保持原样。翻转在边界边上会被拒绝（那里只有一个三角形）；c 和 d
已经相连时也会被拒绝（翻转会造出一条重复的边）。]],
  }
  highlight({ names.h2, names.h4 }, "orange")
end)

step({ en = "The pointers that are easy to forget", zh = "容易忘记的指针" }, function()
  show(rigged)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  highlight({ names.f0, names.h2 }, "orange")
  highlight({ names.a, names.h0 }, "cyan")
  say {
    en = [[
The list above is not all. This is the same diamond, but its faces and vertices store other halfedges, as
they may (any halfedge of the face, any halfedge leaving the vertex): **f0.halfedge = h2** (orange),
f1.halfedge = h4, **a.halfedge = h0** (sky blue) and b.halfedge = h1. The flip moves exactly those halfedges away.]],
    zh = "上面的清单还不完整。这还是同一个菱形，但它的面和顶点存储的是别的半边，这也是允许的（面的任意一条半边、"
      .. "从顶点出发的任意一条半边都可以）：**f0.halfedge = h2**（橙色）、f1.halfedge = h4、**a.halfedge = h0**"
      .. "（天蓝色）以及 b.halfedge = h1。翻转恰好会把这几条半边从它们的面和顶点上移走。",
  }
  pick {
    { en = "After the flip h2 is in f1. Click a halfedge f0.halfedge may point to after the flip.",
      zh = "翻转之后 h2 在 f1 中。点击一条在翻转之后 f0.halfedge 可以指向的半边。" },
    answer = function(element)
      local n = element.kind == "halfedge" and name(tostring(element))
      if n == "h0" or n == "h3" or n == "h4" then
        return true, {
          en = "The arrow named " .. n .. " (its id is " .. tostring(element) .. ") is in f0 after the flip.",
          zh = "名为 " .. n .. " 的箭头（编号为 " .. tostring(element) .. "）在翻转之后属于 f0。",
        }
      end
      return false
    end,
    feedback = function(element)
      local wrong = not_a_halfedge(element)
      if wrong then return wrong end
      local n = name(tostring(element))
      if n == "h2" then
        return { en = "h2 is what f0.halfedge holds now; after the flip h2 is in f1. Leaving it is the classic bug.",
                 zh = "f0.halfedge 现在存的正是 h2；翻转之后 h2 在 f1 中。忘了改它，就是那个经典的错误。" }
      end
      if n == "h1" or n == "h5" then
        return { en = n .. " is in f1 after the flip, not f0.", zh = n .. " 在翻转之后属于 f1，而不是 f0。" }
      end
    end,
    hint = { en = "After the flip f0 = (d, c, a) is made of h0, h3 and h4.",
             zh = "翻转之后 f0 = (d, c, a) 由 h0、h3 和 h4 组成。" },
  }
  choose {
    { en = "a.halfedge is h0, which after the flip runs d to c. Which halfedge must a.halfedge become?",
      zh = "a.halfedge 是 h0，而翻转之后 h0 从 d 指向 c。a.halfedge 必须改成哪条半边？" },
    options = { "h0", "h3", "h4" },
    answer = "h4",
    feedback = {
      h0 = { en = "After the flip h0 leaves d, not a: the validator says 'a.halfedge is h0, but h0 leaves d'.",
             zh = "翻转之后 h0 从 d 出发，而不是从 a 出发：验证器会报告 'a.halfedge is h0, but h0 leaves d'"
               .. "（a.halfedge 是 h0，但 h0 从 d 出发）。" },
      h3 = { en = "h3 runs c to a: it ends at a. A vertex's halfedge must leave the vertex.",
             zh = "h3 从 c 指向 a：它终止于 a。顶点的 halfedge 必须从该顶点出发。" },
      h4 = { en = "h4 runs a to d inside f0: it leaves a. (b likewise takes h2.)",
             zh = "h4 在 f0 内从 a 指向 d：它从 a 出发。（同理，b 要改为 h2。）" },
    },
    hint = { en = "v.halfedge must start at v. Which of these starts at a after the flip?",
             zh = "v.halfedge 必须从 v 出发。翻转之后，这几条中哪一条从 a 出发？" },
  }
  -- A flip that rewrites only the list of the previous step, run on a copy: what validation says of it.
  local broken = rigged:copy()
  local n = names_of(broken:edge(0))
  n.h0.next, n.h3.next, n.h4.next = n.h3, n.h4, n.h0
  n.h1.next, n.h5.next, n.h2.next = n.h5, n.h2, n.h1
  n.h0.vertex, n.h1.vertex = n.d, n.c
  n.h4.face, n.h2.face = n.f0, n.f1
  local ok, report = broken:validate()
  local lines, lines_zh = {}, {}
  for _, v in ipairs(ok and {} or report.violations) do
    local named = v.message:gsub("%a%d+", function(id) return name(id) end)
    lines[#lines + 1] = "- " .. named
    -- The validator's two messages here, in Chinese; any other stays as the validator wrote it.
    local zh, hits = named:gsub("^(%S+)%.halfedge is (%S+), but (%S+)%.face is (%S+)$",
      "%1.halfedge 是 %2，但 %3.face 是 %4")
    if hits == 0 then
      zh = named:gsub("^(%S+)%.halfedge is (%S+), but (%S+) leaves (%S+)$", "%1.halfedge 是 %2，但 %3 从 %4 出发")
    end
    lines_zh[#lines_zh + 1] = "- " .. zh
  end
  say {
    en = "A flip that sets only the next, vertex and face pointers leaves this diamond broken. The validator "
      .. "finds " .. #lines .. " problems (in the diagram's names):\n\n" .. table.concat(lines, "\n"),
    zh = "只设置 next、vertex 和 face 指针的翻转会让这个菱形出错。验证器发现了 " .. #lines
      .. " 个问题（用示意图中的名字表示）：\n\n" .. table.concat(lines_zh, "\n"),
  }
  say {
    en = [[
On the first diamond none of the four pointed at a moved halfedge, so a flip that forgets them looks right
there and breaks on the next edge. So: after the next, vertex and face pointers, set **f0.halfedge = h0**,
**f1.halfedge = h1**, and a.halfedge = h4 if it was h0, b.halfedge = h2 if it was h1.]],
    zh = [[
在第一个菱形上，这四个指针都没有指向被移动的半边，所以忘了改它们的翻转在那里看起来是对的，换一条边就会出错。因此：设好
next、vertex 和 face 指针之后，还要设置 **f0.halfedge = h0**、**f1.halfedge = h1**；如果 a.halfedge 原来是
h0，就改为 h4；如果 b.halfedge 原来是 h1，就改为 h2。]],
  }
end)

step({ en = "One flip in a big mesh", zh = "大网格中的一次翻转" }, function()
  local faces, halfedges = big:num_faces(), big:num_halfedges()
  -- The flip, on a copy, before asking: every field whose value differs afterwards, by m:diff.
  local flipped = big:copy()
  assert(flipped:flip(flipped:element(tostring(big_edge))))
  local changes = flipped:diff(big)
  local count = #changes
  local corners = 3 * faces  -- what a rebuild of the face list writes
  show(big)
  view { labels = false, halfedges = false }
  local h = big_edge.halfedge
  camera { target = (h.vertex.position + h.twin.vertex.position) * 0.5, distance = 10, pitch = 55 }
  highlight(big_edge, "yellow")
  say {
    en = "# A flip in a big mesh\n\nThis grid has **" .. faces .. " triangles** (80 by 70 squares, each cut in "
      .. "two), " .. halfedges .. " halfedges. The yellow edge in its middle is a diagonal like e: two triangles "
      .. "share it. A program that keeps only a list of triangles changes one by writing the list again; the "
      .. "halfedge mesh is built for the other way.",
    zh = "# 大网格中的一次翻转\n\n这个网格有 **" .. faces .. " 个三角形**（80 × 70 个正方形，每个都被切成两半），"
      .. "共 " .. halfedges .. " 条半边。它中间那条黄色的边是一条和 e 一样的对角线：两个三角形共享它。只保存三角形"
      .. "列表的程序，要改动网格就得把整个列表重写一遍；半边网格正是为另一种做法而设计的。",
  }
  answer {
    { en = "Flip the yellow edge: how many fields of the mesh change (a field is one pointer of one element, such as "
        .. "h0.next or f0.halfedge)?",
      zh = "翻转这条黄色的边，网格中会有多少个字段改变（一个字段就是某个元素的一个指针，比如 h0.next 或 "
        .. "f0.halfedge）？" },
    number = count,
    tolerance = 4,
    feedback = function(value)
      if value >= faces / 4 then
        return {
          en = "That is about every element: a rebuild of the face list rewrites every face's corners (3 x "
            .. faces .. " = " .. corners .. " numbers). A flip only rewires the two triangles at the edge.",
          zh = "这差不多是所有元素了：重建面列表才会重写每个面的角点（3 × " .. faces .. " = " .. corners
            .. " 个数）。翻转只会重新连接这条边两侧的两个三角形。",
        }
      end
      if value < count then
        return {
          en = "The diagonal's two halfedges change (h0.vertex and h1.vertex), but so do the next pointers of all "
            .. "six halfedges of the two triangles, and the face of the two halfedges that move.",
          zh = "对角线的两条半边确实会变（h0.vertex 和 h1.vertex），但两个三角形全部六条半边的 next 指针也会变，"
            .. "移动的那两条半边的 face 也会变。",
        }
      end
      return {
        en = "Nothing outside the two triangles at the edge changes, and only some fields inside them: count the "
          .. "after-list of \"Predict the flip\" and the pointers of \"The pointers that are easy to forget\".",
        zh = "这条边两侧两个三角形之外的东西都不变，三角形内部也只有部分字段会变：数一数「预测翻转」一步中的"
          .. "翻转后清单，再加上「容易忘记的指针」一步中的那些指针。",
      }
    end,
    hint = { en = "The diamond's flip changed the next, vertex and face pointers of its list, and some face and vertex "
               .. "pointers. Does the rest of the mesh matter?",
             zh = "菱形上的翻转改变了清单中的 next、vertex 和 face 指针，还有几个面和顶点的指针。网格的其余部分"
               .. "会受影响吗？" },
  }
  show(flipped)
  local kinds, order_of_kinds = {}, { "halfedge", "vertex", "edge", "face" }
  local plural_of = { halfedge = "halfedges", vertex = "vertices", edge = "edges", face = "faces" }
  for _, change in ipairs(changes) do
    local kind = flipped:element(change.element).kind
    kinds[kind] = kinds[kind] or {}
    kinds[kind][change.element] = true
    highlight(change.element, "orange")
  end
  local counted_zh = { halfedge = "条半边", vertex = "个顶点", edge = "条边", face = "个面" }
  local parts, parts_zh, elements = {}, {}, 0
  for _, kind in ipairs(order_of_kinds) do
    local n = 0
    for _ in pairs(kinds[kind] or {}) do n = n + 1 end
    if n > 0 then
      parts[#parts + 1] = n .. " " .. (n == 1 and kind or plural_of[kind])
      parts_zh[#parts_zh + 1] = n .. " " .. counted_zh[kind]
    end
    elements = elements + n
  end
  say {
    en = "The flip changed **" .. count .. " fields** (each a field of one element whose value differs after the "
      .. "flip, as m:diff lists them) of " .. elements .. " elements: " .. table.concat(parts, ", ")
      .. ", all in the two triangles at the edge (orange); the other " .. (faces - 2)
      .. " triangles keep every field. Writing the face list again instead writes 3 corners of each of the "
      .. faces .. " faces, **" .. corners .. " numbers**, about " .. math.floor(corners / count + 0.5)
      .. " times as many, before the halfedges are built from it again; and that grows with the mesh, where the "
      .. "flip's count does not.",
    zh = "这次翻转改变了 " .. elements .. " 个元素的 **" .. count .. " 个字段**（每个字段都是某个元素在翻转后"
      .. "取值不同的一项，也就是 m:diff 列出的项）：" .. table.concat(parts_zh, "、")
      .. "，全都在这条边两侧的两个三角形里（橙色）；其余 " .. (faces - 2)
      .. " 个三角形的每个字段都保持不变。若改为重写面列表，就要为 " .. faces .. " 个面各写 3 个角点，共 **"
      .. corners .. " 个数**，约为前者的 " .. math.floor(corners / count + 0.5)
      .. " 倍，而且之后还要据此重新构建半边；这个数随网格增大而增长，翻转改动的字段数却不会。",
  }
  say {
    en = [[
That is why the course writes flips and splits on a halfedge mesh: each is a fixed handful of pointers, found by
walking from e.halfedge. Your `flip_edge` is held to it: on a mesh this big the Exercises tab and the grader count
the elements it touches (reads or writes), and one that loops over `mesh:halfedges()` to find a halfedge, or reads
the whole mesh with `mesh:copy()` or `mesh:validate()`, is wrong even when the mesh it leaves is right.]],
    zh = [[
这就是课程在半边网格上实现翻转和分裂的原因：每个操作只涉及固定的少数几个指针，从 e.halfedge 出发沿指针走就能找到。你的
`flip_edge` 也要达到这个要求：在这么大的网格上，「练习」标签页和评分器会统计它触及（读或写）的元素；如果它为了找一条半边而遍历
`mesh:halfedges()`，或者用 `mesh:copy()`、`mesh:validate()` 读取整个网格，那么即使最后得到的网格是对的，也算错。]],
  }
end)

step({ en = "Flip it yourself", zh = "亲手翻转" }, function()
  show(rigged)
  camera { fit = true, pitch = 55 }
  view { labels = false, halfedges = true }
  label_all(names)
  highlight(names.e, "yellow")
  say {
    en = "This is the diamond of \"The pointers that are easy to forget\", with f0.halfedge = h2 and a.halfedge = h0. "
      .. "Click the yellow edge **e** (its id is `" .. tostring(names.e) .. "`) to select it.",
    zh = "这是「容易忘记的指针」一步中的那个菱形，f0.halfedge = h2，a.halfedge = h0。点击黄色的边 **e**（编号为 `"
      .. tostring(names.e) .. "`）选中它。",
  }
  wait_for { selection = tostring(names.e),
             hint = { en = "Click the edge between a and b", zh = "点击 a 和 b 之间的那条边" } }
  say {
    en = [[
Now press **F** to flip it.]],
    zh = [[
现在按 **F** 键翻转它。]],
  }
  local c, d = tostring(names.c), tostring(names.d)
  local result = wait_for {
    hint = { en = "Press F to flip the selected edge", zh = "按 F 键翻转选中的边" },
    condition = function()
      local mesh = current_mesh()
      if not mesh or not mesh:validate() then return false end
      local h = mesh:element(tostring(names.e)).halfedge
      local from, to = tostring(h.vertex), tostring(h.twin.vertex)
      if (from == d and to == c) or (from == c and to == d) then return mesh end
      return false
    end,
  }
  local h = result:element(tostring(names.e)).halfedge
  local from, to = name(tostring(h.vertex)), name(tostring(h.twin.vertex))
  say {
    en = "Flipped. e now runs from **" .. from .. "** to **" .. to .. "**, and the mesh still passes validation.",
    zh = "翻转完成。e 现在从 **" .. from .. "** 指向 **" .. to .. "**，网格仍然能通过验证。",
  }
  highlight(result:element(tostring(names.e)), "yellow")
end)

step({ en = "Before and after, pointer by pointer", zh = "翻转前后，逐个指针对照" }, function()
  local after = current_mesh()
  view { labels = false }
  label_all(names)
  local changes = after:diff(rigged)
  local lines, lines_zh = {}, {}
  for _, change in ipairs(changes) do
    lines[#lines + 1] = "- " .. name(change.element) .. "." .. change.field .. ": " .. name(change.before) .. " to "
      .. name(change.after)
    lines_zh[#lines_zh + 1] = "- " .. name(change.element) .. "." .. change.field .. "：由 " .. name(change.before)
      .. " 改为 " .. name(change.after)
  end
  say {
    en = "Here is every field the flip changed (" .. #changes .. " in all), in the diagram's names:\n\n"
      .. table.concat(lines, "\n"),
    zh = "下面是这次翻转改变的每个字段（共 " .. #changes .. " 个），用示意图中的名字表示：\n\n"
      .. table.concat(lines_zh, "\n"),
  }
  say {
    en = [[
The ten next, vertex and face fields are the *after* list; the other four are the face and vertex pointers of
the previous step. The pointer tables beside the view show the same: the changed cells are highlighted, and the
**changes** tab lists them.]],
    zh = [[
其中十个
next、vertex 和 face 字段就是
*翻转后* 清单；另外四个是上一步讲的面和顶点指针。视图旁边的指针表显示的也是这些：改变了的单元格会高亮显示，并且在
**changes** 标签页中一一列出。]],
  }
  for _, change in ipairs(changes) do highlight(change.element, "orange") end
  answer {
    {
      en = "Press F again and again: after how many flips of e in a row is every halfedge pointer back where it "
        .. "started?",
      zh = "反复按 F：连续翻转 e 多少次之后，每个半边指针都会回到最初的位置？",
    },
    number = 4,
    tolerance = 0,
    feedback = function(value)
      if value == 2 then
        return { en = "After 2 flips e joins a and b again, but h0 runs b to a: the two triangles have traded faces.",
                 zh = "翻转 2 次后 e 又连接 a 和 b，但 h0 是从 b 指向 a：两个三角形互换了面。" }
      end
      if value == 1 then
        return { en = "One flip is what you just did: e joins c and d.", zh = "翻转一次就是你刚才做的：e 连接 c 和 d。" }
      end
      if value == 3 then
        return { en = "After 3 flips e joins c and d again, with h0 running c to d.",
                 zh = "翻转 3 次后 e 又连接 c 和 d，此时 h0 从 c 指向 d。" }
      end
    end,
    hint = { en = "Each flip moves both ends of e one corner on around the quad a, d, b, c.",
             zh = "每翻转一次，e 的两个端点都沿四边形 a, d, b, c 往前移一个顶点。" },
  }
  say {
    en = [[
Four: each flip moves each end of e one corner on, and the quad has four corners. The face and vertex
pointers stay as the first flip left them, which is fine: any halfedge of the face, any leaving the vertex.]],
    zh = "答案是四次：每次翻转都让 e 的每个端点往前移一个顶点，而四边形有四个顶点。面和顶点的指针保持第一次翻转后的"
      .. "样子，这没有问题：面的任意一条半边、从顶点出发的任意一条半边都可以。",
  }
  show(rigged)
  clear()
  label_all(names)
  say {
    en = [[
**Your turn.** Write `flip_edge` in scripts/student/flip.lua: collect every element first (h0 to h5, a to d,
f0, f1), then set every pointer. Below, the lesson runs your `flip_edge` on this diamond's edge e (with
f0.halfedge = h2 and a.halfedge = h0, as in the last steps) beside the reference, and says what differs. Save
the file and it runs again; the lesson goes on when yours gives the reference's answer. The Exercises tab (**X**,
**Run mine**) runs the same check on any edge and replays your writes one by one.]],
    zh = [[
**轮到你了。** 在 scripts/student/flip.lua 中编写
`flip_edge`：先取出所有元素（h0 到 h5、a 到 d、f0、f1），再设置每一个指针。下面，本课会在这个菱形的边
e 上（和前几步一样，f0.halfedge = h2，a.halfedge = h0）运行你的
`flip_edge`，与参考实现对照，并指出哪里不同。保存文件后会重新运行；结果与参考实现一致时，课程继续。「练习」标签页（按
**X** 键，再点 **运行我的代码**）会在任意一条边上做同样的检查，并逐条回放你的写操作。]],
  }
  your_turn {
    exercise = "flip",
    mesh = rigged,
    element = names.e,
    names = names,  -- a wrong verdict lists the diagram's names of the ids it mentions
    hint = {
      en = "After the flip f0 holds h0, h3, h4 and f1 holds h1, h5, h2: set each face's and each vertex's halfedge "
        .. "to one that is still in it or still leaves it.",
      zh = "翻转之后 f0 包含 h0、h3、h4，f1 包含 h1、h5、h2：把每个面和每个顶点的 halfedge "
        .. "设为仍在该面中、或仍从该顶点出发的一条半边。",
    },
  }
  say {
    en = [[
Your `flip_edge` gives the reference's answer, pointer for pointer up to renumbering. One more case: the edge
a-c has a face on one side only. There is no second triangle to turn the edge inside, so `flip_edge` must leave
the mesh as it is (and return nothing). The lesson runs yours on a-c next.]],
    zh = [[
你的 `flip_edge` 给出了和参考实现相同的结果：除了编号不同，每个指针都一致。还有一种情况：边 a-c
只有一侧有面。没有第二个三角形可供这条边在其中转动，所以 `flip_edge`
必须让网格保持原样（并且不返回任何值）。接下来，本课会在 a-c 上运行你的代码。]],
  }
  your_turn {
    exercise = "flip",
    mesh = rigged,
    element = names.h7.edge,
    names = names,
    hint = {
      en = "If the face of e.halfedge or of its twin is a boundary face (f:is_boundary()), return before any write.",
      zh = "如果 e.halfedge 或它的 twin 所在的面是边界面（f:is_boundary()），就在任何写操作之前返回。",
    },
  }
  say {
    en = "Your `flip_edge` leaves a boundary edge alone, as the reference does. Last, the yellow edge in the middle "
      .. "of the grid of " .. big:num_faces() .. " triangles (step \"One flip in a big mesh\"): the lesson runs "
      .. "yours there and counts the elements it touches, as the Exercises tab and the grader do.",
    zh = "你的 `flip_edge` 和参考实现一样，不会改动边界边。最后是有 " .. big:num_faces() .. " 个三角形的网格"
      .. "中间那条黄色的边（见「大网格中的一次翻转」一步）：本课会在那里运行你的代码，并像「练习」标签页和评分器"
      .. "那样统计它触及的元素。",
  }
  your_turn {
    exercise = "flip",
    mesh = big,
    element = big_edge,
    hint = {
      en = "Walk from e.halfedge: in a triangle the halfedge before h0 is h0.next.next. A loop over the mesh's "
        .. "halfedges, or a copy or a validate() of the whole mesh, touches every element of it.",
      zh = "从 e.halfedge 出发沿指针走：在三角形中，h0 前面的那条半边是 h0.next.next。遍历网格的所有半边，"
        .. "或者对整个网格做 copy 或 validate()，都会触及它的每一个元素。",
    },
  }
  say {
    en = "Your `flip_edge` changes the big grid as the reference does, touching only the elements around the edge.",
    zh = "你的 `flip_edge` 对大网格的改动与参考实现相同，而且只触及这条边周围的元素。",
  }
end)
