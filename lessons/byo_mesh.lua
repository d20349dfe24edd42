-- Bring your own mesh: what MeshEdit does with a real user's file. Which axis a scan (.ply) or a Blender export
-- (.glb, .gltf, .obj) is shown with up, and View > Up axis; what happens to a file that is not an oriented
-- manifold (the refusal, File > Open a repaired copy, the Repairs tab, `meshedit repair` and `meshedit info`);
-- triangulating quads so Loop accepts them; and the Subdivide menu. Every step asks the student to predict or act
-- before it tells, and each likely wrong answer is named in its feedback.
-- Every number and report line comes from the core: the broken meshes are built here from lists of polygons and
-- handed to meshedit.from_polygons (the refusal) and meshedit.repair (engine/core/mesh_repair.h), the quads to
-- mesh:triangulate(), mesh:loop_subdivide() and mesh:catmull_clark() on copies.
-- CI runs it headless (tests/lesson/lessons_b_test.cpp):
--   meshedit lesson lessons/byo_mesh.lua --headless --answers tests/lesson/lessons/byo_mesh_answers.lua
-- Invariants: the lesson never assumes what file the student opened; it inspects only the meshes it builds and
-- what current_mesh() returns. Every step shows what it talks about itself (Back runs a step again).

lesson {
  title = { en = "Bring your own mesh", zh = "用你自己的网格" },
  summary = {
    en = "Open a scan or a Blender export the right way up, repair a file that is not a manifold, triangulate "
      .. "quads and subdivide them.",
    zh = "以正确的朝向打开扫描文件或 Blender 导出的文件，修复不是流形的文件，把四边形三角化并加以细分。",
  },
}

local function counts(mesh)
  return mesh:num_vertices() .. " vertices, " .. mesh:num_edges() .. " edges, " .. mesh:num_faces() .. " faces"
end

-- counts(mesh) in Chinese: "6 个顶点、6 条边、2 个面".
local function counts_zh(mesh)
  return mesh:num_vertices() .. " 个顶点、" .. mesh:num_edges() .. " 条边、" .. mesh:num_faces() .. " 个面"
end

-- What a pick's element kind is called in Chinese.
local KIND_ZH = { vertex = "顶点", edge = "边", halfedge = "半边", face = "面" }

-- The message the mesh builder refuses polygons with (a file goes through the same check), without the note on
-- numbering that every refusal ends with.
local function refusal(positions, polygons)
  local ok, message = pcall(meshedit.from_polygons, positions, polygons)
  assert(not ok, "these polygons were meant to be refused")
  return (tostring(message):gsub(" %(face k is polygons.*$", ""))
end

-- The number in the first change that matches `pattern` (a Lua pattern with one capture), e.g. "face (%d+) reversed".
local function number_in(report, pattern)
  for _, change in ipairs(report.changes) do
    local n = change:match(pattern)
    if n then return tonumber(n) end
  end
  error("no change of the report matches " .. pattern)
end

-- A repair report as the Repairs tab lists it: the summary, then one line per change.
local function report_text(report)
  local lines = { "**" .. report.summary .. "**" }
  for _, change in ipairs(report.changes) do lines[#lines + 1] = "- " .. change end
  return table.concat(lines, "\n")
end

-- Three broken pieces, as lists of positions and 1-based polygons (what a file holds).
-- A bow-tie: two triangles that share only vertex 0.
local BOWTIE = {
  positions = { { 0, 0, 0 }, { 1, 0.5, 0 }, { 1, -0.5, 0 }, { -1, -0.5, 0 }, { -1, 0.5, 0 } },
  polygons = { { 1, 2, 3 }, { 1, 4, 5 } },
}
-- A fin: three triangles on the edge from vertex 0 to vertex 1.
local FIN = {
  positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 }, { 0.5, 0, 1 } },
  polygons = { { 1, 2, 3 }, { 2, 1, 4 }, { 1, 2, 5 } },
}
-- A flipped face: two triangles on the edge from vertex 0 to vertex 1 that both run from 0 to 1.
local FLIPPED = {
  positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 } },
  polygons = { { 1, 2, 3 }, { 1, 2, 4 } },
}

-- The three pieces side by side in one list, as one file that has all three problems.
local function all_three()
  local positions, polygons = {}, {}
  for piece_index, piece in ipairs({ BOWTIE, FIN, FLIPPED }) do
    local base = #positions
    for _, p in ipairs(piece.positions) do
      positions[#positions + 1] = { p[1] + 3 * (piece_index - 1), p[2], p[3] }
    end
    for _, polygon in ipairs(piece.polygons) do
      local shifted = {}
      for k, corner in ipairs(polygon) do shifted[k] = corner + base end
      polygons[#polygons + 1] = shifted
    end
  end
  return positions, polygons
end

-- The cube's six sides as counter-clockwise quads (1-based corners of meshedit.cube()), like a Blender export
-- that was not triangulated.
local CUBE_QUADS = { { 1, 3, 4, 2 }, { 5, 6, 8, 7 }, { 1, 2, 6, 5 }, { 3, 7, 8, 4 }, { 1, 5, 7, 3 }, { 2, 4, 8, 6 } }
local function quad_cube()
  local corners = meshedit.cube()
  local positions = {}
  for i = 0, 7 do positions[i + 1] = corners:vertex(i).position end
  return meshedit.from_polygons(positions, CUBE_QUADS)
end

step({ en = "Which way is up", zh = "哪边朝上" }, function()
  show(quad_cube())
  camera "fit"
  view { labels = false }
  say {
    en = [[
# Bring your own mesh

Everything you wrote works on any mesh, not only the course files. MeshEdit opens **.obj**, **glTF** (.gltf,
.glb), **.ply**, .stl, .off and .dae with **Ctrl+O** or by dropping the file on the window. Positions are never
rotated: only the view chooses which axis points up, by the file's format.]],
    zh = [[
# 用你自己的网格

你写的一切不只适用于课程文件，也适用于任何网格。按 **Ctrl+O** 或把文件拖到窗口上，MeshEdit 就能打开
**.obj**、**glTF**（.gltf、.glb）、**.ply**、.stl、.off 和 .dae 文件。顶点位置从不旋转：只有视图会按文件的格式
决定哪个轴朝上。]],
  }
  choose {
    { en = "A laser scan saved as .ply (the Stanford bunny, say) has no up axis in the file. Which does MeshEdit "
        .. "show up?",
      zh = "存成 .ply 的激光扫描（比如斯坦福兔子）在文件里没有写明向上轴。MeshEdit 会把哪个轴显示为朝上？" },
    options = { { en = "Y up", zh = "Y 轴向上" }, { en = "Z up", zh = "Z 轴向上" } }, answer = "Y up",
    feedback = {
      ["Y up"] = { en = "The Stanford scans stand on Y, and MeshLab keeps a scan's axes, so a .ply opens Y-up.",
        zh = "斯坦福的扫描模型以 Y 轴朝上站立，MeshLab 也保留扫描的坐标轴，所以 .ply 打开时 Y 轴向上。" },
      ["Z up"] = { en = "Z up is for .stl and .off: 3D printing and CAD put the build plate in the XY plane. "
          .. "Scans differ.",
        zh = "Z 轴向上用于 .stl 和 .off：3D 打印和 CAD 把打印平台放在 XY 平面上。扫描文件不一样。" },
    },
    hint = { en = "Think of where the scans come from, not of Blender.",
      zh = "想想这些扫描来自哪里，而不是想着 Blender。" },
  }
  choose {
    { en = "Blender's glTF export keeps +Y Up by default, glTF's own rule. You ticked it off, so the file is Z-up, and "
        .. "MeshEdit shows it lying on its side. What do you change?",
      zh = "Blender 的 glTF 导出默认勾选 +Y Up，这是 glTF 自己的规定。你取消了勾选，于是文件是 Z 轴向上的，"
        .. "MeshEdit 显示出来的模型是侧躺着的。你该改什么？" },
    options = { { en = "View > Up axis > Z up", zh = "视图 > 向上轴 > Z 轴向上" },
      { en = "Rotate it 90 degrees in Blender and export again", zh = "在 Blender 中把它旋转 90 度再重新导出" },
      { en = "Nothing: Ctrl+O again", zh = "什么都不改：再按一次 Ctrl+O" } },
    answer = "View > Up axis > Z up",
    feedback = {
      ["View > Up axis > Z up"] = { en = "Only the view turns; the file's coordinates stay as they are.",
        zh = "只有视图转动；文件里的坐标保持不变。" },
      ["Rotate it 90 degrees in Blender and export again"] = { en = "That changes every position in the file to fix "
        .. "what is only a question of the view.",
        zh = "这样做会改动文件中的每个位置，而要解决的只是视图的问题。" },
      ["Nothing: Ctrl+O again"] = { en = "Opening it again reads the same file the same way: a .glb is shown Y-up.",
        zh = "再打开一次，还是以同样的方式读同一个文件：.glb 会显示为 Y 轴向上。" },
    },
  }
  say {
    en = [[
The **status bar** says which axis is up. Y is up for .obj (Blender's default export), glTF and .ply; Z for .stl
and .off; a COLLADA file says so itself. **View > Up axis** overrides it for the file on screen.]],
    zh = [[
**状态栏** 会显示哪个轴朝上。.obj（Blender 的默认导出）、glTF 和 .ply 是 Y 轴向上；.stl 和 .off 是 Z 轴
向上；COLLADA 文件则由文件自己说明。**视图 > 向上轴** 可以为屏幕上的文件改变这一设定。]],
  }
end)

step({ en = "A bow-tie vertex", zh = "蝴蝶结顶点" }, function()
  local fixed, report = meshedit.repair(BOWTIE.positions, BOWTIE.polygons)
  show(fixed)
  camera { fit = true, pitch = 55 }  -- flat pieces: seen from above
  view { labels = false }
  label(fixed:vertex(0), { en = "vertex 0", zh = "顶点 0" })
  label(fixed:face(0), { en = "face 0", zh = "面 0" })
  label(fixed:face(1), { en = "face 1", zh = "面 1" })
  say {
    en = [[
A half-edge mesh can only hold an **oriented manifold**: at most two faces per edge, running along it in opposite
directions, and the faces around each vertex a single fan. On screen: two triangles from a file that share only
**vertex 0**, with nothing else between them, a bow-tie. MeshEdit refuses such a file, naming the faces and the
vertex. File > **Open a repaired copy** opens it repaired instead.]],
    zh = [[
半边网格只能容纳 **有向流形**：每条边最多属于两个面，且两个面沿这条边的走向相反；每个顶点周围的面组成单独一个扇形。
屏幕上是某个文件中的两个三角形，它们只共用 **顶点 0**，中间再没有别的东西，形如蝴蝶结。MeshEdit 会拒绝打开这样的
文件，并指出是哪些面和哪个顶点。改用 文件 > **打开修复后的副本**，就会打开修复后的网格。]],
  }
  answer {
    { en = "The file has " .. #BOWTIE.positions .. " vertices. How many does the repaired mesh have?",
      zh = "这个文件有 " .. #BOWTIE.positions .. " 个顶点。修复后的网格有多少个顶点？" },
    number = fixed:num_vertices(),
    feedback = function(value)
      if value == #BOWTIE.positions then
        return { en = "That is the file's count. A vertex can be the corner of one fan only: one triangle needs a "
          .. "vertex of its own there.",
          zh = "这是文件里的数目。一个顶点只能做一个扇形的角点：其中一个三角形在那里需要一个自己的顶点。" }
      end
      if value < #BOWTIE.positions then
        return { en = "The repair never merges or drops a vertex a face uses.",
          zh = "修复从不合并或删除任何被面用到的顶点。" }
      end
      return { en = "The repair adds one vertex per fan beyond the first, and here there are two fans.",
        zh = "修复为第一个扇形之外的每个扇形各添加一个顶点，而这里只有两个扇形。" }
    end,
  }
  local refused = refusal(BOWTIE.positions, BOWTIE.polygons)
  say({ en = "Refused as it is: " .. refused .. ".", zh = "按原样打开会被拒绝：" .. refused .. "。" })
  say({ en = "Repaired (meshedit.repair): " .. counts(fixed) .. ".\n\n" .. report_text(report),
    zh = "修复后（meshedit.repair）：" .. counts_zh(fixed) .. "。\n\n" .. report_text(report) })
  local moved = number_in(report, "%(face (%d+) moved%)")
  highlight(fixed:face(moved), "orange")
  say({ en = "The orange face, f" .. moved .. ", is the one moved to the new vertex, at the same place as vertex 0.",
    zh = "橙色的面 f" .. moved .. " 就是被移到新顶点上的那个面，新顶点与顶点 0 位于同一处。" })
end)

step({ en = "A fin and a flipped face", zh = "鳍与翻转的面" }, function()
  local fin_fixed, fin_report = meshedit.repair(FIN.positions, FIN.polygons)
  local detached = number_in(fin_report, "face (%d+) detached")
  show(fin_fixed)
  camera { fit = true, pitch = 30 }
  view { labels = false }
  for f = 0, 2 do label(fin_fixed:face(f), { en = "face " .. f, zh = "面 " .. f }) end
  label(fin_fixed:vertex(0), "0")
  label(fin_fixed:vertex(1), "1")
  say {
    en = [[
Three triangles on the edge from vertex 0 to vertex 1, a **fin**: face 0 runs 0 to 1, face 1 runs 1 to 0 and
face 2 runs 0 to 1 again. An edge keeps only two faces, one each way; the repair gives each other face corners of
its own there (it *detaches* it).]],
    zh = [[
从顶点 0 到顶点 1 的这条边上有三个三角形，形成一片 **鳍**：面 0 从 0 走到 1，面 1 从 1 走到 0，面 2 又从 0 走到 1。
一条边只能保留两个面，每个方向一个；对其余的面，修复会在那里给它一组自己的角点（即把它 *分离* 出去）。]],
  }
  choose {
    { en = "Which face does the repair detach?", zh = "修复会分离哪个面？" },
    options = { { en = "face 0", zh = "面 0" }, { en = "face 1", zh = "面 1" }, { en = "face 2", zh = "面 2" } },
    answer = "face " .. detached,
    feedback = {
      ["face " .. detached] = { en = "Yes: the repair keeps the edge for the first face and the first later face "
        .. "that runs the other way.",
        zh = "对：修复把这条边留给第一个面，以及其后第一个走向相反的面。" },
      ["face 0"] = { en = "Face 0 is the first face on the edge: it keeps it.",
        zh = "面 0 是这条边上的第一个面：它保留这条边。" },
      ["face 1"] = { en = "Face 1 runs 1 to 0, against face 0: the two are a proper pair, and it keeps the edge.",
        zh = "面 1 从 1 走到 0，与面 0 方向相反：两者正好配成一对，所以它保留这条边。" },
    },
  }
  local fin_refused = refusal(FIN.positions, FIN.polygons)
  say({ en = "Refused: " .. fin_refused .. ".", zh = "被拒绝：" .. fin_refused .. "。" })
  say({ en = "Repaired: " .. counts(fin_fixed) .. ".\n\n" .. report_text(fin_report),
    zh = "修复后：" .. counts_zh(fin_fixed) .. "。\n\n" .. report_text(fin_report) })
  highlight(fin_fixed:face(detached), "orange")

  local flip_fixed, flip_report = meshedit.repair(FLIPPED.positions, FLIPPED.polygons)
  local reversed = number_in(flip_report, "face (%d+) reversed")
  clear()
  show(flip_fixed)
  camera { fit = true, pitch = 55 }
  for f = 0, 1 do label(flip_fixed:face(f), { en = "face " .. f, zh = "面 " .. f }) end
  label(flip_fixed:vertex(0), "0")
  label(flip_fixed:vertex(1), "1")
  say {
    en = [[
Now two triangles on one edge that **both** run from vertex 0 to vertex 1: one of them faces the wrong way, and
the repair turns it.]],
    zh = [[
现在一条边上的两个三角形 **都** 从顶点 0 走到顶点 1：其中一个朝向错了，修复会把它翻过来。]],
  }
  choose {
    { en = "Which face does the repair reverse?", zh = "修复会反转哪个面？" },
    options = { { en = "face 0", zh = "面 0" }, { en = "face 1", zh = "面 1" },
      { en = "neither: it is refused", zh = "都不反转：它会被拒绝" } },
    answer = "face " .. reversed,
    feedback = {
      ["face " .. reversed] = { en = "Yes: the repair turns faces to agree with the lowest face of their piece, "
        .. "unless more of them already face the other way.",
        zh = "对：修复会把面翻转成与所在连通块中编号最小的面一致，除非已有更多的面朝向另一边。" },
      ["face 0"] = { en = "Face 0 is the lowest face of the piece, and the two are one each: the others follow face 0.",
        zh = "面 0 是这一块中编号最小的面，而两种朝向各有一个：其余的面随面 0 而定。" },
      ["neither: it is refused"] = { en = "from_polygons refuses it; meshedit.repair and Open a repaired copy fix it.",
        zh = "from_polygons 会拒绝它；meshedit.repair 和「打开修复后的副本」会修复它。" },
    },
  }
  highlight(flip_fixed:face(reversed), "orange")
  local flip_refused = refusal(FLIPPED.positions, FLIPPED.polygons)
  say({ en = "Refused: " .. flip_refused .. ".", zh = "被拒绝：" .. flip_refused .. "。" })
  say({ en = "Repaired: " .. counts(flip_fixed) .. ".\n\n" .. report_text(flip_report),
    zh = "修复后：" .. counts_zh(flip_fixed) .. "。\n\n" .. report_text(flip_report) })
end)

step({ en = "The Repairs tab", zh = "「修复」标签页" }, function()
  local positions, polygons = all_three()
  local fixed, report = meshedit.repair(positions, polygons)
  local reversed = number_in(report, "face (%d+) reversed")
  show(fixed)
  camera { fit = true, pitch = 55 }
  view { labels = false }
  for f = 0, fixed:num_faces() - 1 do label(fixed:face(f), "f" .. f) end
  choose {
    { en = "Ctrl+O refuses your file, naming faces and a vertex. How do you see it anyway?",
      zh = "Ctrl+O 拒绝打开你的文件，并指出了几个面和一个顶点。怎样才能照样看到它？" },
    options = { { en = "File > Open a repaired copy", zh = "文件 > 打开修复后的副本" },
      { en = "Edit > Triangulate", zh = "编辑 > 三角化" }, { en = "View > Up axis", zh = "视图 > 向上轴" } },
    answer = "File > Open a repaired copy",
    feedback = {
      ["Edit > Triangulate"] = { en = "Triangulate works on the mesh on screen, and a refused file never got there.",
        zh = "三角化作用于屏幕上的网格，而被拒绝的文件根本没能显示到屏幕上。" },
      ["View > Up axis"] = { en = "The up axis only turns the view; it cannot make a mesh of a file that is refused.",
        zh = "向上轴只会转动视图；它没法把一个被拒绝的文件变成网格。" },
    },
  }
  say({ en = [[
The three pieces side by side, as one file with all three problems, opened repaired. The **Repairs** tab lists
every change with the file's own vertex and face numbers; clicking a row selects and highlights its spot. Here is
the list the repair gives, for a mesh of ]] .. counts(fixed) .. ".\n\n" .. report_text(report),
    zh = [[
这三块并排放在一起，当作同时有这三种问题的一个文件，以修复后的形式打开。**修复** 标签页列出每一处改动，
使用的是文件自己的顶点和面编号；单击一行就会选中并高亮它所在的位置。下面是修复给出的列表，修复后的网格有
]] .. counts_zh(fixed) .. "。\n\n" .. report_text(report) })
  pick {
    { en = "Click the face the row \"... reversed ...\" names, as a click on that row would select it.",
      zh = "点击「... reversed ...」那一行所指的面，就像单击那一行时会选中的那样。" },
    answer = function(e)
      if e.kind ~= "face" then
        return false, { en = "That is a " .. e.kind .. ": click inside a triangle.",
          zh = "这是一个" .. (KIND_ZH[e.kind] or " " .. e.kind .. " ") .. "：请点击三角形内部。" }
      end
      return e.id == reversed
    end,
    feedback = function(e)
      if e.kind == "face" then
        return { en = "f" .. e.id .. " faced the right way already. Nothing was dropped, so a face "
          .. "keeps the file's number.",
          zh = "f" .. e.id .. " 本来就朝向正确。没有删除任何面，所以每个面都保留它在文件中的编号。" }
      end
    end,
  }
  highlight(fixed:face(reversed), "orange")
  say {
    en = [[
Outside the window: `meshedit info FILE` lists what a repair would change, and `meshedit repair IN -o OUT` writes
the repaired copy. In Lua, `meshedit.repair(positions, polygons)` returns the mesh and this report.]],
    zh = [[
在窗口之外：`meshedit info FILE` 列出修复将做的改动，`meshedit repair IN -o OUT` 写出修复后的副本。在 Lua 中，
`meshedit.repair(positions, polygons)` 返回修复后的网格和这份报告。]],
  }
end)

-- A scan patch shipped with the app (assets/scan_with_defects.ply, see assets/README.md): a flipped face, a repeated
-- face and a loose triangle touching the patch at one corner, as scans have.
local SCAN = "../assets/scan_with_defects.ply"

step({ en = "Open a scan with defects", zh = "打开一个有缺陷的扫描" }, function()
  local scan, report = meshedit.load(lesson_file(SCAN), { repair = true })
  say({ en = [[
Now a real file. The app ships a small scanned patch in MeshEdit's folder, **assets/scan_with_defects.ply**. Open
it with **File > Open** (Ctrl+O): it is refused, and the status bar names the problem. Then **File > Open a
repaired copy**.]],
    zh = [[
现在来看一个真实的文件。应用在 MeshEdit 的文件夹里附带了一小块扫描面片 **assets/scan_with_defects.ply**。用
**文件 > 打开**（Ctrl+O）打开它：它会被拒绝，状态栏会指出问题所在。然后选 **文件 > 打开修复后的副本**。]] })
  answer {
    { en = "Before you open it: the file has " .. (scan:num_faces() + 1) .. " faces, and one of them repeats "
        .. "another. How many faces will the repaired copy have?",
      zh = "打开之前先想一想：这个文件有 " .. (scan:num_faces() + 1) .. " 个面，其中一个与另一个重复。"
        .. "修复后的副本会有多少个面？" },
    number = scan:num_faces(),
    feedback = function(value)
      if value == scan:num_faces() + 1 then
        return { en = "The repeated face is dropped: it is the same triangle twice.",
          zh = "重复的面会被删除：它是同一个三角形出现了两次。" }
      end
      if value < scan:num_faces() then
        return { en = "Only the repeated face goes; a flipped face is turned, not dropped.",
          zh = "只有重复的面会被去掉；翻转的面会被翻回来，而不是删除。" }
      end
    end,
    hint = { en = "Which of a repeat, a flipped face and a bow-tie corner removes a face?",
      zh = "重复的面、翻转的面和蝴蝶结角点，哪一种会去掉一个面？" },
  }
  wait_for {
    hint = { en = "File > Open assets/scan_with_defects.ply, then File > Open a repaired copy",
      zh = "文件 > 打开 assets/scan_with_defects.ply，然后 文件 > 打开修复后的副本" },
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == scan:num_faces() and m:num_vertices() == scan:num_vertices()
    end,
  }
  camera "fit"
  say({ en = "The repaired copy: " .. counts(scan) .. ". The Repairs tab lists what was done, in the file's "
    .. "numbers:\n\n" .. report_text(report) .. "\n\nClick its rows: each one selects its spot on the patch.",
    zh = "修复后的副本：" .. counts_zh(scan) .. "。「修复」标签页用文件中的编号列出了所做的改动：\n\n"
      .. report_text(report) .. "\n\n单击其中的各行：每一行都会在面片上选中它所在的位置。" })
end)

-- Suzanne, Blender's test character, as Blender 3.4 exports her to .obj with its default settings (assets/README.md):
-- quads and triangles, and a hole at each eye.
local SUZANNE = "../assets/suzanne.obj"

-- How many faces of `mesh` have `sides` sides.
local function faces_with(mesh, sides)
  local n = 0
  for f in mesh:faces() do if f:degree() == sides then n = n + 1 end end
  return n
end

step({ en = "Triangulate the quads", zh = "把四边形三角化" }, function()
  local suzanne = meshedit.load(lesson_file(SUZANNE))
  show(suzanne, { up = "y" }) -- her .obj is Y-up, as opening it in the window shows her
  camera "fit"
  view { labels = false, halfedges = false }
  local quads, triangles_before = faces_with(suzanne, 4), faces_with(suzanne, 3)
  say({ en = "A Blender export keeps Blender's quads unless you triangulate. On screen: **Suzanne**, Blender's test "
    .. "character, exported to .obj as Blender does by default (assets/suzanne.obj): " .. counts(suzanne) .. ", "
    .. quads .. " of the faces quads and " .. triangles_before .. " triangles. Press **L** to try Loop "
    .. "subdivision on her.",
    zh = "除非你做三角化，Blender 导出的文件会保留 Blender 的四边形。屏幕上是 **Suzanne**（Blender 的测试角色），"
      .. "按 Blender 的默认设置导出为 .obj（assets/suzanne.obj）：" .. counts_zh(suzanne) .. "，其中 "
      .. quads .. " 个面是四边形，" .. triangles_before .. " 个是三角形。按 **L** 键，试着对她做 Loop 细分。" })
  wait_for { key = "L", hint = { en = "Press L", zh = "按 L" } }
  local loop_ok, why = suzanne:copy():loop_subdivide()
  assert(not loop_ok, "Loop subdivision was meant to refuse quads")
  say({ en = "Loop subdivision refuses her, and the status bar says why: " .. why .. ".",
    zh = "Loop 细分拒绝处理她，状态栏给出了原因：" .. why .. "。" })
  local triangles = suzanne:copy()
  local split = triangles:triangulate()
  answer {
    { en = "How many faces will she have after Edit > Triangulate?",
      zh = "执行 编辑 > 三角化 之后，她会有多少个面？" },
    number = triangles:num_faces(),
    feedback = function(value)
      if value == suzanne:num_faces() then
        return { en = "That is the number of faces now. Each quad is cut in two.",
          zh = "这是她现在的面数。每个四边形会被切成两个。" }
      end
      if value == 4 * quads + triangles_before then
        return { en = "Four per quad is a cut through the centre; triangulation adds no vertex, so a quad makes "
          .. "n - 2 = 2.",
          zh = "每个四边形变成四个，那是穿过中心的切法；三角化不添加顶点，所以一个四边形得到 n - 2 = 2 个三角形。" }
      end
      if value == 2 * suzanne:num_faces() then
        return { en = "The " .. triangles_before .. " triangles stay as they are.",
          zh = "原有的 " .. triangles_before .. " 个三角形保持不变。" }
      end
    end,
    hint = { en = "A face of n corners becomes n - 2 triangles.", zh = "有 n 个角点的面会变成 n - 2 个三角形。" },
  }
  say { en = "Now do it: **Edit > Triangulate** on the mesh on screen.",
    zh = "现在动手：对屏幕上的网格执行 **编辑 > 三角化**。" }
  local yours = wait_for {
    hint = { en = "Edit > Triangulate", zh = "编辑 > 三角化" },
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == triangles:num_faces() and m:validate() and m
    end,
  }
  say({ en = "Triangulate split " .. split .. " faces: " .. counts(suzanne) .. " before, " .. counts(yours)
    .. " after. No vertex was added or moved. In Lua it is mesh:triangulate(); on the shell, "
    .. "`meshedit triangulate IN -o OUT`.",
    zh = "三角化分裂了 " .. split .. " 个面：之前 " .. counts_zh(suzanne) .. "，之后 " .. counts_zh(yours)
      .. "。没有添加或移动任何顶点。在 Lua 中它是 mesh:triangulate()；在命令行中是 "
      .. "`meshedit triangulate IN -o OUT`。" })
end)

step({ en = "Subdivide it", zh = "细分它" }, function()
  local mesh = current_mesh()
  if not mesh then
    local triangles = meshedit.load(lesson_file(SUZANNE))
    triangles:triangulate()
    show(triangles, { up = "y" })
    mesh = current_mesh()
  end
  local ok_loop, why = mesh:copy():loop_subdivide()
  if not ok_loop then
    say({ en = "The mesh on screen cannot be Loop-subdivided: " .. why .. ". Go Back to triangulate it.",
      zh = "屏幕上的网格无法做 Loop 细分：" .. why .. "。按「上一步」回去把它三角化。" })
    return
  end
  say({ en = "Press **L** to subdivide the mesh on screen (" .. counts(mesh) .. ").",
    zh = "按 **L** 键细分屏幕上的网格（" .. counts_zh(mesh) .. "）。" })
  local after = wait_for {
    hint = { en = "Press L", zh = "按 L" },
    condition = function()
      local m = current_mesh()
      return m and m:num_faces() == 4 * mesh:num_faces() and m:validate() and m
    end,
  }
  camera "fit"
  say({ en = "Loop: " .. counts(after) .. ".", zh = "Loop 细分：" .. counts_zh(after) .. "。" })
  local cc = mesh:copy()
  assert(cc:catmull_clark())
  answer {
    { en = "The Subdivide menu also has Catmull-Clark. How many faces would it make of the " .. mesh:num_faces()
        .. " triangles you had before L?",
      zh = "「细分」菜单里还有 Catmull-Clark 细分。对你按 L 之前的 " .. mesh:num_faces()
        .. " 个三角形，它会生成多少个面？" },
    number = cc:num_faces(),
    feedback = function(value)
      if value == after:num_faces() then
        return { en = "That is Loop's count, four per triangle. Catmull-Clark makes one quad per corner of each face.",
          zh = "这是 Loop 细分的面数，每个三角形变四个。Catmull-Clark 细分为每个面的每个角点各生成一个四边形。" }
      end
    end,
  }
  local linear = mesh:copy()
  assert(linear:linear_subdivide())
  say({ en = "Catmull-Clark: " .. counts(cc) .. ", all quads. The menu's **Linear** cuts the same way as Loop ("
    .. counts(linear) .. ") but moves no vertex. Save any of them with File > Save as... and open it in Blender.",
    zh = "Catmull-Clark 细分：" .. counts_zh(cc) .. "，全是四边形。菜单中的 **线性细分** 与 Loop 细分的切分方式相同（"
      .. counts_zh(linear) .. "），但不移动任何顶点。任选其一，用 文件 > 另存为... 保存，再在 Blender 中打开。" })
end)
