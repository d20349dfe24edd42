-- Part 1: Bézier curves by de Casteljau's algorithm: the levels at a parameter t (level 0 is the control points,
-- level k comes after k steps), the curve traced as t moves, a curve of six control points at every level (the
-- write-up's figure), splitting a curve in two, the Bernstein weights and the derivative. Each step asks the
-- student to predict or to act before it shows; the numbers the lesson prints are computed by the project's own
-- Bézier code (meshedit.curve), so the text never drifts from what the curve view draws, except a few worked values
-- of this curve written in its text (3/8, t = 1/3, the polygon's length 6.47 and quarter point (0.72, 1.45),
-- C'(0.5) = (4.5, 0)), each checked against the core by tests/lesson/lessons_a_test.cpp.
-- The last step runs the student's own evaluate_step (your_turn) at t = 0.25, where swapped weights show.
-- CI runs it headless:
--   meshedit lesson lessons/1_de_casteljau.lua --headless --answers tests/lesson/lessons/1_de_casteljau_answers.lua \
--     --student tests/exercise/solutions

lesson {
  title = { en = "de Casteljau's algorithm", zh = "de Casteljau 算法" },
  summary = {
    en = "How four points make a curve: the levels at t, the point they end in, splitting, weights and tangents.",
    zh = "四个点怎样构成一条曲线：t 处的各层、各层最终得到的那个点、分割、权重和切线。",
  },
}

-- A cubic: four control points, drawn in the z = 0 plane.
local curve = meshedit.curve { {0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0} }
local degree = #curve.points - 1

-- "(1.25, 1.5)": a point as the panel prints it (2D, short numbers).
local function pt(p)
  return string.format("(%g, %g)", p.x, p.y)
end

local function list(points)
  local parts = {}
  for i, p in ipairs(points) do parts[i] = pt(p) end
  return table.concat(parts, ", ")
end

local function near(p, x, y, tolerance)
  return math.abs(p.x - x) < (tolerance or 1e-3) and math.abs(p.y - y) < (tolerance or 1e-3)
end

-- The curve the view shows now, as the student left it (dragged points, added points), or the lesson's.
local function on_screen()
  local points = curve_points()
  if points and #points >= 2 then return meshedit.curve(points) end
  return curve
end

-- The levels at t, one line each, level 0 first; `line` formats a line ("- level %d: %s" unless given: the Chinese
-- passes "- 第 %d 层：%s").
local function level_lines(c, t, line)
  local lines = {}
  for k, level in ipairs(c:levels(t)) do
    lines[k] = string.format(line or "- level %d: %s", k - 1, list(level))
  end
  return table.concat(lines, "\n")
end

-- |C'(t)|: the degree times the distance between the two points of the next-to-last level.
local function speed(c, t)
  local levels = c:levels(t)
  local two = levels[#levels - 1]
  return ((two[2] - two[1]) * (#c.points - 1)):length()
end

-- The hodograph: the control points of C'(t), n times the differences of neighbouring control points.
local function hodograph_points(points)
  local n, out = #points - 1, {}
  for i = 1, n do out[i] = (points[i + 1] - points[i]) * n end
  return out
end

step({ en = "Four points, one curve", zh = "四个点，一条曲线" }, function()
  show(curve)
  camera "fit"
  say {
    en = [[
# Bézier curves

A **Bézier curve** is drawn from a few **control points**. On screen is a *cubic*: four control points,
joined by the **control polygon**. The curve itself is hidden for now.]],
    zh = [[
# 贝塞尔曲线

**贝塞尔曲线** 由几个 **控制点** 确定。屏幕上是一条 *三次* 曲线：四个控制点，
由 **控制多边形** 依次连起来。曲线本身暂时隐藏。]],
  }
  say({ en = "The control points are " .. list(curve.points) .. ".", zh = "控制点是 " .. list(curve.points) .. "。" })
  choose {
    { en = "Before you see it: which control points will the curve pass through?",
      zh = "看到曲线之前，先猜一猜：曲线会经过哪些控制点？" },
    options = { { en = "all four", zh = "全部四个" }, { en = "the first and the last", zh = "第一个和最后一个" },
                { en = "the two middle ones", zh = "中间的两个" }, { en = "none of them", zh = "一个也不经过" } },
    answer = "the first and the last",
    feedback = {
      ["all four"] = {
        en = "A curve through all four would be an interpolating curve. A Bézier curve only passes "
          .. "through some of its control points; the others pull it without being reached.",
        zh = "经过全部四个点的曲线是插值曲线。贝塞尔曲线只经过它的一部分控制点；其余的控制点拉着曲线，"
          .. "曲线却不会到达它们。",
      },
      ["the two middle ones"] = {
        en = "The middle points are the ones that pull the curve; think of where t = 0 and "
          .. "t = 1 must put the point.",
        zh = "中间的点正是拉着曲线的那两个点；想一想 t = 0 和 t = 1 时，点必须在哪里。",
      },
      ["none of them"] = {
        en = "The curve has to start and end somewhere: where is it at t = 0, before any mixing?",
        zh = "曲线总得有起点和终点：t = 0 时，还没有任何混合，它在哪里？",
      },
      ["the first and the last"] = {
        en = "Yes: it starts at the first point and ends at the last one.",
        zh = "对：它从第一个点出发，在最后一个点结束。",
      },
    },
    hint = {
      en = "At t = 0 every step of the algorithm keeps the first point of each pair.",
      zh = "t = 0 时，算法的每一步都保留每对点中的第一个。",
    },
  }
  say {
    en = [[
Press **C** to draw the curve, then drag a control point in the view and watch the curve follow.]],
    zh = [[
按 **C** 画出曲线，然后在视图中拖动一个控制点，看曲线如何跟着变化。]],
  }
  wait_for { key = "C", hint = { en = "Press C to show the curve", zh = "按 C 显示曲线" } }
  say {
    en = [[
The curve starts at the first point and ends at the last one. It does not pass through the two middle
points: they *pull* the curve towards them.]],
    zh = [[
曲线从第一个点出发，在最后一个点结束。它不经过中间的两个点：它们把曲线 *拉* 向自己。]],
  }
end)

step({ en = "One step: level 1", zh = "一步：第 1 层" }, function()
  show(curve)
  say {
    en = [[
To find the point of the curve at a parameter **t** between 0 and 1, de Casteljau's algorithm only ever
does one thing: it takes two neighbouring points and goes the fraction **t** of the way from the first to
the second, `(1 - t) * a + t * b`. Done to every neighbouring pair of the control points (**level 0**), it
gives the points of **level 1**.]],
    zh = [[
要求出曲线在参数 **t**（0 到 1 之间）处的点，de Casteljau 算法自始至终只做一件事：取两个相邻的点，
从第一个点朝第二个点走过两点间距离的 **t** 倍，即 `(1 - t) * a + t * b`。
对控制点（**第 0 层**）中每一对相邻的点都这样做，就得到 **第 1 层** 的点。]],
  }
  answer {
    { en = "At t = 0.25, where is the first point of level 1, between (0, 0) and (1, 2)? Give x, y.",
      zh = "t = 0.25 时，第 1 层的第一个点（在 (0, 0) 和 (1, 2) 之间）在哪里？以 x, y 的形式作答。" },
    point = { 0.25, 0.5 },
    feedback = function(p)
      if near(p, 0.75, 1.5) then
        return {
          en = "(0.75, 1.5) is three quarters of the way: t and 1 - t swapped. At t = 0.25 the point stays "
            .. "close to the first point, (1 - t) * a + t * b with a = (0, 0).",
          zh = "(0.75, 1.5) 走到了四分之三处：t 和 1 - t 弄反了。t = 0.25 时，这个点离第一个点较近，"
            .. "即 (1 - t) * a + t * b，其中 a = (0, 0)。",
        }
      elseif near(p, 0.5, 1) then
        return { en = "(0.5, 1) is the midpoint, the average of the two points: that is t = 0.5, not t = 0.25.",
                 zh = "(0.5, 1) 是中点，即两个点的平均：那是 t = 0.5，而不是 t = 0.25。" }
      elseif near(p, 1.5, 2) or near(p, 3.25, 1.5) then
        return {
          en = pt(p) .. " is a level-1 point of another pair: the first point of level 1 comes from the first "
            .. "two control points.",
          zh = pt(p) .. " 是另一对点得到的第 1 层的点：第 1 层的第一个点来自前两个控制点。",
        }
      elseif near(p, 0, 0) or near(p, 1, 2) then
        return { en = pt(p) .. " is a control point itself: level 1 lies between the two, t of the way along.",
                 zh = pt(p) .. " 本身就是控制点：第 1 层的点位于两者之间，在两点间距离的 t 倍处。" }
      end
    end,
    hint = { en = "Go a quarter of the way from (0, 0) towards (1, 2).", zh = "从 (0, 0) 朝 (1, 2) 走四分之一的路程。" },
  }
  say {
    en = [[
Now see it: drag the **t** slider of the curve view to **0.25** (or scroll over the view: one notch moves t
by 0.01), then press **E** to draw level 1.]],
    zh = [[
现在来看一看：把曲线视图中的 **t** 滑块拖到 **0.25**（或在视图上滚动滚轮：每滚一格，t 改变 0.01），
然后按 **E** 画出第 1 层。]],
  }
  wait_for {
    condition = function() local t = curve_t() return t and math.abs(t - 0.25) < 0.005 end,
    hint = { en = "Move t to 0.25: the slider shows its value", zh = "把 t 调到 0.25：滑块上会显示它的值" },
  }
  wait_for { key = "E", hint = { en = "Press E to draw level 1", zh = "按 E 画出第 1 层" } }
  live(function()
    local c = on_screen()
    local t = curve_t() or 0.25
    return { en = string.format("At t = %.2f level 1 is %s.", t, list(c:levels(t)[2])),
             zh = string.format("t = %.2f 时，第 1 层是 %s。", t, list(c:levels(t)[2])) }
  end)
  say {
    en = [[
Three points, one fewer than level 0: each lies on a side of the control polygon, t of the way along it.]],
    zh = [[
三个点，比第 0 层少一个：每个点都位于控制多边形的一条边上，在这条边上走过全长的 t 倍处。]],
  }
end)

step({ en = "Counting levels", zh = "数一数层数" }, function()
  show(curve)
  say {
    en = [[
Each step turns the points of one level into the next, one point fewer. Level 0 is the control points, and
**level k** is what you have after **k** steps.]],
    zh = [[
每一步都把一层的点变成下一层，点数少一个。第 0 层就是控制点，**第 k 层** 是走完 **k** 步之后得到的点。]],
  }
  choose {
    { en = "A quartic curve has 5 control points. How many points are in its level 2?",
      zh = "四次曲线有 5 个控制点。它的第 2 层有几个点？" },
    options = { "5", "4", "3", "2" },
    answer = "3",
    feedback = {
      ["5"] = { en = "5 is level 0, the control points themselves, before any step.",
                zh = "5 是第 0 层，也就是还没走任何一步时的控制点本身。" },
      ["4"] = { en = "4 is level 1, after one step: off by one. Level 2 comes after two steps.",
                zh = "4 是走一步之后的第 1 层：少算了一步。第 2 层要走两步才得到。" },
      ["2"] = {
        en = "2 is level 3, after three steps: one step too many. Level k is not k points; it is what is left "
          .. "after k steps, each removing one point.",
        zh = "2 是走三步之后的第 3 层：多走了一步。第 k 层并不是 k 个点，而是走 k 步之后剩下的点，"
          .. "每一步去掉一个点。",
      },
      ["3"] = { en = "Yes: 5, then 4 after one step, then 3 after two.",
                zh = "对：起初 5 个，走一步后 4 个，走两步后 3 个。" },
    },
    hint = { en = "Each step removes one point. Level 0 has 5.", zh = "每一步去掉一个点。第 0 层有 5 个。" },
  }
  say {
    en = [[
Check it in the view: press **Add point** to make the curve a quartic and press **E** until the table below the
curve shows level 2. A curve with n control points needs n - 1 steps to reach its single point, the last level,
which **is on the curve**.]],
    zh = [[
在视图里验证一下：按 **添加点** 把曲线变成四次曲线，再按 **E**，直到曲线下方的表格显示出第 2 层。
有 n 个控制点的曲线要走 n - 1 步，才能得到唯一的那个点，也就是最后一层，而它 **就在曲线上**。]],
  }
  wait_for { key = "E", hint = { en = "Press E to draw the next level", zh = "按 E 画出下一层" } }
end)

step({ en = "Moving t", zh = "移动 t" }, function()
  show(curve)
  view { curve = true }
  say {
    en = [[
For each t the levels end in one point, and together those points are the curve, drawn now in the view. Before
you compute one, guess.]],
    zh = [[
对每个 t，各层最后都只剩一个点；所有这些点合起来就是曲线，现在已经画在视图中。在计算之前，先猜一猜。]],
  }
  pick {
    { en = "Click the point of the curve you think is C(0.25), the point at t = 0.25.",
      zh = "点击曲线上你认为是 C(0.25) 的点，也就是 t = 0.25 处的点。" },
    on = "curve",
    answer = 0.25,
    tolerance = 0.03,
    feedback = function(t)
      if t < 0.25 then
        return {
          en = string.format("That is C(%.2f), short of C(0.25): t = 0.25 is a quarter of the way in t, and this "
            .. "curve moves a little faster near its ends, so C(0.25) is a bit more than a quarter of its length.", t),
          zh = string.format("这是 C(%.2f)，还没到 C(0.25)：t = 0.25 是在 t 上走了四分之一，而这条曲线在两端附近"
            .. "走得稍快一些，所以 C(0.25) 比曲线长度的四分之一还要远一点。", t),
        }
      end
      return {
        en = string.format("That is C(%.2f), past C(0.25): t = 0.25 is a quarter of the way from P0 in t, so "
          .. "C(0.25) is near the first end.", t),
        zh = string.format("这是 C(%.2f)，超过了 C(0.25)：t = 0.25 是从 P0 出发、在 t 上走了四分之一，"
          .. "所以 C(0.25) 靠近起始的一端。", t),
      }
    end,
    hint = { en = "t runs from 0 at P0 to 1 at P3 along the curve.", zh = "沿着曲线，t 从 P0 处的 0 变到 P3 处的 1。" },
  }
  say {
    en = [[
Near enough: now compute it. Press **E** three times to draw every level, then drag **t** from 0 to 1 (the slider,
or the wheel over the view): the last level's point, C(t), runs along the curve. The levels below are those of the
curve on screen at the view's t, and follow it.]],
    zh = [[
足够接近了：现在来算出它。按三次 **E** 画出每一层，然后把 **t** 从 0 拖到 1（用滑块，或在视图上滚动滚轮）：
最后一层的点 C(t) 沿着曲线移动。下面列出的是屏幕上这条曲线在视图当前 t 处的各层，它们会随之变化。]],
  }
  live(function()
    local t = curve_t()
    if not t then return { en = "(the curve view is not on screen)", zh = "（曲线视图不在屏幕上）" } end
    return { en = string.format("**t = %.2f**\n\n%s", t, level_lines(on_screen(), t)),
             zh = string.format("**t = %.2f**\n\n%s", t, level_lines(on_screen(), t, "- 第 %d 层：%s")) }
  end)
  local quarter = curve:evaluate(0.25)
  answer {
    { en = "Move t to 0.25 and read the curve's point C(0.25) off the levels. Give it as x, y.",
      zh = "把 t 调到 0.25，从各层中读出曲线上的点 C(0.25)。以 x, y 的形式作答。" },
    point = { quarter.x, quarter.y },
    tolerance = 1e-3,
    feedback = function(p)
      if near(p, 0.5625, 0.875) or near(p, 1.9375, 1.875) then
        return {
          en = pt(p) .. " is a level-2 point: one more step, between the two level-2 points, gives the curve's "
            .. "point.",
          zh = pt(p) .. " 是第 2 层的点：在第 2 层的两个点之间再走一步，才得到曲线上的点。",
        }
      elseif near(p, 0.25, 0.5) or near(p, 1.5, 2) or near(p, 3.25, 1.5) then
        return { en = pt(p) .. " is a level-1 point: two more steps to the curve.",
                 zh = pt(p) .. " 是第 1 层的点：还要再走两步才到曲线上。" }
      elseif near(p, 3.09375, 1.125) then
        return { en = "(3.094, 1.125) is C(0.75): t and 1 - t swapped.",
                 zh = "(3.094, 1.125) 是 C(0.75)：t 和 1 - t 弄反了。" }
      elseif near(p, 2, 1) then
        return {
          en = "(2, 1) is the average of the four control points: the curve's point weights them, it does not "
            .. "average them.",
          zh = "(2, 1) 是四个控制点的平均：曲线上的点是对它们加权，而不是求平均。",
        }
      end
    end,
    hint = { en = "The live text lists every level at the view's t: the last level is the curve's point.",
             zh = "实时文本列出了视图当前 t 处的每一层：最后一层就是曲线上的点。" },
  }
  say({
    en = "Yes, C(0.25) = " .. pt(quarter) .. ". That is not a quarter of the way along the control polygon (6.47 long:"
      .. " a quarter of it is still on its first side, near (0.72, 1.45)): the curve moves at its own speed.",
    zh = "对，C(0.25) = " .. pt(quarter) .. "。这并不是沿控制多边形走四分之一的位置（控制多边形长 6.47，"
      .. "它的四分之一处还在第一条边上，约在 (0.72, 1.45)）：曲线按自己的速度移动。",
  })
end)

-- A curve of six control points, as the assignment's write-up asks for one: a wave that crosses its own chord.
local six = meshedit.curve { {0, 0, 0}, {1, 3, 0}, {2.5, -1, 0}, {3.5, 3.5, 0}, {5, -0.5, 0}, {6, 1.5, 0} }

step({ en = "Six points, every level", zh = "六个点，每一层" }, function()
  show(six)
  say {
    en = [[
The write-up asks for a curve of **six** control points with every level of de Casteljau drawn. Here is one: a
quintic, degree 5.]],
    zh = [[
写作报告要求给出一条有 **六个** 控制点的曲线，并画出 de Casteljau 算法的每一层。这里就有一条：五次曲线，次数为 5。]],
  }
  answer {
    { en = "How many times must you press E, from the control points alone, until the view shows the curve's point?",
      zh = "从只有控制点的状态开始，要按几次 E，视图才会显示出曲线上的点？" },
    number = #six.points - 1,
    tolerance = 0,
    feedback = function(value)
      if value == #six.points then
        return {
          en = "Six would be one step past the point: each step removes one point, and six points reach one after "
            .. "five steps.",
          zh = "六次就比那个点多走了一步：每一步去掉一个点，六个点走五步就只剩一个。",
        }
      end
      if value == 3 then
        return { en = "Three steps take a cubic, four points, to its point; this curve has six.",
                 zh = "三步能把一条三次曲线（四个点）带到它的点；而这条曲线有六个点。" }
      end
      if value == 1 then
        return { en = "One step gives level 1, five points: each step removes only one.",
                 zh = "一步得到的是第 1 层，有五个点：每一步只去掉一个点。" }
      end
    end,
    hint = { en = "Level k has 6 - k points. Which k leaves one?", zh = "第 k 层有 6 - k 个点。哪个 k 只剩一个点？" },
  }
  local presses = 0
  live(function()
    local t = curve_t()
    if not t then return { en = "(the curve view is not on screen)", zh = "（曲线视图不在屏幕上）" } end
    return { en = string.format("**t = %.2f**\n\n%s", t, level_lines(on_screen(), t)),
             zh = string.format("**t = %.2f**\n\n%s", t, level_lines(on_screen(), t, "- 第 %d 层：%s")) }
  end)
  say {
    en = "Now press **E** five times, one level at a time, and watch each level's points slide along the last one's "
      .. "sides.",
    zh = "现在按五次 **E**，一次一层，看每一层的点如何沿着上一层的边滑动。",
  }
  while presses < #six.points - 1 do
    wait_for { key = "E", hint = { en = "Press E: level " .. (presses + 1) .. " of " .. (#six.points - 1),
                                   zh = "按 E：第 " .. (presses + 1) .. " 层，共 " .. (#six.points - 1) .. " 层" } }
    presses = presses + 1
  end
  local t = curve_t() or 0.5
  say({
    en = "Every level at t = " .. string.format("%.2f", t) .. ": " .. #six:levels(t) .. " levels from the 6 control "
      .. "points down to C(t) = " .. pt(six:evaluate(t)) .. ". Drag t and the whole pyramid follows; press **C** to "
      .. "draw the curve through all its points. That picture, at two or three values of t, is the write-up's.",
    zh = "t = " .. string.format("%.2f", t) .. " 时的每一层：从 6 个控制点一直到 C(t) = " .. pt(six:evaluate(t))
      .. "，共 " .. #six:levels(t) .. " 层。拖动 t，整座金字塔都会跟着变化；按 **C** 画出由所有这些点构成的曲线。"
      .. "在两三个不同的 t 值下画出这幅图，就是写作报告要的图。",
  })
end)

step({ en = "Splitting a curve", zh = "分割曲线" }, function()
  show(curve)
  choose {
    {
      en = "The curve cut at t gives two cubics, the part from 0 to t and the part from t to 1. Which points are the "
        .. "control points of the part from 0 to t?",
      zh = "在 t 处把曲线切开，得到两条三次曲线：从 0 到 t 的部分，以及从 t 到 1 的部分。"
        .. "从 0 到 t 那部分的控制点是哪些点？",
    },
    options = { { en = "the first point of every level", zh = "每一层的第一个点" },
                { en = "the last point of every level", zh = "每一层的最后一个点" },
                { en = "the points of level 1", zh = "第 1 层的点" },
                { en = "the midpoints of the control polygon", zh = "控制多边形各边的中点" } },
    answer = "the first point of every level",
    feedback = {
      ["the last point of every level"] = {
        en = "The last points, read backwards, control the other part, from t to 1.",
        zh = "这些最后的点倒过来读，控制的是另一部分，即从 t 到 1 的部分。",
      },
      ["the points of level 1"] = {
        en = "Level 1 has 3 points and a cubic needs 4: one from each level, 0 to 3.",
        zh = "第 1 层只有 3 个点，而三次曲线需要 4 个：每层取一个，从第 0 层到第 3 层。",
      },
      ["the midpoints of the control polygon"] = {
        en = "Midpoints are level 1 at t = 0.5 only; the cut can be at any t.",
        zh = "中点只是 t = 0.5 时的第 1 层；而切点可以在任意 t 处。",
      },
      ["the first point of every level"] = {
        en = "Yes: the first point of level 0 (the curve's start) down to the "
          .. "last level (the point at t).",
        zh = "对：从第 0 层的第一个点（曲线的起点）一直到最后一层（t 处的点）。",
      },
    },
    hint = { en = "The part from 0 to t starts where the curve starts and ends at C(t).",
             zh = "从 0 到 t 的部分，起点就是曲线的起点，终点是 C(t)。" },
  }
  say {
    en = [[
See it: tick **Split at t** in the curve view. The two halves are drawn in two colours, their control points
ringed; the table lists them as **left** and **right**. Now drag **t** and watch both halves change.]],
    zh = [[
来看一看：在曲线视图中勾选 **在 t 处分割**。两半用两种颜色绘制，它们的控制点画有圆圈；
表格把它们列为 **左半段** 和 **右半段**。现在拖动 **t**，看两半如何变化。]],
  }
  live(function()
    local t = curve_t()
    if not t then return { en = "(the curve view is not on screen)", zh = "（曲线视图不在屏幕上）" } end
    local c = on_screen()
    local left, right = c:split(t)
    local levels = c:levels(t)
    local firsts, lasts = {}, {}
    for k = 1, #levels do
      firsts[k] = levels[k][1]
      lasts[k] = levels[#levels - k + 1][#levels[#levels - k + 1]]
    end
    local agree = true
    for k = 1, #levels do
      if left.points[k] ~= firsts[k] or right.points[k] ~= lasts[k] then agree = false end
    end
    return {
      en = string.format("At t = %.2f: left %s; right %s. The first points of the levels %s the left half.",
        t, list(left.points), list(right.points), agree and "are" or "are NOT"),
      zh = string.format("t = %.2f 时：左半段 %s；右半段 %s。各层的第一个点%s左半段的控制点。",
        t, list(left.points), list(right.points), agree and "正是" or " **不是** "),
    }
  end)
  wait_for {
    condition = function() local t = curve_t() return t and math.abs(t - 0.5) > 0.1 end,
    hint = { en = "Drag t away from 0.5 (below 0.4 or above 0.6)", zh = "把 t 拖离 0.5（小于 0.4 或大于 0.6）" },
  }
  say {
    en = [[
Splitting costs nothing more than evaluating. Splitting again and again gives control polygons that hug the
curve ever closer, which is how curves are drawn and intersected fast.]],
    zh = [[
分割的开销并不比求值多。一次又一次地分割，得到的控制多边形会越来越贴近曲线；快速绘制曲线、求曲线的交点，
靠的就是这一点。]],
  }
end)

local function bernstein(i)
  local binomial = ({ 1, 3, 3, 1 })[i + 1]
  return function(t) return binomial * t ^ i * (1 - t) ^ (3 - i) end
end

step({ en = "The weights", zh = "权重" }, function()
  show(curve)
  say {
    en = [[
Every level mixes the points of the level before, so the last point is a mix of the control points:
`C(t) = B0(t) P0 + B1(t) P1 + B2(t) P2 + B3(t) P3`. The **B**s are the **Bernstein weights**.]],
    zh = [[
每一层都是上一层各点的混合，所以最后的点是控制点的混合：
`C(t) = B0(t) P0 + B1(t) P1 + B2(t) P2 + B3(t) P3`。其中的各个 **B** 就是 **Bernstein 权重**（Bernstein 基函数）。]],
  }
  answer {
    { en = "What is B1(0.5), the weight of P1 = (1, 2) in C(0.5)?",
      zh = "B1(0.5)，也就是 P1 = (1, 2) 在 C(0.5) 中的权重，是多少？" },
    number = 0.375,
    feedback = function(value)
      if math.abs(value - 0.25) < 1e-3 then
        return {
          en = "1/4 would make C(0.5) the average of the four points. The curve's point weights them: the middle "
            .. "points get more.",
          zh = "如果是 1/4，C(0.5) 就成了四个点的平均。曲线上的点是对它们加权：中间的点分到的权重更多。",
        }
      elseif math.abs(value - 0.125) < 1e-3 then
        return { en = "1/8 is the weight of an end point, P0 or P3, at t = 0.5.",
                 zh = "1/8 是端点 P0 或 P3 在 t = 0.5 时的权重。" }
      elseif math.abs(value - 0.5) < 1e-3 then
        return { en = "0.5 is the weight P1 gets in the first level-1 point only; two more steps mix it again.",
                 zh = "0.5 只是 P1 在第 1 层第一个点中得到的权重；后面还有两步会再次混合。" }
      end
    end,
    hint = { en = "Run the steps at t = 0.5 with the number 1 in place of P1 and 0 for the others.",
             zh = "在 t = 0.5 处执行这些步骤，把 P1 换成数 1，其余的点都换成 0。" },
  }
  say {
    en = "Yes: 3/8. Here are all four weights as t goes from 0 to 1; the line is the view's t. Drag t and watch it.",
    zh = "对：3/8。下面是 t 从 0 变到 1 时全部四个权重的曲线；图中的竖线就是视图当前的 t。拖动 t 观察它。",
  }
  local curves = {}
  for i = 0, degree do
    local colour = ({ "blue", "orange", "green", "purple" })[i + 1]
    curves[#curves + 1] = { label = "B" .. i, fn = bernstein(i), colour = colour }
  end
  plot {
    title = { en = "Bernstein weights", zh = "Bernstein 权重" }, x = { 0, 1 }, y = { 0, 1 }, curves = curves,
    marker = function() return curve_t() end,
  }
  answer {
    { en = "Drag t and watch B1. At which t is B1 largest, so that P1 pulls hardest?",
      zh = "拖动 t，观察 B1。在哪个 t 处 B1 最大，也就是 P1 拉得最用力？" },
    number = 1 / 3,
    tolerance = 0.02,
    feedback = function(value)
      if math.abs(value - 0.5) < 0.02 then
        return { en = "At 0.5 B1 and B2 are equal: it is where they cross, not where B1 is at its top.",
                 zh = "在 0.5 处 B1 和 B2 相等：那是两条曲线的交点，而不是 B1 的最高点。" }
      elseif math.abs(value - 2 / 3) < 0.02 then
        return { en = "Around 2/3 is where B2 is largest: B1 is the weight of P1, nearer the start.",
                 zh = "2/3 附近是 B2 最大的地方：B1 是 P1 的权重，它的最高点更靠近起点。" }
      elseif value < 0.02 then
        return { en = "At t = 0 all the weight is B0: the curve is at P0.",
                 zh = "t = 0 时全部权重都在 B0 上：曲线位于 P0。" }
      end
    end,
    hint = { en = "Put the marker on the top of the orange curve: the legend gives each weight at the marker.",
             zh = "把竖线移到橙色曲线的最高点：图例会给出竖线处每个权重的值。" },
  }
  say {
    en = [[
Yes, t = 1/3. The weights are never negative and add up to 1 at every t, so the curve stays inside the
control polygon's convex hull.]],
    zh = [[
对，t = 1/3。这些权重从不为负，并且在每个 t 处之和都为 1，所以曲线始终位于控制多边形的凸包之内。]],
  }
end)

step({ en = "The tangent", zh = "切线" }, function()
  show(curve)
  say {
    en = [[
The curve's **derivative** C'(t) is its velocity: the direction the point moves as t grows, and how fast.]],
    zh = [[
曲线的 **导数** C'(t) 就是它的速度：t 增大时点移动的方向，以及移动的快慢。]],
  }
  answer {
    { en = "At t = 0 the curve leaves P0 = (0, 0) towards P1 = (1, 2). What is C'(0)? Give x, y.",
      zh = "t = 0 时，曲线从 P0 = (0, 0) 出发，朝 P1 = (1, 2) 而去。C'(0) 是多少？以 x, y 的形式作答。" },
    point = { 3, 6 },
    feedback = function(p)
      if near(p, 1, 2) then
        return { en = "(1, 2) = P1 - P0 has the right direction, but the speed is n times it, and a cubic has n = 3.",
                 zh = "(1, 2) = P1 - P0 的方向是对的，但速度是它的 n 倍，而三次曲线的 n = 3。" }
      elseif near(p, 2, 4) then
        return { en = "(2, 4) takes the factor as 2: the factor is the degree n, the number of steps, 3 for a cubic.",
                 zh = "(2, 4) 把系数当成了 2：系数是次数 n，也就是步数，三次曲线为 3。" }
      elseif near(p, 4, 8) then
        return { en = "(4, 8) takes the factor as 4, the number of control points: the factor is the degree, 3.",
                 zh = "(4, 8) 把系数当成了控制点的个数 4：系数应当是次数 3。" }
      elseif near(p, -3, -6) or near(p, -1, -2) then
        return { en = pt(p) .. " points from P1 back to P0: the curve moves away from P0, towards P1.",
                 zh = pt(p) .. " 是从 P1 指回 P0 的方向：曲线是离开 P0、朝 P1 移动的。" }
      end
    end,
    hint = { en = "The direction is along the first side of the control polygon; the length is a multiple of it.",
             zh = "方向沿着控制多边形的第一条边；长度是这条边长的若干倍。" },
  }
  say {
    en = [[
Yes: **C'(0) = 3 (P1 - P0)**. At any t the levels give it too: the last step goes from the first level-2 point to
the second, so **C'(t) = 3 (second - first level-2 point)**, and the segment between them **touches the curve at
C(t)**: it is the tangent. The view now draws it as an arrow from C(t), **C'(t) / 3**, as long as that segment
(**Tangent** in the curve view shows or hides it).]],
    zh = [[
对：**C'(0) = 3 (P1 - P0)**。在任意 t 处，各层也能给出它：最后一步是从第 2 层的第一个点走向第二个点，
所以 **C'(t) = 3 (第 2 层第二个点 - 第一个点)**，而两点之间的线段 **在 C(t) 处与曲线相切**：它就是切线。
视图现在把它画成一支从 C(t) 出发的箭头 **C'(t) / 3**，与这条线段一样长
（曲线视图中的 **切线** 复选框可以显示或隐藏它）。]],
  }
  view { curve = true, tangent = true }
  local ends, middle = speed(curve, 0), speed(curve, 0.5)
  choose {
    { en = "Before you drag t: where is the arrow longest, where the point moves fastest?",
      zh = "拖动 t 之前先想一想：箭头在哪里最长，也就是点在哪里移动得最快？" },
    options = { { en = "at the ends, t = 0 and 1", zh = "在两端，t = 0 和 1" },
                { en = "in the middle, t = 0.5", zh = "在中间，t = 0.5" },
                { en = "the same length everywhere", zh = "处处一样长" } },
    answer = "at the ends, t = 0 and 1",
    feedback = {
      ["in the middle, t = 0.5"] = {
        en = string.format("At t = 0.5 the arrow is shortest: |C'(0.5)| = %.2f against %.2f "
          .. "at the ends, the level-2 points %.2f apart there against %.2f at t = 0.", middle, ends, middle / degree,
          ends / degree),
        zh = string.format("t = 0.5 时箭头最短：|C'(0.5)| = %.2f，而两端为 %.2f；此时第 2 层的两个点相距 %.2f，"
          .. "而 t = 0 时相距 %.2f。", middle, ends, middle / degree, ends / degree),
      },
      ["the same length everywhere"] = {
        en = "Only a curve whose control points are evenly spaced on a line moves at one "
          .. "speed. Drag t and watch the arrow: it shrinks towards the middle.",
        zh = "只有控制点在一条直线上均匀分布的曲线，才会以恒定的速度移动。拖动 t 观察箭头：越往中间它越短。",
      },
      ["at the ends, t = 0 and 1"] = {
        en = string.format("Yes: |C'(0)| = 3 |P1 - P0| = %.2f, and |C'(0.5)| = %.2f only.", ends, middle),
        zh = string.format("对：|C'(0)| = 3 |P1 - P0| = %.2f，而 |C'(0.5)| 只有 %.2f。", ends, middle),
      },
    },
    hint = { en = "The arrow is C'(t) / 3, the last step's segment. At t = 0 it is P1 - P0.",
             zh = "箭头是 C'(t) / 3，即最后一步的那条线段。t = 0 时它就是 P1 - P0。" },
  }
  say {
    en = "Drag t and watch the arrow; press **E** twice to draw level 2 and see the arrow lie on its segment.",
    zh = "拖动 t 观察箭头；按两次 **E** 画出第 2 层，看箭头如何落在第 2 层的线段上。",
  }
  live(function()
    local t = curve_t()
    if not t then return { en = "(the curve view is not on screen)", zh = "（曲线视图不在屏幕上）" } end
    local c = on_screen()
    local levels = c:levels(t)
    if #levels < 3 then
      return { en = "(the curve needs 3 control points or more)", zh = "（曲线至少需要 3 个控制点）" }
    end
    local two = levels[#levels - 1]
    local d = (two[2] - two[1]) * (#c.points - 1)
    return {
      en = string.format("At t = %.2f the level-%d points are %s and %s: C'(t) = %d x their difference = %s.",
        t, #levels - 2, pt(two[1]), pt(two[2]), #c.points - 1, pt(d)),
      zh = string.format("t = %.2f 时，第 %d 层的两个点是 %s 和 %s：C'(t) = %d × 它们的差 = %s。",
        t, #levels - 2, pt(two[1]), pt(two[2]), #c.points - 1, pt(d)),
    }
  end)
  wait_for { key = "E", hint = { en = "Press E to draw the next level", zh = "按 E 画出下一层" } }
end)

step({ en = "The hodograph", zh = "速端曲线" }, function()
  local hodo = meshedit.curve(hodograph_points(curve.points))
  show(hodo)
  camera "fit"
  say({
    en = "The derivative of a cubic is itself a Bézier curve, the **hodograph**, of degree 2. Its control points are "
      .. "3 times the differences of the cubic's: 3 (P1 - P0), 3 (P2 - P1), 3 (P3 - P2) = **" .. list(hodo.points)
      .. "**. They are on screen now (the view calls its point C(t): here that is the hodograph's point, C'(t)).",
    zh = "三次曲线的导数本身也是一条贝塞尔曲线，称为 **速端曲线**（hodograph），次数为 2。它的控制点是三次曲线"
      .. "相邻控制点之差的 3 倍：3 (P1 - P0)、3 (P2 - P1)、3 (P3 - P2) = **" .. list(hodo.points)
      .. "**。它们现在显示在屏幕上（视图把它的点称为 C(t)：在这里，那就是速端曲线上的点 C'(t)）。",
  })
  local at = hodo:evaluate(0.25)
  local swapped = hodo:evaluate(0.75)
  local level1 = hodo:levels(0.25)[2]
  answer {
    { en = "What is C'(0.25), the hodograph's point at t = 0.25? Give x, y.",
      zh = "C'(0.25)，也就是速端曲线在 t = 0.25 处的点，是多少？以 x, y 的形式作答。" },
    point = { at.x, at.y },
    feedback = function(p)
      if near(p, 6, 0) then
        return {
          en = "(6, 0) is the hodograph's middle control point: its curve only passes through the first and last.",
          zh = "(6, 0) 是速端曲线中间的那个控制点：曲线只经过第一个和最后一个控制点。",
        }
      elseif near(p, swapped.x, swapped.y) then
        return { en = pt(p) .. " is C'(0.75): t and 1 - t swapped.", zh = pt(p) .. " 是 C'(0.75)：t 和 1 - t 弄反了。" }
      elseif near(p, level1[1].x, level1[1].y) or near(p, level1[2].x, level1[2].y) then
        return { en = pt(p) .. " is a level-1 point of the hodograph: one more step gives its point.",
                 zh = pt(p) .. " 是速端曲线第 1 层的点：再走一步才得到曲线上的点。" }
      elseif near(p, at.x / 3, at.y / 3) then
        return { en = pt(p) .. " is the difference of the cubic's level-2 points, without the factor 3.",
                 zh = pt(p) .. " 是三次曲线第 2 层两个点之差，少乘了系数 3。" }
      elseif near(p, 4, 0) then
        return { en = "(4, 0) = P3 - P0 is the average velocity over the whole curve, not the velocity at t = 0.25.",
                 zh = "(4, 0) = P3 - P0 是整条曲线上的平均速度，而不是 t = 0.25 处的速度。" }
      end
    end,
    hint = { en = "de Casteljau on the three hodograph points at t = 0.25: two steps.",
             zh = "在 t = 0.25 处对速端曲线的三个控制点运行 de Casteljau 算法：两步。" },
  }
  say({
    en = "Yes: C'(0.25) = " .. pt(at) .. ", up and to the right, as the curve climbs. Press **E** twice to see the "
      .. "hodograph's own levels end in it, and drag t: the live line is C'(t) at the view's t. At t = 0.5 it is "
      .. "horizontal, (4.5, 0): the top of the arch.",
    zh = "对：C'(0.25) = " .. pt(at) .. "，指向右上方，因为曲线在上升。按两次 **E**，看速端曲线自己的各层"
      .. "最后落在这个点上；再拖动 t：实时显示的那一行就是视图当前 t 处的 C'(t)。t = 0.5 时它是水平的，"
      .. "(4.5, 0)：那是拱顶。",
  })
  live(function()
    local t = curve_t()
    if not t then return { en = "(the curve view is not on screen)", zh = "（曲线视图不在屏幕上）" } end
    return string.format("t = %.2f: C'(t) = %s", t, pt(on_screen():evaluate(t)))
  end)
  wait_for { key = "E", hint = { en = "Press E to draw the next level", zh = "按 E 画出下一层" } }
end)

step({ en = "Your turn", zh = "轮到你了" }, function()
  show(curve)
  say {
    en = [[
# Your code

Open `scripts/student/curve.lua` and write `evaluate_step(points, t)`: given the points of one level, return
the next level, one point fewer. The lesson runs it on this curve's control points at t = 0.25 each time you
save the file, and compares it with the reference's level 1. A point that is missing or in the wrong place is
named, and a Lua error shows its `curve.lua:LINE`.]],
    zh = [[
# 你的代码

打开 `scripts/student/curve.lua`，写出 `evaluate_step(points, t)`：给定一层的点，返回下一层，点数少一个。
每次保存文件时，课程都会在 t = 0.25 处对这条曲线的控制点运行它，并与参考实现的第 1 层比较。
缺少的点或位置不对的点会被指出；Lua 错误会显示出错的 `curve.lua:LINE`。]],
  }
  your_turn {
    exercise = "curve",
    points = curve.points,
    t = 0.25,
    hint = {
      en = "Point i of the next level is (1 - t) * points[i] + t * points[i + 1], for i = 1 .. #points - 1.",
      zh = "下一层的第 i 个点是 (1 - t) * points[i] + t * points[i + 1]，其中 i = 1 .. #points - 1。",
    },
  }
  say {
    en = [[
Your `evaluate_step` gives the reference's level 1. Now watch it make every level: tick **mine** in the curve
view (or press **M**) and press **E**. Each level is made by your function from the level before and checked
against the reference; drag the points or move t to try other inputs. A level that differs is drawn in
vermillion over the reference's.

The grading suite runs the same checks from a terminal:

    meshedit grade --suite tests/grading/suites/curve.lua --submission scripts/student]],
    zh = [[
你的 `evaluate_step` 给出了与参考实现相同的第 1 层。现在看它生成每一层：在曲线视图中勾选 **我的**（或按 **M**），
然后按 **E**。每一层都由你的函数从上一层算出，并与参考实现比对；拖动控制点或移动 t，可以试试别的输入。
与参考实现不同的那一层会用朱红色画在参考实现的那一层之上。

评分套件在终端里运行同样的检查：

    meshedit grade --suite tests/grading/suites/curve.lua --submission scripts/student]],
  }
  wait_for { key = "M", hint = { en = "Press M to draw your evaluate_step's levels in the curve view",
                                 zh = "按 M 在曲线视图中画出你的 evaluate_step 算出的各层" } }
end)
