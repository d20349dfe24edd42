-- Part 3: walking the half-edge structure (around a face with h.next, why a face list cannot find a vertex's
-- neighbours without reading every face, around a vertex with h.twin.next, along a boundary loop), then
-- area-weighted vertex normals (on a fan where the weighting changes the answer) and flat vs smooth shading.
-- Each step asks or has the student act before it tells: the student clicks h.next or h.twin.next, counts, walks
-- a boundary loop, predicts the normal or switches the shading, and every wrong answer is told what it is. Every
-- walk is done on the mesh on screen and every highlight and label marks the element the walk reached, so what the
-- student sees is what the pointers say. The last step runs the student's own vertex_normal (your_turn) on the fan.
-- CI runs it headless:
--   meshedit lesson lessons/3_halfedge_walks.lua --headless \
--     --answers tests/lesson/lessons/3_halfedge_walks_answers.lua --student tests/exercise/solutions

lesson {
  title = { en = "Walking the half-edge mesh", zh = "在半边网格上行走" },
  summary = {
    en = "Around a face, why half-edges, around a vertex, along a boundary; then vertex normals and shading.",
    zh = "绕面一周、为什么要用半边、绕顶点一周、沿边界行走；然后是顶点法向量与着色。",
  },
}

local cube = meshedit.cube()

local function vec(p)
  local function r(x) return math.abs(x) < 5e-4 and 0 or x end  -- no "-0.000"
  return string.format("(%.3f, %.3f, %.3f)", r(p.x), r(p.y), r(p.z))
end

-- What a clicked element is, for feedback that names it: "a vertex (v3)".
local function kind_of(element)
  return "a " .. element.kind .. " (" .. tostring(element) .. ")"
end

-- The same in Chinese: "一个顶点（v3）".
local kind_names_zh = { vertex = "顶点", halfedge = "半边", edge = "边", face = "面", boundary = "边界环" }
local function kind_of_zh(element)
  return "一个" .. (kind_names_zh[element.kind] or element.kind) .. "（" .. tostring(element) .. "）"
end

-- A pick returns a handle on a copy of the mesh on screen: compare elements by id.
local function same(a, b) return tostring(a) == tostring(b) end

-- The fan of the normals step: an interior vertex (v0, at the origin) with six triangles around it, a roof
-- whose ridge runs along y, away from the front view (z is up). The triangles on the right (+x) are large and slope
-- down to the right, those on the left small and slope down to the left: their unit normals cancel sideways, their
-- areas do not.
local function fan()
  local points = { { 0, 0, 0 } }
  for k = 0, 5 do
    local t = math.rad(60 * k)
    local x, y = math.cos(t), math.sin(t)
    local r = x > 0.1 and 2.4 or (x < -0.1 and 0.8 or 1.4)
    points[#points + 1] = { r * x, r * y, -0.6 * math.abs(r * x) }
  end
  local faces = {}
  for k = 0, 5 do faces[#faces + 1] = { 1, 2 + k, 2 + (k + 1) % 6 } end
  return meshedit.from_polygons(points, faces)
end

-- The cube's faces and vertex the walks use: f5 is on the front and v5 the front top right corner, so in the
-- three-quarter view (camera "reset") every halfedge a student may click for them is in sight.
local FACE, VERTEX = 5, 5

step({ en = "Around a face", zh = "绕面一周" }, function()
  show(cube)
  camera "fit"
  camera "reset"
  view { halfedges = true, labels = true }
  local f = cube:face(FACE)
  local h = f.halfedge
  highlight(f, "yellow")
  highlight(h, "red")
  label(h, "h")
  say {
    en = "# Around a face\n\nEvery face knows **one** of its halfedges, `f.halfedge`. The yellow face is **"
      .. tostring(f) .. "**, and the red arrow is its halfedge **h** = " .. tostring(h)
      .. ". Each halfedge knows the one after it in its face, `h.next`.",
    zh = "# 绕面一周\n\n每个面都记着它的 **一条** 半边：`f.halfedge`。黄色的面是 **"
      .. tostring(f) .. "**，红色箭头是它的半边 **h** = " .. tostring(h)
      .. "。每条半边都记着同一个面里紧跟在它后面的那条半边：`h.next`。",
  }
  pick {
    { en = "Click the halfedge that is h.next.", zh = "点击 h.next 所指的那条半边。" },
    answer = h.next,
    feedback = function(e)
      if e.kind ~= "halfedge" then
        return {
          en = "That is " .. kind_of(e) .. ", not a halfedge: click one of the arrows inside the faces.",
          zh = "这是" .. kind_of_zh(e) .. "，不是半边：请点击面内的某个箭头。",
        }
      end
      if same(e, h) then
        return { en = "That is h itself; h.next is the one after it.", zh = "这就是 h 本身；h.next 是它后面的那条。" }
      end
      if same(e, h.twin) then
        return {
          en = "That is h.twin: the same edge the other way, in the face next door (" .. tostring(e.face)
            .. "). next stays in h's face.",
          zh = "这是 h.twin：同一条边上方向相反的半边，属于隔壁的面（" .. tostring(e.face)
            .. "）。next 始终留在 h 所在的面内。",
        }
      end
      if same(e, h.next.next) then
        return {
          en = "That is h.next.next, the halfedge before h (it ends where h starts): next starts where h ends, "
            .. "at the tip of h's arrow.",
          zh = "这是 h.next.next，即 h 前面的那条半边（它的终点是 h 的起点）：next 从 h 的终点出发，"
            .. "也就是 h 箭头的尖端。",
        }
      end
      return {
        en = tostring(e) .. " is in " .. tostring(e.face) .. ", not in the yellow face: h.next stays in h's face.",
        zh = tostring(e) .. " 属于 " .. tostring(e.face) .. "，不在黄色的面内：h.next 始终留在 h 所在的面内。",
      }
    end,
    hint = {
      en = "h.next starts at the tip of h's arrow, inside the yellow face.",
      zh = "h.next 从 h 箭头的尖端出发，位于黄色的面内。",
    },
  }
  local names = { "h", "h.next", "h.next.next" }
  local walked, count = h, 0
  repeat
    count = count + 1
    highlight(walked, count == 1 and "red" or "orange")
    label(walked, names[count] or { en = "step " .. count, zh = "第 " .. count .. " 步" })
    walked = walked.next
  until walked == h or count > 16
  say {
    en = [[
From any halfedge, `h.next` is the following halfedge around the same face, counter-clockwise. Keep following
`next` and you come back to where you started.]],
    zh = [[
从任意一条半边出发，`h.next` 是沿同一个面逆时针方向的下一条半边。一直沿着 `next` 走下去，
就会回到出发的地方。]],
  }
  say {
    en = "On screen: face **" .. tostring(f) .. "** and its halfedges, labelled as you reach them from `"
      .. tostring(h) .. "`. After " .. count .. " steps of `next` the walk is back at the start: " .. tostring(f)
      .. " is a triangle.",
    zh = "屏幕上是面 **" .. tostring(f) .. "** 和它的半边，按从 `" .. tostring(h)
      .. "` 出发依次到达的顺序做了标注。沿 `next` 走了 " .. count .. " 步之后回到起点：" .. tostring(f)
      .. " 是一个三角形。",
  }
  say {
    en = [[
Now **click a face** of your own.]],
    zh = [[
现在请你自己 **点击一个面**。]],
  }
  local picked = wait_for { click = "face", hint = { en = "Click a face", zh = "点击一个面" } }
  if type(picked) ~= "string" then
    local n, g = 0, picked.halfedge
    repeat n = n + 1; g = g.next until g == picked.halfedge or n > 64
    say {
      en = "You clicked **" .. tostring(picked) .. "**. Walking `next` from its halfedge " .. tostring(picked.halfedge)
        .. " takes " .. n .. " steps to come back: that is how `f:degree()` counts its sides.",
      zh = "你点击了 **" .. tostring(picked) .. "**。从它的半边 " .. tostring(picked.halfedge)
        .. " 出发沿 `next` 走，要 " .. n .. " 步才能回来：`f:degree()` 就是这样数出面的边数的。",
    }
  end
end)

step({ en = "Why half-edges at all", zh = "为什么要用半边" }, function()
  show(cube)
  camera "fit"
  camera "reset"
  view { halfedges = true, labels = true }
  local v = cube:vertex(VERTEX)
  local touching = 0
  for f in cube:faces() do
    for w in f:vertices() do
      if w == v then touching = touching + 1 end
    end
  end
  highlight(v, "red")
  label(v, tostring(v))
  say {
    en = [[
# What a face list cannot answer

The simplest way to store a mesh is a **face list**, as an OBJ file does: each triangle is the numbers of its
three corners, `{1, 2, 3}`, `{1, 3, 4}`, ... This cube has 12 triangles. Drawing them is easy. Now a question
every mesh operation asks: which vertices are the **neighbours of ]] .. tostring(v) .. [[** (red)?]],
    zh = [[
# 面列表回答不了的问题

存储网格最简单的方式是 **面列表**，OBJ 文件就是这样做的：每个三角形记作它三个角点的编号，
`{1, 2, 3}`、`{1, 3, 4}` 等等。这个立方体有 12 个三角形。把它们画出来很容易。现在来看一个
每个网格操作都会问的问题：哪些顶点是 **]] .. tostring(v) .. [[ 的邻居**（红色）？]],
  }
  answer {
    {
      en = "With only the face list, how many of the 12 triangles must you read to be sure you found every neighbour "
        .. "of " .. tostring(v) .. "?",
      zh = "如果只有面列表，要确保找全 " .. tostring(v) .. " 的所有邻居，这 12 个三角形中你必须读多少个？",
    },
    number = 12,
    tolerance = 0,
    feedback = function(value)
      if value == touching then
        return {
          en = touching .. " triangles touch " .. tostring(v) .. ", but the list does not say which " .. touching
            .. ": they could be anywhere in it.",
          zh = "有 " .. touching .. " 个三角形用到了 " .. tostring(v) .. "，但列表并没有说是哪 " .. touching
            .. " 个：它们可能在列表中的任何位置。",
        }
      end
      if value == 3 then
        return {
          en = "3 square sides meet at " .. tostring(v) .. ", but nothing in the list says where their triangles are.",
          zh = "在 " .. tostring(v) .. " 处交汇的正方形侧面有 3 个，但列表中没有任何信息说明它们的三角形在哪里。",
        }
      end
      if value < 12 then
        return {
          en = "Nothing in a face list says where " .. tostring(v) .. "'s triangles are stored: which could you skip?",
          zh = "面列表中没有任何信息说明 " .. tostring(v) .. " 的三角形存放在哪里：你能跳过哪一个呢？",
        }
      end
      if value > 12 then return { en = "The list has only 12 triangles.", zh = "列表里只有 12 个三角形。" } end
    end,
    hint = {
      en = "Could a triangle near the end of the list use " .. tostring(v)
        .. "? How would you know without reading it?",
      zh = "列表末尾附近的某个三角形会不会用到 " .. tostring(v) .. "？不读它，你怎么知道？",
    },
  }
  local count, h = 0, v.halfedge
  repeat
    count = count + 1
    highlight(h, "cyan")
    h = h.twin.next
  until h == v.halfedge or count > 64
  say {
    en = "All 12: a face list answers in time that grows with the **whole mesh**, and a mesh operation asks this for "
      .. "every vertex it touches. A half-edge mesh stores, with each element, the pointers to its neighbours: from "
      .. "`v.halfedge` the walk `h = h.twin.next` reaches the " .. count .. " halfedges leaving " .. tostring(v)
      .. " (sky blue), one per neighbour, and nothing else: time that grows with its degree only. The next step walks "
      .. "it.",
    zh = "全部 12 个：用面列表回答这个问题，所需时间随 **整个网格** 的规模增长，而网格操作对它碰到的每个顶点"
      .. "都要问一遍。半边网格在每个元素中都存有指向其邻居的指针：从 `v.halfedge` 出发，按 `h = h.twin.next` "
      .. "行走，恰好到达从 " .. tostring(v) .. " 出发的 " .. count .. " 条半边（天蓝色），每个邻居一条，"
      .. "别的都不碰：所需时间只随它的度数增长。下一步就来走一走。",
  }
end)

step({ en = "Around a vertex", zh = "绕顶点一周" }, function()
  show(cube)
  camera "fit"
  camera "reset"
  view { halfedges = true, labels = true }
  local v = cube:vertex(VERTEX)
  local start = v.halfedge
  highlight(v, "red")
  label(v, tostring(v))
  highlight(start, "cyan")
  label(start, "h")
  say {
    en = (string.gsub([[
# Around a vertex

A vertex knows one halfedge that **starts** at it, `v.halfedge`: the sky-blue arrow **h**, leaving **V**. To reach
the next one around V, go across with `h.twin` (it ends at V) and then take `.next` (it starts at V again, in
the neighbouring face).]], "V", tostring(v))),
    zh = (string.gsub([[
# 绕顶点一周

顶点记着一条从它 **出发** 的半边：`v.halfedge`，也就是离开 **V** 的天蓝色箭头 **h**。要到达绕 V 的下一条，
先用 `h.twin` 走到边的另一侧（它终止于 V），再取 `.next`（它又从 V 出发，位于相邻的面内）。]], "V", tostring(v))),
  }
  -- The walk's order, to tell a student who clicked a later halfedge of the walk how far round it is.
  local order, g, k = {}, start, 0
  repeat
    k = k + 1
    order[tostring(g)] = k
    g = g.twin.next
  until g == start or k > 64
  pick {
    { en = "Click the halfedge that is h.twin.next.", zh = "点击 h.twin.next 所指的那条半边。" },
    answer = start.twin.next,
    feedback = function(e)
      if e.kind ~= "halfedge" then
        return {
          en = "That is " .. kind_of(e) .. ", not a halfedge: click one of the arrows.",
          zh = "这是" .. kind_of_zh(e) .. "，不是半边：请点击一个箭头。",
        }
      end
      if same(e, start) then return { en = "That is h itself.", zh = "这就是 h 本身。" } end
      if same(e, start.twin) then
        return {
          en = "That is h.twin: it ends at " .. tostring(v) .. ". Take one more step: its next.",
          zh = "这是 h.twin：它终止于 " .. tostring(v) .. "。再走一步：取它的 next。",
        }
      end
      if same(e, start.next) then
        return {
          en = "That is h.next: it goes on around h's own face, away from " .. tostring(v) .. ".",
          zh = "这是 h.next：它沿着 h 自己所在的面继续走，离开了 " .. tostring(v) .. "。",
        }
      end
      if order[tostring(e)] then
        return {
          en = tostring(e) .. " leaves " .. tostring(v) .. " too, but it is " .. (order[tostring(e)] - 1)
            .. " steps round the walk, not one.",
          zh = tostring(e) .. " 也从 " .. tostring(v) .. " 出发，但沿这条路线要走 " .. (order[tostring(e)] - 1)
            .. " 步才到，而不是一步。",
        }
      end
      return {
        en = tostring(e) .. " does not start at " .. tostring(v) .. ": every halfedge of this walk leaves it.",
        zh = tostring(e) .. " 不是从 " .. tostring(v) .. " 出发的：这次行走经过的每条半边都从它出发。",
      }
    end,
    hint = {
      en = "h.twin runs along the same edge as h, back into " .. tostring(v) .. ", inside the face on the other side.",
      zh = "h.twin 与 h 在同一条边上，方向相反，指回 " .. tostring(v) .. "，位于这条边另一侧的面内。",
    },
  }
  local h, count = start, 0
  repeat
    count = count + 1
    highlight(h, "cyan")
    label(h, tostring(count))
    h = h.twin.next
  until h == start or count > 64
  say {
    en = [[
So the walk around a vertex is `h = h.twin.next`, and seen from outside it turns clockwise around the
vertex: the opposite way to `next` around a face.]],
    zh = [[
所以，绕顶点行走就是 `h = h.twin.next`；从网格外面看，它绕着顶点顺时针转：
与绕面行走的 `next` 方向相反。]],
  }
  say {
    en = "The halfedges numbered on screen are the ones that walk visits around **" .. tostring(v) .. "**: " .. count
      .. " of them, so " .. tostring(v) .. " has degree " .. count .. " (the mesh agrees: `v:degree()` is "
      .. v:degree() .. ").",
    zh = "屏幕上编了号的半边，就是绕 **" .. tostring(v) .. "** 行走时经过的那些：共 " .. count
      .. " 条，所以 " .. tostring(v) .. " 的度数为 " .. count .. "（网格给出的结果一致：`v:degree()` 为 "
      .. v:degree() .. "）。",
  }
  say {
    en = [[
Try the walk yourself. Select a halfedge, then press **T** to jump to its twin.]],
    zh = [[
自己走一走。选中一条半边，然后按 **T** 键跳到它的 twin。]],
  }
  wait_for { key = "T", hint = { en = "Press T: go to the twin", zh = "按 T 键：跳到 twin" } }
  say {
    en = [[
Now press **N** to take the twin's next. Together, T then N is one step of the walk around the vertex.]],
    zh = [[
现在按 **N** 键，取 twin 的 next。先按 T 再按 N，合起来就是绕顶点行走的一步。]],
  }
  wait_for { key = "N", hint = { en = "Press N: go to the next halfedge", zh = "按 N 键：走到下一条半边（next）" } }
  say {
    en = [[
Repeat **T**, **N** and you circle the vertex one face at a time.]],
    zh = [[
重复按 **T**、**N**，每次跨过一个面，就能绕顶点转一圈。]],
  }
end)

step({ en = "Along a boundary", zh = "沿边界行走" }, function()
  local grid = meshedit.grid(3, 2)
  show(grid)
  camera "fit"
  view { halfedges = true, labels = true }  -- the boundary walk is drawn on the arrows
  local start
  for h in grid:halfedges() do
    if h:is_boundary() then
      start = h
      break
    end
  end
  local h, count = start, 0
  repeat
    count = count + 1
    highlight(h, "green")
    h = h.next
  until h == start or count > 256
  label(start, { en = "start", zh = "起点" })
  say {
    en = [[
# Along a boundary

A mesh with holes or edges, like this flat grid, has **boundary halfedges**: the halfedges on the outer
side of its edges, in no face. MeshEdit keeps them in a **boundary loop** (`b0`), so `h.next` still works
and walks along the boundary.]],
    zh = [[
# 沿边界行走

有洞或有边缘的网格（比如这块平面网格）带有 **边界半边**：位于网格边缘外侧、不属于任何面的半边。
MeshEdit 把它们放在一个 **边界环**（`b0`）中，所以 `h.next` 照样可用，并且会沿着边界走。]],
  }
  say {
    en = "The green halfedges are the walk along `next` from " .. tostring(start) .. ": " .. count
      .. " steps around the grid and back to the start, one per boundary edge.",
    zh = "绿色的半边是从 " .. tostring(start) .. " 出发沿 `next` 走过的路线：绕网格一圈共 " .. count
      .. " 步回到起点，每条边界边一步。",
  }
  say {
    en = [[
**Select an edge on the boundary** (any of the outer edges of the grid).]],
    zh = [[
**选中一条边界上的边**（网格外围的任意一条边都可以）。]],
  }
  local picked = wait_for {
    condition = function()
      local s = selection()
      if s and type(s) ~= "string" and s.kind == "edge" and s:is_boundary() then return s end
      return false
    end,
    hint = { en = "Select an outer edge of the grid", zh = "选中网格外围的一条边" },
  }
  say {
    en = "Yes: **" .. tostring(picked) .. "** is on the boundary. One of its halfedges has a face, the other lies in "
      .. "the boundary loop. Interior edges have a face on both sides.",
    zh = "对：**" .. tostring(picked) .. "** 在边界上。它的一条半边属于某个面，另一条位于边界环中。"
      .. "内部的边两侧都有面。",
  }
end)

step({ en = "Area-weighted normals", zh = "面积加权的法向量" }, function()
  local mesh = fan()
  show(mesh)
  camera "fit"
  camera { yaw = 0, pitch = 30 }  -- the front view, from a little above: x to the right, z up
  view { labels = false, halfedges = false }
  local v = mesh:vertex(0)
  local weighted, plain = meshedit.vec3(0, 0, 0), meshedit.vec3(0, 0, 0)
  local faces = 0
  for h in v:halfedges() do
    if not h:is_boundary() then
      local a = h.vertex.position
      local b = h.next.vertex.position
      local c = h.next.next.vertex.position
      local n = (b - a):cross(c - a)
      weighted = weighted + n
      plain = plain + n:normalized()
      faces = faces + 1
    end
  end
  weighted, plain = weighted:normalized(), plain:normalized()
  highlight(v, "red")
  label(v, "v")
  local p = v.position
  arrow(p, p + plain * 1.6, "blue")
  say {
    en = [[
# Vertex normals

A vertex has no surface of its own, so its normal is made from the faces around it: walk around the vertex
and add up the faces' normals. For each face, the cross product of two of its edges points out of the face, and
its **length is twice the face's area**.]],
    zh = [[
# 顶点法向量

顶点本身不是一块曲面，所以它的法向量要由周围的面来构造：绕顶点走一圈，把各个面的法向量加起来。
对每个面，取它两条边的叉积：叉积指向面的外侧，而它的 **长度等于面积的两倍**。]],
  }
  say {
    en = "The vertex **v** has " .. faces .. " triangles around it: big ones on the right sloping down to the right, "
      .. "small ones on the left sloping down to the left. The **blue** arrow is the plain average: each face's "
      .. "cross product normalized first, so every face counts the same. It points straight up, " .. vec(plain) .. ".",
    zh = "顶点 **v** 周围有 " .. faces .. " 个三角形：右边是大三角形，向右下方倾斜；左边是小三角形，"
      .. "向左下方倾斜。**蓝色** 箭头是简单平均：先把每个面的叉积归一化，这样每个面的权重都一样。"
      .. "它竖直向上：" .. vec(plain) .. "。",
  }
  choose {
    {
      en = "Now add the cross products as they are, so each face counts by its area, and normalize the sum. "
        .. "Where does that normal point?",
      zh = "现在把叉积原样相加，这样每个面按其面积计入，再把和归一化。这个法向量指向哪里？",
    },
    options = {
      { en = "Leaning right, towards the big faces", zh = "向右倾斜，偏向大的面" },
      { en = "Leaning left, towards the small faces", zh = "向左倾斜，偏向小的面" },
      { en = "Straight up, as the blue one", zh = "竖直向上，和蓝色箭头一样" },
    },
    answer = "Leaning right, towards the big faces",
    feedback = {
      ["Leaning left, towards the small faces"] = {
        en = "The other way: a small face has a short cross product, so it counts for less.",
        zh = "方向反了：小的面叉积短，所以权重更小。",
      },
      ["Straight up, as the blue one"] = {
        en = "Only when all the faces have the same area, as on a cube's corner. Here the right-hand faces are bigger.",
        zh = "只有所有面的面积都相同时才会这样，比如立方体的角上。这里右边的面更大。",
      },
      ["Leaning right, towards the big faces"] = {
        en = "The big faces' long cross products outweigh the small ones'.",
        zh = "大的面叉积长，压过了小的面的叉积。",
      },
    },
    hint = {
      en = "Which faces have the longest cross products, and which way do their normals lean?",
      zh = "哪些面的叉积最长？它们的法向量向哪边倾斜？",
    },
  }
  arrow(p, p + weighted * 1.6, "orange")
  say {
    en = "The **orange** arrow is the area-weighted normal, " .. vec(weighted) .. ": it leans towards the big faces. "
      .. "That is the normal your `vertex_normal` returns. Area weighting lets a big face count for more than a thin "
      .. "sliver, which keeps the normal steady when the mesh has badly shaped triangles.",
    zh = "**橙色** 箭头是面积加权的法向量 " .. vec(weighted) .. "：它偏向大的面。"
      .. "这就是你的 `vertex_normal` 要返回的法向量。面积加权让大的面比细长的碎片占更大的权重，"
      .. "这样即使网格中有形状很差的三角形，法向量也能保持稳定。",
  }
end)

step({ en = "Flat or smooth", zh = "平直还是平滑" }, function()
  show(meshedit.icosahedron())
  camera "fit"
  say {
    en = [[
# Shading

With **flat shading** every triangle uses its own face normal: the light is constant across it and the
edges show. With **Phong shading** the vertex normals are interpolated across each triangle and lighting
is computed per pixel: the same mesh looks smooth.]],
    zh = [[
# 着色

使用 **平直着色** 时，每个三角形都用自己的面法向量：整个三角形上的光照相同，棱边清晰可见。
使用 **Phong 着色** 时，顶点法向量在每个三角形内插值，光照逐像素计算：同一个网格看起来就是光滑的。]],
  }
  say {
    en = [[
Press **Q** to switch between the two.]],
    zh = [[
按 **Q** 键在两者之间切换。]],
  }
  wait_for { key = "Q", hint = { en = "Press Q: flat or smooth shading", zh = "按 Q 键：平直着色或平滑着色" } }
  say {
    en = [[
Same triangles, same positions: only the normals used for lighting changed. That is why your
`vertex_normal` matters.]],
    zh = [[
同样的三角形，同样的位置：变的只是用于光照的法向量。所以你的 `vertex_normal` 很重要。]],
  }
end)

step({ en = "Your turn", zh = "轮到你了" }, function()
  local mesh = fan()
  show(mesh)
  camera "fit"
  camera { yaw = 0, pitch = 30 }
  view { labels = false, halfedges = false }
  highlight(mesh:vertex(0), "red")
  label(mesh:vertex(0), "v")
  say {
    en = [[
# Your code

Open `scripts/student/normals.lua` and write `vertex_normal(v)`: walk around `v` with `h = h.twin.next`,
add the cross products of the faces you meet (skip boundary halfedges: their `h.face` is a boundary loop,
`h.face:is_boundary()`, not a face) and return the sum normalized. The lesson runs it on the fan's vertex **v**
each time you save the file and compares it with the reference's area-weighted normal: the plain average of unit
normals, a face left out or counted alone, a cross product taken the wrong way round are named as such, with the
faces they concern, and a Lua error shows its `normals.lua:LINE`.]],
    zh = [[
# 你的代码

打开 `scripts/student/normals.lua`，编写 `vertex_normal(v)`：用 `h = h.twin.next` 绕 `v` 行走，
把遇到的各个面的叉积加起来（跳过边界半边：它们的 `h.face` 是边界环，`h.face:is_boundary()` 为真，
而不是一个面），最后返回归一化后的和。每次保存文件时，本课都会在扇形网格的顶点 **v** 上运行它，
并与参考实现的面积加权法向量比较：如果你用了单位法向量的简单平均、漏掉了某个面或只算了一个面、
或者叉积的方向取反了，都会被明确指出，并列出涉及的面；如果出现 Lua 错误，会显示出错位置 `normals.lua:LINE`。]],
  }
  your_turn {
    exercise = "normals",
    mesh = mesh,
    element = mesh:vertex(0),
    hint = {
      en = "Add (b - a):cross(c - a) for each face as it is: its length is twice the face's area, so normalize "
        .. "only the sum.",
      zh = "对每个面，把 (b - a):cross(c - a) 原样加起来：它的长度是面积的两倍，所以只对最后的和做归一化。",
    },
  }
  say {
    en = [[
Your `vertex_normal` gives the reference's normal at **v**. In the window you can run it on any vertex of any
mesh: select a vertex, open the **Exercises** tab (X), choose the vertex normal and press **Run mine**.]],
    zh = [[
你的 `vertex_normal` 在 **v** 处给出了与参考实现相同的法向量。在窗口中，你可以在任意网格的任意顶点上运行它：
选中一个顶点，打开 **练习** 标签页（X），选择顶点法向量（vertex normal），然后点击 **运行我的代码**。]],
  }
end)
