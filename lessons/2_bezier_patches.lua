-- Part 2: Bézier patches: a 4x4 grid of control points, evaluated as four curves in u (the rows) and then
-- one curve in v (the column through the row points); the normal at (u, v) from the two tangents, on the probe the
-- student moves; then the Utah teapot, 32 such patches, and what makes two of them meet smoothly. Each step asks the
-- student to predict before it shows, and names the likely mistakes (u and v swapped, rows and columns swapped).
-- Numbers come from the project's Bézier code (meshedit.patch, p:evaluation), and the teapot from
-- assets/teapot.bez, found next to this file with lesson_file(). The last step runs the student's own evaluate
-- (your_turn) at the (u, v) of the hand computation. CI runs it headless:
--   meshedit lesson lessons/2_bezier_patches.lua --headless \
--     --answers tests/lesson/lessons/2_bezier_patches_answers.lua --student tests/exercise/solutions

lesson {
  title = { en = "Bézier patches and the teapot", zh = "贝塞尔曲面片与犹他茶壶" },
  summary = {
    en = "From curves to surfaces: sixteen control points, rows in u then a column in v, and the teapot.",
    zh = "从曲线到曲面：十六个控制点，先沿 u 求各行，再沿 v 求一列，最后是犹他茶壶。",
  },
}

-- A gentle hill over [0, 3] x [0, 3]: row r (0..3) at y = r, column c at x = c; the middle four points raised.
local hill_points = {}
for r = 0, 3 do
  for c = 0, 3 do
    local raised = (r == 1 or r == 2) and (c == 1 or c == 2)
    hill_points[#hill_points + 1] = { c, r, raised and 2 or 0 }
  end
end
local hill = meshedit.patch(hill_points)

local function pt(p)
  return string.format("(%g, %g, %g)", p.x, p.y, p.z)
end

-- A unit vector with three decimals: "(-0.647, 0.144, 0.749)".
local function unit(n)
  return string.format("(%.3f, %.3f, %.3f)", n.x, n.y, n.z)
end

local function near(p, q, tolerance)
  return (p - q):length() < (tolerance or 1e-3)
end

step({ en = "From curves to surfaces", zh = "从曲线到曲面" }, function()
  show(hill)
  camera "fit"
  say {
    en = [[
# Bézier patches

A **Bézier patch** is a surface made from a 4 by 4 grid of **control points**, 16 in all. On screen is a
small hill: the twelve points around the edge lie flat, the four in the middle are raised to height 2.
Each of the four **rows** of the grid is the control polygon of a cubic curve, as in part 1.]],
    zh = [[
# 贝塞尔曲面片

**贝塞尔曲面片** 是由排成 4 行 4 列网格的 **控制点** 构成的曲面，共 16 个控制点。屏幕上是一座小山：
边缘一圈的十二个点平放在地面上，中间的四个点被抬高到高度 2。
网格的每一 **行** 都是一条三次曲线的控制多边形，和第 1 部分一样。]],
  }
  choose {
    { en = "Which of the control points does the surface pass through?", zh = "曲面经过哪些控制点？" },
    options = {
      { en = "all sixteen", zh = "全部十六个" },
      { en = "the four corners", zh = "四个角点" },
      { en = "the four raised middle points", zh = "中间被抬高的四个点" },
      { en = "the twelve around the edge", zh = "边缘一圈的十二个点" },
    },
    answer = "the four corners",
    feedback = {
      ["all sixteen"] = {
        en = "A curve does not pass through its middle control points; a patch, made of curves, does "
          .. "not either.",
        zh = "曲线不经过它中间的控制点；由曲线构成的曲面片也同样不经过。",
      },
      ["the four raised middle points"] = {
        en = "The raised points pull the surface up, but it stays below them: look "
          .. "at the top of the hill.",
        zh = "抬高的点把曲面向上拉，但曲面始终在它们下方：看看山顶。",
      },
      ["the twelve around the edge"] = {
        en = "Each edge of the patch is a cubic curve: it passes through the ends of "
          .. "its control polygon, not through its middle points.",
        zh = "曲面片的每条边缘都是一条三次曲线：它经过控制多边形的两个端点，而不经过中间的点。",
      },
      ["the four corners"] = {
        en = "Yes: each edge is a cubic through its two end points, the corners.",
        zh = "对：每条边缘都是一条经过其两个端点（也就是角点）的三次曲线。",
      },
    },
    hint = {
      en = "Each edge of the patch is a cubic curve with four of the control points. Which of them does it reach?",
      zh = "曲面片的每条边缘都是一条三次曲线，由其中四个控制点决定。它真正经过的是哪几个？",
    },
  }
  say {
    en = [[
The patch has two parameters, **u** and **v**, both between 0 and 1, one for each direction of the grid:
**u** runs along a row (here along x), **v** across the rows (along y).]],
    zh = [[
曲面片有两个参数 **u** 和 **v**，取值都在 0 到 1 之间，分别对应网格的两个方向：
**u** 沿着一行变化（这里是沿 x 方向），**v** 跨越各行变化（沿 y 方向）。]],
  }
  choose {
    {
      en = "The points are stored row by row: `points[row * 4 + col + 1]`. Which index holds row 1, column 2 (rows and "
        .. "columns counted from 0)?",
      zh = "控制点按行依次存放：`points[row * 4 + col + 1]`。第 1 行、第 2 列的点（行和列都从 0 开始数）"
        .. "存放在哪个下标？",
    },
    options = { "6", "7", "10" },
    answer = "7",
    feedback = {
      ["10"] = {
        en = "10 = 2 * 4 + 1 + 1 is row 2, column 1: rows and columns swapped. The row is multiplied by 4.",
        zh = "10 = 2 * 4 + 1 + 1 是第 2 行、第 1 列：行和列弄反了。乘以 4 的是行号。",
      },
      ["6"] = {
        en = "6 = 1 * 4 + 2 is the index counted from 0; Lua lists start at 1, hence the + 1.",
        zh = "6 = 1 * 4 + 2 是从 0 开始数的下标；Lua 的列表从 1 开始，所以还要 + 1。",
      },
      ["7"] = { en = "Yes: 1 * 4 + 2 + 1 = 7.", zh = "对：1 * 4 + 2 + 1 = 7。" },
    },
    hint = {
      en = "A row holds 4 points, so each row moves the index on by 4.",
      zh = "每行有 4 个点，所以每多一行，下标就增加 4。",
    },
  }
  say {
    en = "`points[7]` of the hill is " .. pt(hill.points[7]) .. ": x is the column, y the row, and it is raised.",
    zh = "小山的 `points[7]` 是 " .. pt(hill.points[7]) .. "：x 是列，y 是行，而且它被抬高了。",
  }
end)

step({ en = "Rows in u", zh = "先沿 u 求各行" }, function()
  show(hill)
  say {
    en = [[
To evaluate the patch at (u, v), use de Casteljau twice:

- first, evaluate each of the **four rows** as a curve at **u**: that gives four points
- then, those four points are the control points of one more curve, the **column**: evaluate it at **v**]],
    zh = [[
要求曲面片在 (u, v) 处的点，需要用两次 de Casteljau 算法：

- 先把 **四行** 各自当作一条曲线，在 **u** 处求值：得到四个点
- 再把这四个点当作另一条曲线（即 **列**）的控制点，在 **v** 处求值]],
  }
  choose {
    {
      en = "How many one-dimensional de Casteljau evaluations (whole curves, each down to a single point) does one "
        .. "point of a patch take?",
      zh = "求曲面片上的一个点，需要做几次一维的 de Casteljau 求值（每次求一整条曲线，一直算到只剩一个点）？",
    },
    options = { "4", "5", "8", "16" },
    answer = "5",
    feedback = {
      ["4"] = {
        en = "4 are the rows: their four points still need one more curve, the column, to become one point.",
        zh = "4 只是各行：得到的四个点还要再经过一条曲线（即列），才能变成一个点。",
      },
      ["8"] = {
        en = "8 evaluates every row and every column of the grid; only one column is needed, the one through the "
          .. "four row points.",
        zh = "8 是把网格的每一行和每一列都求一遍；其实只需要一列，就是由四个行点构成的那一列。",
      },
      ["16"] = {
        en = "16 is the number of control points, not of curves: each curve takes a whole row of four.",
        zh = "16 是控制点的个数，不是曲线的条数：每条曲线要用掉一整行的四个点。",
      },
      ["5"] = { en = "Yes: four rows and one column.", zh = "对：四行，再加一列。" },
    },
    hint = {
      en = "Count the row curves, then the curves that the row points make.",
      zh = "先数行曲线有几条，再数由行点构成的曲线有几条。",
    },
  }
  local row1 = meshedit.curve { hill.points[5], hill.points[6], hill.points[7], hill.points[8] }
  local at = row1:evaluate(0.25)
  answer {
    {
      en = "Row 1 is (0, 1, 0), (1, 1, 2), (2, 1, 2), (3, 1, 0). Where is its point at u = 0.25? Give x, y, z.",
      zh = "第 1 行是 (0, 1, 0)、(1, 1, 2)、(2, 1, 2)、(3, 1, 0)。它在 u = 0.25 处的点在哪里？请给出 x、y、z。",
    },
    point = { at.x, at.y, at.z },
    feedback = function(p)
      local swapped = row1:evaluate(0.75)
      if near(p, swapped) then
        return {
          en = pt(p) .. " is the row's point at 0.75: u and 1 - u swapped.",
          zh = pt(p) .. " 是这一行在 0.75 处的点：把 u 和 1 - u 弄反了。",
        }
      end
      if near(p, meshedit.vec3(1.5, 1, 1)) then
        return {
          en = "(1.5, 1, 1) is the average of the row's four points: the curve's point weights them.",
          zh = "(1.5, 1, 1) 是这一行四个点的平均值：而曲线上的点是它们的加权组合。",
        }
      end
      if math.abs(p.x - at.x) < 1e-3 and math.abs(p.z - at.z) > 1e-3 then
        return {
          en = "x is right; the height is not: run the steps on z too, 0, 2, 2, 0.",
          zh = "x 对了，高度不对：对 z 也做同样的步骤，也就是 0, 2, 2, 0。",
        }
      end
    end,
    hint = {
      en = "Its heights 0, 2, 2, 0 are part 1's y values, so z is part 1's y at 0.25; x goes 0, 1, 2, 3, evenly "
        .. "spaced, so x = 3u.",
      zh = "它的高度 0, 2, 2, 0 正是第 1 部分的 y 值，所以 z 就是第 1 部分在 0.25 处的 y；"
        .. "x 依次为 0, 1, 2, 3，间距均匀，所以 x = 3u。",
    },
  }
  local e = hill:evaluation(0.25, 0.5)
  local rows = {}
  for i, p in ipairs(e.rows) do rows[i] = pt(p) end
  say {
    en = "Yes. The four rows at u = 0.25 give " .. table.concat(rows, ", ")
      .. ": the two flat rows stay at height 0, and every row point has x = 0.75.",
    zh = "对。四行在 u = 0.25 处给出 " .. table.concat(rows, ", ")
      .. "：平的两行仍在高度 0，每个行点的 x 都是 0.75。",
  }
end)

step({ en = "Then the column in v", zh = "再沿 v 求那一列" }, function()
  show(hill)
  local u, v = 0.25, 0.5
  local e = hill:evaluation(u, v)
  local swapped = hill:evaluate(v, u)
  local rows = {}
  for i, p in ipairs(e.rows) do rows[i] = pt(p) end
  say {
    en = "The four row points at u = 0.25 are " .. table.concat(rows, ", ") .. ". They are the control points of "
      .. "the column curve.",
    zh = "u = 0.25 时的四个行点是 " .. table.concat(rows, ", ") .. "。它们就是列曲线的控制点。",
  }
  answer {
    {
      en = "Where is the patch's point P(0.25, 0.5)? Give x, y, z.",
      zh = "曲面片上的点 P(0.25, 0.5) 在哪里？请给出 x、y、z。",
    },
    point = { e.point.x, e.point.y, e.point.z },
    feedback = function(p)
      if near(p, swapped) then
        return {
          en = pt(p) .. " is P(0.5, 0.25): u and v swapped. u is for the rows (x here), v for the column through "
            .. "the row points (y).",
          zh = pt(p) .. " 是 P(0.5, 0.25)：u 和 v 弄反了。u 用于各行（这里是 x），v 用于由各行点决定的那一列（y）。",
        }
      end
      if near(p, e.rows[2]) or near(p, e.rows[3]) then
        return {
          en = pt(p) .. " is a row point: the column curve through all four row points is still to evaluate.",
          zh = pt(p) .. " 是一个行点：还需要对由四个行点决定的列曲线求值。",
        }
      end
      if math.abs(p.z - 0.5625) < 1e-3 then
        return {
          en = "z = 0.5625 is the average of the row points' heights: the column's point weights them.",
          zh = "z = 0.5625 是各行点高度的平均值：而列曲线上的点是它们的加权组合。",
        }
      end
    end,
    hint = {
      en = "Run de Casteljau on the four row points at v = 0.5; x stays 0.75.",
      zh = "在 v = 0.5 处对四个行点运行 de Casteljau 算法；x 仍然是 0.75。",
    },
  }
  say {
    en = "Yes: **P(0.25, 0.5) = " .. pt(e.point) .. "**. See it in the patch view: set **u** to 0.25 and **v** to "
      .. "0.5; the probe point P(u, v) is drawn on the surface and listed in the panel. Swapping u and v gives "
      .. pt(swapped) .. ", the mirror point across the diagonal: on this symmetric hill only x and y tell them apart.",
    zh = "对：**P(0.25, 0.5) = " .. pt(e.point) .. "**。在曲面片视图中看看它：把 **u** 设为 0.25，**v** 设为 "
      .. "0.5；探测点 P(u, v) 会画在曲面上，并列在面板中。交换 u 和 v 得到 "
      .. pt(swapped) .. "，即关于对角线的镜像点：在这座对称的小山上，只有 x 和 y 能把两者区分开。",
  }
  say {
    en = [[
Doing the columns in v first and then a row in u gives the very same point; MeshEdit follows the assignment's
order, rows first.]],
    zh = [[
先沿 v 求各列、再沿 u 求一行，得到的是完全相同的点；MeshEdit 按照作业中的顺序，先求各行。]],
  }
end)

-- The patch with rows and columns swapped: its rows are `patch`'s columns.
local function transposed(patch)
  local points = {}
  for r = 0, 3 do
    for c = 0, 3 do points[c * 4 + r + 1] = patch.points[r * 4 + c + 1] end
  end
  return meshedit.patch(points)
end

-- The tangents at (u, v) as lesson 1 found a curve's: 3 times the difference of the last level's two points, for
-- the column curve through the rows at u (along v) and for the row curve through the columns at v (along u); their
-- cross product, normalised, is the normal.
local function tangents(patch, u, v)
  local along_v = patch:evaluation(u, v).column_levels[3]
  local along_u = transposed(patch):evaluation(v, u).column_levels[3]
  local tu, tv = (along_u[2] - along_u[1]) * 3, (along_v[2] - along_v[1]) * 3
  return tu, tv, tu:cross(tv):normalized()
end

step({ en = "The normal at (u, v)", zh = "(u, v) 处的法向量" }, function()
  show(hill)
  camera "fit"
  local top = hill:evaluate(0.5, 0.5)
  local tu, tv, n = tangents(hill, 0.5, 0.5)
  say {
    en = [[
Shading a patch needs its **normal** at every (u, v). Lesson 1 found a curve's tangent in its last level: 3 times
the difference of the two level-2 points. A patch has a curve through every point in each direction: the column
curve (along v) and the row curve through the four columns at v (along u), so it has two tangents.]],
    zh = [[
给曲面片着色，需要知道它在每个 (u, v) 处的 **法向量**。第 1 课从曲线的最后一层求出了切线：
第 2 层两个点之差的 3 倍。曲面片上的每一点，在两个方向上各有一条曲线经过：列曲线（沿 v），
以及由四列在 v 处的点决定的行曲线（沿 u），所以它有两条切线。]],
  }
  local up = "Straight up"
  choose {
    {
      en = "At the top of the hill, (u, v) = (0.5, 0.5), which way does the normal point?",
      zh = "在山顶，即 (u, v) = (0.5, 0.5) 处，法向量指向哪个方向？",
    },
    options = {
      { en = up, zh = "竖直向上" },
      { en = "Along u, the way the rows run", zh = "沿 u 方向，也就是各行延伸的方向" },
      { en = "Toward the corner (0, 0)", zh = "朝向角点 (0, 0)" },
    },
    answer = up,
    feedback = {
      ["Along u, the way the rows run"] = {
        en = "Along u is a tangent: it lies in the surface. The normal is square to "
          .. "both tangents.",
        zh = "沿 u 的方向是一条切线：它位于曲面内。法向量与两条切线都垂直。",
      },
      ["Toward the corner (0, 0)"] = {
        en = "The hill is the same seen from every side of its middle, so at the middle "
          .. "nothing picks out one corner.",
        zh = "从中心的任何一侧看，这座小山都一样，所以在中心没有哪个角点是特殊的。",
      },
      [up] = {
        en = "Yes: at the top both tangents are level, so the normal, square to both, points straight up.",
        zh = "对：在山顶两条切线都是水平的，所以与两者都垂直的法向量竖直向上。",
      },
    },
    hint = {
      en = "The normal is square to the surface. How does the surface lie at the very top of the hill?",
      zh = "法向量垂直于曲面。在山的最高点，曲面是怎样放置的？",
    },
  }
  arrow(top, top + n, "blue")
  say {
    en = "At (0.5, 0.5) the tangents are Tu = " .. pt(tu) .. " and Tv = " .. pt(tv) .. "; their cross product, "
      .. "normalised, is n = " .. unit(n) .. " (blue arrow, from P = " .. pt(top) .. ").",
    zh = "在 (0.5, 0.5) 处，两条切线为 Tu = " .. pt(tu) .. " 和 Tv = " .. pt(tv) .. "；它们的叉积"
      .. "归一化后为 n = " .. unit(n) .. "（蓝色箭头，起点为 P = " .. pt(top) .. "）。",
  }
  live(function()
    local u, v = patch_uv()
    if not u then return { en = "(the patch view is not on screen)", zh = "（曲面片视图不在屏幕上）" } end
    local a, b, normal = tangents(hill, u, v)
    return {
      en = string.format("At the probe (u, v) = (%.2f, %.2f): Tu = %s, Tv = %s, n = %s", u, v, pt(a), pt(b),
        unit(normal)),
      zh = string.format("探测点 (u, v) = (%.2f, %.2f) 处：Tu = %s，Tv = %s，n = %s", u, v, pt(a), pt(b),
        unit(normal)),
    }
  end)
  say {
    en = [[
Now move the probe (the **u** and **v** sliders of the Patches panel, on the right) onto the slope: **u below
0.3**, with v between 0.3 and 0.7.]],
    zh = [[
现在把探测点移到山坡上（用右侧 Patches 面板中的 **u** 和 **v** 滑块）：**u 小于 0.3**，
v 在 0.3 到 0.7 之间。]],
  }
  local u = wait_for {
    hint = { en = "Drag u below 0.3, v between 0.3 and 0.7", zh = "把 u 拖到 0.3 以下，v 保持在 0.3 到 0.7 之间" },
    condition = function()
      local pu, pv = patch_uv()
      if pu and pu < 0.3 and pv >= 0.3 and pv <= 0.7 then return pu end
      return false
    end,
  }
  local _, v = patch_uv()
  local p = hill:evaluate(u, v)
  local _, _, slope = tangents(hill, u, v)
  clear()
  arrow(p, p + slope, "blue")
  local down = "Away from the top, toward u = 0"
  choose {
    {
      en = "The blue arrow is the normal at your probe. Which way does it lean?",
      zh = "蓝色箭头是你的探测点处的法向量。它向哪边倾斜？",
    },
    options = {
      { en = down, zh = "背离山顶，朝向 u = 0" },
      { en = "Toward the top", zh = "朝向山顶" },
      { en = "It points straight up", zh = "竖直向上" },
    },
    answer = slope.x < 0 and down or "Toward the top",
    feedback = {
      ["Toward the top"] = {
        en = "The slope rises toward the top, so a normal square to it tips back, away from the top.",
        zh = "山坡朝山顶方向升高，所以垂直于它的法向量会向后倾，背离山顶。",
      },
      ["It points straight up"] = {
        en = string.format("Its x is %.3f: not 0. Only where the surface is level does it "
          .. "point straight up.", slope.x),
        zh = string.format("它的 x 分量是 %.3f，不是 0。只有在曲面水平的地方，法向量才竖直向上。", slope.x),
      },
      [down] = {
        en = "Yes: the surface rises toward the top, and the normal, square to it, tips the other way.",
        zh = "对：曲面朝山顶方向升高，而垂直于它的法向量则倒向另一边。",
      },
    },
    hint = {
      en = "Picture a ramp rising to the right: which way does a stick standing square to it lean?",
      zh = "想象一个向右升高的斜坡：一根垂直立在斜坡上的木棍会向哪边倾斜？",
    },
  }
  say {
    en = "At (" .. string.format("%.2f, %.2f", u, v) .. ") the normal is " .. unit(slope) .. ". Phong shading in "
      .. "part 3 uses normals like these; here each comes straight from the two tangents.",
    zh = "在 (" .. string.format("%.2f, %.2f", u, v) .. ") 处，法向量为 " .. unit(slope) .. "。第 3 部分的 "
      .. "Phong 着色用的就是这样的法向量；这里每个法向量都直接由两条切线求得。",
  }
end)

step({ en = "The Utah teapot", zh = "犹他茶壶" }, function()
  local patches = meshedit.load_patches(lesson_file("../assets/teapot.bez"))
  show(patches)
  camera "fit"
  say {
    en = "# The teapot\n\nThe **Utah teapot** (Martin Newell, 1975) is made of **" .. #patches
      .. " Bézier patches**: rim, body, lid, handle and spout. That is only " .. 16 * #patches
      .. " control points for the whole smooth shape.",
    zh = "# 茶壶\n\n**犹他茶壶**（Martin Newell，1975 年）由 **" .. #patches
      .. " 个贝塞尔曲面片** 组成：壶沿、壶身、壶盖、壶柄和壶嘴。整个光滑的形状只用了 " .. 16 * #patches
      .. " 个控制点。",
  }
  say {
    en = [[
The view draws each patch by evaluating it on a grid of (u, v) values and joining the points into
triangles. At **resolution** n, each patch is cut into n by n small squares.]],
    zh = [[
视图绘制每个曲面片的方法是：在由 (u, v) 值构成的网格上对它求值，再把这些点连成三角形。
**分辨率**（resolution）为 n 时，每个曲面片被切成 n × n 个小方格。]],
  }
  choose {
    {
      en = "At resolution 8, how many points of one patch does the view evaluate?",
      zh = "分辨率为 8 时，视图要在一个曲面片上求多少个点？",
    },
    options = { "16", "64", "81" },
    answer = "81",
    feedback = {
      ["64"] = {
        en = "64 counts the squares. A row of 8 squares has 9 corners: the points are one more each way.",
        zh = "64 是小方格的个数。一排 8 个方格有 9 个角：每个方向上的点都比方格多一个。",
      },
      ["16"] = {
        en = "16 are the control points, which the view does not draw on the surface: it evaluates the patch "
          .. "at values of u and v.",
        zh = "16 是控制点的个数，视图并不把它们画在曲面上：它是在若干 u 和 v 的取值处对曲面片求值。",
      },
      ["81"] = {
        en = "Yes: 9 values of u (0, 1/8, ..., 1) times 9 values of v.",
        zh = "对：u 的 9 个取值（0, 1/8, ..., 1）乘以 v 的 9 个取值。",
      },
    },
    hint = {
      en = "Count the corners along one side of 8 squares in a row first.",
      zh = "先数一数：一排 8 个方格，沿一条边有几个角？",
    },
  }
  say {
    en = [[
Move the **resolution** slider and watch the panel's count of vertices and triangles follow. The **control net**
box (on at the start) draws the nets that shape the pot, grey for every patch but the probed one; untick it to see
the surface alone.]],
    zh = [[
拖动 **分辨率**（resolution）滑块，看面板中的顶点数和三角形数随之变化。**控制网格**（control net）复选框
（一开始是勾选的）会画出决定茶壶形状的控制网格，除当前探测的曲面片外都显示为灰色；取消勾选即可只看曲面。]],
  }
end)

step({ en = "Where patches meet", zh = "曲面片的拼接处" }, function()
  local patches = meshedit.load_patches(lesson_file("../assets/teapot.bez"))
  show(patches)
  say {
    en = [[
Why do 32 separate patches look like one smooth pot? Look at one edge of a patch, where v = 0.]],
    zh = [[
为什么 32 个各自独立的曲面片，看起来像一把光滑的茶壶？看看曲面片在 v = 0 处的那条边缘。]],
  }
  choose {
    {
      en = "Along the edge v = 0 of a patch, which control points decide the edge curve?",
      zh = "在曲面片的边缘 v = 0 上，哪些控制点决定了这条边缘曲线？",
    },
    options = {
      { en = "the first row's four points", zh = "第一行的四个点" },
      { en = "the first column's four points", zh = "第一列的四个点" },
      { en = "all sixteen", zh = "全部十六个" },
      { en = "the four corners", zh = "四个角点" },
    },
    answer = "the first row's four points",
    feedback = {
      ["the first column's four points"] = {
        en = "The first column is the edge u = 0: rows and columns swapped. At "
          .. "v = 0 it is the column curve that is at its start.",
        zh = "第一列是边缘 u = 0：行和列弄反了。在 v = 0 处，处在起点的是列曲线。",
      },
      ["all sixteen"] = {
        en = "At v = 0 the column curve is at its first control point, which is the first row's point: "
          .. "the other rows drop out.",
        zh = "在 v = 0 处，列曲线正好落在它的第一个控制点上，也就是第一行上的那个点：其他各行都不起作用。",
      },
      ["the four corners"] = {
        en = "The corners are the ends of the edge; its middle is pulled by two more points.",
        zh = "角点只是这条边缘的两端；边缘的中间部分还受另外两个点的牵引。",
      },
      ["the first row's four points"] = {
        en = "Yes: the column curve at v = 0 is its first control point, the first "
          .. "row's point at u.",
        zh = "对：列曲线在 v = 0 处就是它的第一个控制点，即第一行在 u 处的点。",
      },
    },
    hint = {
      en = "Evaluate the column curve at v = 0: which of its four control points is left?",
      zh = "在 v = 0 处对列曲线求值：它的四个控制点中还剩下哪一个？",
    },
  }
  local first = patches[1]
  local row = {}
  for c = 1, 4 do row[c] = first.points[c] end
  local edge_curve = meshedit.curve(row)
  local u = 0.3
  local on_patch, on_curve = first:evaluate(u, 0), edge_curve:evaluate(u)
  say {
    en = "Checked on the first teapot patch at u = 0.3: the patch at v = 0 gives " .. pt(on_patch)
      .. " and the curve of its first row gives " .. pt(on_curve) .. ". "
      .. (on_patch == on_curve and "The same point." or "They differ!"),
    zh = "在茶壶的第一个曲面片上取 u = 0.3 验证：曲面片在 v = 0 处给出 " .. pt(on_patch)
      .. "，它第一行的曲线给出 " .. pt(on_curve) .. "。"
      .. (on_patch == on_curve and "是同一个点。" or "两者不同！"),
  }
  say {
    en = [[
Two patches that share the four points of an edge therefore share the whole edge: no gaps.]],
    zh = [[
因此，两个曲面片只要共用一条边缘上的四个控制点，就共用整条边缘：不会有缝隙。]],
  }
  local smooth = "The points next to the edge, on both sides, in line with it"
  choose {
    {
      en = "No gap is not yet smooth: the surface could still fold along the edge. What else must the two patches' "
        .. "control points do for the surface to turn smoothly across it?",
      zh = "没有缝隙还不等于光滑：曲面仍可能沿着边缘折出一道棱。要让曲面光滑地跨过边缘，"
        .. "两个曲面片的控制点还必须满足什么？",
    },
    options = {
      { en = smooth, zh = "边缘两侧紧挨着它的控制点，与边缘上的点排成一条直线" },
      { en = "Share their four corners", zh = "共用四个角点" },
      { en = "Nothing more: a shared edge is smooth", zh = "不需要别的：共用边缘就已经光滑了" },
    },
    answer = smooth,
    feedback = {
      ["Share their four corners"] = {
        en = "Sharing the edge's four points already makes them share its corners; the "
          .. "question is what happens across the edge, not along it.",
        zh = "共用边缘上的四个点，本身就意味着共用它的角点；问题在于跨过边缘时怎样，而不是沿着边缘怎样。",
      },
      ["Nothing more: a shared edge is smooth"] = {
        en = "Two curves can meet at a point and still make a corner there: "
          .. "lesson 1's tangent at t = 0 is 3 (P1 - P0), set by the point next to the end.",
        zh = "两条曲线可以在一点相接，却仍在那里形成尖角：第 1 课中 t = 0 处的切线是 3 (P1 - P0)，"
          .. "由紧挨端点的那个点决定。",
      },
      [smooth] = {
        en = "Yes: across the edge, each column curve's tangent at its end is 3 (P1 - P0), set by the row next "
          .. "to the edge. When the row before the edge on one patch, the edge and the row after it on the other lie "
          .. "in line (and evenly spaced), the tangents across the edge agree and the surface turns smoothly.",
        zh = "对：在跨过边缘的方向上，每条列曲线在端点处的切线是 3 (P1 - P0)，由紧挨边缘的那一行决定。"
          .. "当一个曲面片上边缘之前的那一行、边缘本身、以及另一个曲面片上边缘之后的那一行排成一条直线"
          .. "（且间距均匀）时，两侧跨过边缘的切线就一致，曲面便能光滑过渡。",
      },
    },
    hint = {
      en = "Think of lesson 1: what sets a curve's tangent at its first point?",
      zh = "回想第 1 课：是什么决定了曲线在第一个点处的切线？",
    },
  }
  say {
    en = [[
The teapot's modeller kept, along most edges, the control points on either side in line, so the surface turns
smoothly from one patch to the next.]],
    zh = [[
茶壶的建模者在大多数边缘处都让两侧的控制点保持共线，所以曲面能从一个曲面片光滑地过渡到下一个。]],
  }
end)

step({ en = "Your turn", zh = "轮到你了" }, function()
  show(hill)
  say {
    en = [[
# Your code

Open `scripts/student/patch.lua` and write `evaluate(patch, u, v)`. `patch.points` holds the 16 control
points row by row (`patch.points[row * 4 + col + 1]`). Evaluate the four rows at **u**, then the column at
**v**, with de Casteljau steps as in part 1. Each exercise file runs on its own (in the window and in grading,
`patch.lua` is loaded alone), so part 1's `evaluate_step` is not there to call: copy it into `patch.lua` as a
local function. The lesson runs it on the hill at u = 0.25, v = 0.5, the point you computed by hand,
each time you save the file, and compares it with the reference; a Lua error shows its `patch.lua:LINE`.]],
    zh = [[
# 你的代码

打开 `scripts/student/patch.lua`，编写 `evaluate(patch, u, v)`。`patch.points` 按行存放 16 个控制点
（`patch.points[row * 4 + col + 1]`）。像第 1 部分那样用 de Casteljau 的步骤，先在 **u** 处求四行，
再在 **v** 处求那一列。每个练习文件都是单独运行的（无论在窗口中还是评分时，`patch.lua` 都是单独加载的），
所以调用不到第 1 部分的 `evaluate_step`：把它复制到 `patch.lua` 里，作为局部函数。每次保存文件时，
本课都会在小山上 u = 0.25、v = 0.5 处（也就是你手算过的那个点）运行它，并与参考实现比较；
如果出现 Lua 错误，会显示出错位置 `patch.lua:LINE`。]],
  }
  your_turn {
    exercise = "patch",
    patch = hill,
    u = 0.25,
    v = 0.5,
    hint = {
      en = "Evaluate each row (points 1-4, 5-8, 9-12, 13-16) at u, then the curve through those four points at v.",
      zh = "在 u 处对每一行（第 1-4、5-8、9-12、13-16 个点）求值，再在 v 处对由这四个点决定的曲线求值。",
    },
  }
  say {
    en = [[
Your `evaluate` gives the reference's P(0.25, 0.5). Now try it everywhere: tick **mine** in the patch view (or
press **M**). The probe point at (u, v) is then also computed by your `evaluate`: a bluish-green dot inside the
vermillion P(u, v) when it is right, a vermillion dot joined to P(u, v) when it is not. Move u and v, pick other
patches; save the file and the view runs the new version.

The grading suite runs the same checks from a terminal:

    meshedit grade --suite tests/grading/suites/patch.lua --submission scripts/student

When it is right, it gives the very points of the teapot you saw here.]],
    zh = [[
你的 `evaluate` 给出了与参考实现相同的 P(0.25, 0.5)。现在到处试试：在曲面片视图中勾选 **mine**
（或按 **M** 键）。这时 (u, v) 处的探测点也会用你的 `evaluate` 来计算：结果正确时，朱红色的 P(u, v)
中间会出现一个蓝绿色的点；不正确时，会有一个朱红色的点与 P(u, v) 连在一起。移动 u 和 v，选择其他曲面片；
保存文件后，视图就会运行新版本。

评分套件会在终端中运行同样的检查：

    meshedit grade --suite tests/grading/suites/patch.lua --submission scripts/student

代码正确时，它给出的正是你在这里看到的茶壶上的那些点。]],
  }
  wait_for {
    key = "M",
    hint = { en = "Press M to check your evaluate in the patch view", zh = "按 M 键，在曲面片视图中检查你的 evaluate" },
  }
end)
