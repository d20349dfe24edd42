-- The welcome lesson: what MeshEdit is for, how to look around, how to pick elements, and the keys every
-- later lesson uses (the student flips an edge with one of them). CI runs it headless with scripted answers:
--   meshedit lesson lessons/welcome.lua --headless --answers tests/lesson/lessons/welcome_answers.lua

lesson {
  title = { en = "Welcome to MeshEdit", zh = "欢迎使用 MeshEdit" },
  summary = {
    en = "What this app is for, how to look around and pick elements, and the keys you will use in every part.",
    zh = "这个应用是做什么的，怎样四处查看、选取元素，以及之后每个部分都要用到的按键。",
  },
}

local cube = meshedit.cube()

step({ en = "What MeshEdit is", zh = "MeshEdit 是什么" }, function()
  show(cube)
  camera "fit"
  say {
    en = [[
# Welcome

MeshEdit is a workbench for **geometric modelling**: the curves and surfaces that modelling programs,
games and films are built from. You will build each piece yourself, and see every step it takes.]],
    zh = [[
# 欢迎

MeshEdit 是一个 **几何建模** 的工作台。几何建模研究曲线和曲面，建模软件、游戏和电影都是用它们搭建起来的。
每一部分你都会亲手实现，并看清它执行的每一步。]],
  }
  say {
    en = [[
The lessons follow the parts of the assignment:

- **Bézier curves**, evaluated by de Casteljau's algorithm, one level at a time
- **Bézier patches**, the surfaces the Utah teapot is made of
- **half-edge meshes**: walking around faces and vertices, and vertex normals
- **edge flip** and **edge split**, the two local operations
- **Loop subdivision**, which turns a coarse mesh into a smooth one
- and, beyond the assignment, **Catmull-Clark** subdivision and **bringing your own mesh**]],
    zh = [[
课程按作业的各个部分展开：

- **贝塞尔曲线**，用 de Casteljau 算法逐层求值
- **贝塞尔曲面片**，犹他茶壶就是由它们拼成的
- **半边网格**：绕着面和顶点行走，以及顶点法向量
- **边翻转** 和 **边分裂**，两种局部操作
- **Loop 细分**，把粗糙的网格变成光滑的网格
- 以及作业之外的 **Catmull-Clark** 细分和 **导入你自己的网格**]],
  }
  say {
    en = [[
On screen is a cube made of 12 triangles, stored as a half-edge mesh. Press **Next** when you are ready.]],
    zh = [[
屏幕上是一个由 12 个三角形组成的立方体，以半边网格的形式存储。准备好了就按 **下一步**。]],
  }
end)

step({ en = "Look around", zh = "四处看看" }, function()
  say {
    en = [[
Drag with the mouse to **orbit** around the cube. Hold Shift (or the middle button) and drag to **pan**;
turn the wheel to **zoom**. **Space** brings the view back.]],
    zh = [[
用鼠标拖动，可以绕着立方体 **旋转** 视角。按住 Shift（或鼠标中键）拖动可以 **平移**；
转动滚轮可以 **缩放**。按 **Space** 键让视图复位。]],
  }
  say {
    en = [[
Two keys change how the mesh is drawn:

- **W** switches the wireframe on and off: the edges drawn over the faces
- **Q** switches between flat shading (one normal per face) and smooth (Phong) shading

Press **W** now.]],
    zh = [[
有两个键可以改变网格的绘制方式：

- **W** 打开或关闭线框，也就是画在面上的那些边
- **Q** 在平直着色（每个面一个法向量）和平滑（Phong）着色之间切换

现在按 **W**。]],
  }
  wait_for { key = "W", hint = { en = "Press W to switch the wireframe", zh = "按 W 切换线框" } }
  say {
    en = [[
Well done. Keep the wireframe on: from now on you will want to see every edge.]],
    zh = [[
很好。让线框一直开着：从现在起，你会希望看清每一条边。]],
  }
end)

step({ en = "Pick a vertex", zh = "选取一个顶点" }, function()
  say {
    en = [[
A mesh is made of **vertices** (points), **edges** (segments between two vertices) and **faces** (the
polygons the edges enclose). Every element has an id: `v3` is vertex 3, `e7` edge 7, `f2` face 2.]],
    zh = [[
网格由 **顶点**（点）、**边**（连接两个顶点的线段）和 **面**（由边围成的多边形）组成。
每个元素都有一个编号：`v3` 是顶点 3，`e7` 是边 7，`f2` 是面 2。]],
  }
  say {
    en = [[
**Click** on a corner of the cube to select a vertex. If the dots are hidden, turn them on in the
**View** menu. Press **I** to open the inspector: it lists everything about the selection.]],
    zh = [[
**点击** 立方体的一个角，选中一个顶点。如果看不到顶点的圆点，可以在 **视图** 菜单里打开它们。
按 **I** 打开检查器：它会列出所选元素的全部信息。]],
  }
  local v = wait_for { click = "vertex" }
  highlight(v, "yellow")
  label(v, { en = "you are here", zh = "你在这里" })
  if type(v) == "string" then
    say({ en = "You picked **" .. v .. "**.", zh = "你选中了 **" .. v .. "**。" })
  else
    say({
      en = "You picked **" .. tostring(v) .. "**. " .. v:degree() .. " edges meet there: that number is the vertex's "
        .. "**degree**. The inspector shows it too.",
      zh = "你选中了 **" .. tostring(v) .. "**。有 " .. v:degree() .. " 条边在这里交汇：这个数就是该顶点的 **度数**。"
        .. "检查器里也会显示它。",
    })
  end
end)

step({ en = "Walk the halfedges", zh = "沿着半边行走" }, function()
  say {
    en = [[
Inside the mesh, every edge is two **halfedges**, one for each face beside it, pointing opposite ways.
A halfedge knows five things: `next` (the following halfedge around its face), `twin` (its partner
across the edge), `vertex` (where it starts), `edge` and `face`. Everything else is found by walking.]],
    zh = [[
在网格内部，每条边由两条 **半边** 组成，分别属于它两侧的面，方向相反。
一条半边知道五件事：`next`（绕它所在的面的下一条半边）、`twin`（边另一侧与它配对的半边）、
`vertex`（它的起点）、`edge` 和 `face`。其余的一切都靠沿着指针行走得到。]],
  }
  say {
    en = [[
With something selected, press **N** to go to the *next* halfedge. (From a vertex, N first takes the
vertex's own halfedge, then its next.)]],
    zh = [[
选中某个元素后，按 **N** 走到 *下一条* 半边（next）。（从顶点出发时，N 先走到这个顶点自己的半边，
之后才是它的 next。）]],
  }
  wait_for { key = "N", hint = { en = "Press N to walk to the next halfedge", zh = "按 N 走到下一条半边" } }
  say {
    en = [[
Press **N** two more times: the cube's faces are triangles, so three presses bring you back to the halfedge
you started from (from a vertex: its own halfedge). Then press **T** to jump to the *twin*, into the
neighbouring face. **V**, **E** and **H** take you to the vertex, the edge and back to a halfedge. This walking
is exactly what your code will do.]],
    zh = [[
再按两次 **N**：立方体的面都是三角形，所以按三次就回到出发时的那条半边（从顶点出发时：回到它自己的半边）。
然后按 **T** 跳到 *twin*，进入相邻的面。**V**、**E** 和 **H** 分别带你到顶点、到边，以及回到一条半边。
你的代码要做的，正是这样的行走。]],
  }
end)

-- The two vertices edge `id` of `mesh` joins, as "v1 and v2" (`joiner` in place of " and ": " 和 " for the Chinese).
local function ends_of(mesh, id, joiner)
  local h = mesh:edge(id).halfedge
  return tostring(h.vertex) .. (joiner or " and ") .. tostring(h.twin.vertex)
end

step({ en = "Keys for the parts ahead", zh = "后面各部分要用的按键" }, function()
  show(cube)
  local diagonal = 11  -- e11 cuts the front square (y = -0.5, facing the start view) into two triangles
  highlight(cube:edge(diagonal), "orange")
  label(cube:edge(diagonal), "e11")
  say({
    en = "Some keys change the mesh. Try one: the orange edge e11, the diagonal of the front square, joins "
      .. ends_of(cube, diagonal) .. ". **Click** it to select it, then press **F** and watch which corners it joins "
      .. "afterwards.",
    zh = "有些键会修改网格。试一个：橙色的边 e11 是正面那个正方形的对角线，连接着 " .. ends_of(cube, diagonal, " 和 ")
      .. "。**点击** 选中它，然后按 **F**，看看它之后连接的是哪两个角。",
  })
  wait_for { selection = "e11", hint = { en = "Click the orange edge e11", zh = "点击橙色的边 e11" } }
  wait_for { key = "F", hint = { en = "Press F to flip e11", zh = "按 F 翻转 e11" } }
  local flipped = current_mesh()
  if flipped and ends_of(flipped, diagonal) ~= ends_of(cube, diagonal) then
    say({
      en = "e11 now joins " .. ends_of(flipped, diagonal) .. ": it turned inside its two triangles to join their "
        .. "other two corners, the square's other diagonal. That was an **edge flip**, part 4 of the assignment.",
      zh = "e11 现在连接的是 " .. ends_of(flipped, diagonal, " 和 ") .. "：它在自己的两个三角形内部转了过去，"
        .. "连接起它们另外两个角，也就是正方形的另一条对角线。这就是 **边翻转**，作业的第 4 部分。",
    })
  end
  say {
    en = [[
Every change can be undone with **Ctrl+Z** (and redone with **Ctrl+Y**). The keys that change the mesh:

- **F** flips the selected edge: it turns to join the other two corners of its two triangles
- **S** splits the selected edge: a new vertex in its middle, joined to the opposite corners
- **L** runs one step of Loop subdivision; **Shift+L** runs it one phase at a time
- **C** collapses the selected edge into a single vertex]],
    zh = [[
每次修改都可以用 **Ctrl+Z** 撤销（用 **Ctrl+Y** 重做）。会修改网格的按键有：

- **F** 翻转选中的边：它转过去，连接它两个三角形的另外两个角
- **S** 分裂选中的边：在它的中点处加一个新顶点，并与对面的角相连
- **L** 运行一步 Loop 细分；**Shift+L** 每次只运行其中一个阶段
- **C** 把选中的边坍缩成一个顶点]],
  }
  say {
    en = [[
The pointer tables in the right column (the **Pointers** tab) show every `next`, `twin`, `vertex`, `edge` and
`face`: after an edit, the cells that changed are highlighted. Press **F1** any time for the list of keys.]],
    zh = [[
右侧栏的指针表（**指针** 标签页）列出每一个 `next`、`twin`、`vertex`、`edge` 和 `face`：
每次编辑之后，发生变化的单元格会高亮显示。任何时候按 **F1** 都能查看按键列表。]],
  }
  say {
    en = [[
That is all you need. Open the lesson list to start with **de Casteljau's algorithm**.]],
    zh = [[
需要知道的就这些。打开课程列表，从 **de Casteljau 算法** 开始吧。]],
  }
end)
