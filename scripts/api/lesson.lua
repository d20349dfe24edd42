---@meta lesson
-- LuaLS type descriptions of the globals a lesson file sees (engine/lesson/internal/lesson_api.h), for editors only.
-- A lesson also has the whole `meshedit` module (meshedit.lua). lesson{} and step() only at the top level;
-- the others only while a step runs (lesson_file anywhere; selection, current_mesh, curve_t, curve_points and
-- patch_uv also inside a live() function or a plot's marker).

---A text the student reads: English, or the English with its translations beside it, `{ en = [[...]], zh = [[...]] }`.
---The lesson's logic only sees the English (choose returns it, feedback tables are keyed by it); the panel shows the
---window's language (View > Language), the English where a translation is missing.
---@alias Text string|{en: string, zh?: string}

---@class LessonInfo
---@field title? Text defaults to the file's stem
---@field summary? Text

---@param info LessonInfo
function lesson(info) end

---Steps run in the order they are defined.
---@param title Text
---@param body fun()
function step(title, body) end

---Adds a markdown block to the panel: # heading, **bold**, *italic*, `code`, [link](url), "- " lists.
---@param markdown Text
function say(markdown) end

---The menu commands a step can wait for (wait_for{command = ...}).
---@alias MenuCommand
---| "loop"
---| "loop-phase"
---| "catmull-clark"
---| "catmull-clark-phase"
---| "linear"
---| "linear-phase"
---| "triangulate"
---| "open-repaired"

---What a step can wait for (give exactly one of key, command, click, selection, condition, button).
---@class WaitSpec
---@field key? string "F", "shift+L", "ctrl+Z" (case ignored); returns the key as pressed
---@field command? MenuCommand a menu command the student runs (from its menu or its key), once run; returns its name
---@field click? string|Element "vertex", "e7", "any" or a handle; returns the clicked element
---@field selection? string|Element "e7", "edge", "any" or a handle; returns the selected element
---@field condition? fun(): any checked now, then once per frame; returns its first truthy value
---@field button? Text a button label; returns its English
---@field hint? Text one line under the text, shown at once: it is the instruction ("Press F")

---Pauses the step until the wait is met. Elements come back as handles on a copy of the mesh on screen
---(e.mesh), or as id strings when no mesh is shown.
---@param spec WaitSpec
---@return any
function wait_for(spec) end

---Calls fn with t from 0 to 1 as the frames pass.
---@param seconds number
---@param fn fun(t: number)
function animate(seconds, fn) end

---Shows a mesh, a 2D curve (z = 0), a list of points (a curve) or patches ({{16 points}, ...}).
---A mesh is shown Z-up, as every mesh MeshEdit makes; `{up = "y"}` shows one read from a Y-up file (.obj, glTF,
---.ply) the way opening that file does (the status bar says "Y up (the lesson's)"; View > Up axis still turns it).
---@param what Mesh|Curve|Patch|Patch[]|point[]|point[][]
---@param options? {up: "x"|"y"|"z"}
function show(what, options) end

---@alias Colour string|number[] "red" ... (colour-blind-safe palette colours), "#rrggbb" or {r, g, b} in [0, 1]

---@param element Element|string|(Element|string)[]
---@param colour? Colour default: the last-edit colour (vermillion)
function highlight(element, colour) end

---@param element Element|string
---@param text Text
function label(element, text) end

---Removes highlights and labels.
function clear() end

---@class CameraSpec
---@field fit? boolean
---@field reset? boolean
---@field yaw? number degrees
---@field pitch? number degrees
---@field distance? number
---@field target? point

---@param spec "fit"|"reset"|CameraSpec
function camera(spec) end

---@class ViewSpec
---@field halfedges? boolean the halfedge arrows inside their faces (on by default for small meshes)
---@field wireframe? boolean
---@field vertices? boolean
---@field labels? boolean the id labels (v3, e5, h12...)
---@field curve? boolean the curve view's whole curve (its key C)
---@field tangent? boolean the curve view's tangent arrow C'(t) / n at C(t)

---Turns parts of the mesh view and the curve view on or off; fields left out keep what the student chose.
---@param spec ViewSpec
function view(spec) end

---A copy of the mesh on screen (with the student's edits), or nil.
---@return Mesh?
function current_mesh() end

---The selected element (a handle on a copy of the mesh on screen), or nil.
---@return Element?
function selection() end

---The path of a file next to the lesson, for meshedit.load / load_patches / load_curve.
---@param relative string
---@return string
function lesson_file(relative) end

-- ---- asking the student: each waits until the right answer and returns it (scripts/api/README.md) ----

---@class ChooseSpec
---@field [1] Text the question
---@field options Text[] at least two, all different; the panel shows one button each
---@field answer string the right option (one of options)
---@field feedback? table<string, Text> what to say to each wrong option (and, for the right one, beside it)
---@field hint? Text shown only after the first wrong answer

---Asks a multiple-choice question. A wrong option shows its feedback (or "h2 is not the answer.") and the step keeps
---waiting; the right one returns.
---@param spec ChooseSpec
---@return string option the option chosen (the right one)
function choose(spec) end

---@alias PickAnswer Element|string|fun(element: Element|string): boolean, string?
---@alias PickFeedback table<string, Text>|fun(element: Element|string): Text?

---@class PickSpec
---@field [1] Text the question ("Click the halfedge that ...")
---@field on? "curve" a click on the curve view: answer and feedback then take (t, point), the t of the curve point
---nearest the click and that point, and the pick returns the t
---@field answer PickAnswer|number|fun(t: number, point: vec3): boolean, string? the element (a handle or an id like
---"h4"), or a function: is this one right, and why; on the curve: the t, or a function of (t, point)
---@field tolerance? number on the curve: how far in t a click may be from the answer (default 0.04)
---@field feedback? PickFeedback|fun(t: number, point: vec3): string? what to say to a wrong click: a table from ids
---to text, or a function of it
---@field hint? Text shown only after the first wrong click

---Asks the student to click an element in the view. A wrong click shows its feedback (the feedback's, then the answer
---function's reason, then "Not h2: look again.") and the step keeps waiting; the right one returns.
---@param spec PickSpec
---@return Element|string|number element a handle on a copy of the mesh on screen (its id when no mesh is shown); on
---the curve, the t clicked
function pick(spec) end

---@class AnswerSpec
---@field [1] Text the question
---@field number? number the answer, when it is a number (give number or point)
---@field point? point the answer, when it is a point: {x, y} or {x, y, z}
---@field tolerance? number how far off an answer may be (distance for a point); default 1e-3
---@field feedback? fun(value: number|vec3): Text? what to say to a wrong value
---@field hint? Text shown only after the first wrong answer

---Asks for a number or a point, typed into a box ("0.375", "3/8", "2, 1.5"). Text that is not a number is told how to
---write one and does not count as a try; a wrong value shows its feedback (or "0.4 is not the answer.").
---@param spec AnswerSpec
---@return number|vec3 value the value typed (a vec3 with z = 0 for a 2D point)
function answer(spec) end

---@class YourTurnSpec
---@field exercise string "curve", "patch", "normals", "flip", "split", "upsample" or an exercise of scripts/exercises
---@field control? point[] an exercise of scripts/exercises on points: the control points
---@field args? any[] an exercise of scripts/exercises on points or a patch: the values passed after the input
---@field mesh? Mesh normals, flip, split, upsample: the mesh (copied when your_turn is called)
---@field element? Element|string normals: a vertex; flip, split: an edge (a handle or an id like "e0")
---@field points? point[] curve: the points given to evaluate_step
---@field t? number curve
---@field patch? Patch patch: meshedit.patch(...) (an exercise of scripts/exercises on a patch: also 16 points)
---@field u? number patch
---@field v? number patch
---@field hint? Text shown under the diagnosis while the student's answer is wrong

---Runs the student's function from the student folder (scripts/student, the Exercises tab's) on the input, beside the
---reference, with the Exercises tab's comparison. Right: returns. Wrong (or a Lua error, shown as "flip.lua:LINE: ...",
---or a run stopped by the sandbox's limits): the panel shows the diagnosis in the Exercises tab's words and the step
---waits; each save of the file runs it again.
---@param spec YourTurnSpec
---@return true
function your_turn(spec) end

-- ---- what follows the view ----

---A text block whose text is fn's value (tostring, then markdown), evaluated now and again every frame, so it follows
---the view (curve_t(), curve_points(), selection()). fn may only read: say, show, highlight... are errors in it. An
---error shows its file:line in place of the text and stops that block for the rest of the step.
---@param fn fun(): any
function live(fn) end

---@class PlotCurve
---@field label? Text default "curve N"
---@field fn fun(x: number): number sampled once, when plot runs
---@field colour? Colour default: the palette's colours in turn

---@class PlotSpec
---@field title? Text
---@field x? number[] {from, to}; default {0, 1}
---@field y? number[] {low, high}; default: the samples' range
---@field samples? integer samples per curve minus one (2 to 2000); default 100
---@field curves PlotCurve[] one to twelve
---@field marker? fun(): number? read every frame like live(); its x is drawn as a vertical line (nil: none)

---A plot in the lesson panel: each curve sampled once at samples + 1 equally spaced x, and an optional marker that
---follows the view (marker = function() return curve_t() end).
---@param spec PlotSpec
function plot(spec) end

---An arrow over the mesh view or the patch view, from one point to another (the shown mesh's or patches'
---coordinates), cleared with the step's other marks. Solid where the mesh does not hide it, faint where it does.
---@param from point
---@param to point
---@param colour? Colour default: the last-edit colour (vermillion)
function arrow(from, to, colour) end

---The curve view's t (0 to 1), or nil when the curve view is not on screen.
---@return number?
function curve_t() end

---The curve view's control points as the student left them (dragged, added, removed), as vec3 with z = 0, or nil
---when the curve view is not on screen.
---@return vec3[]?
function curve_points() end

---The patch view's (u, v) probe and the probed patch's index in the shown list (from 1), or nil when the patch view
---is not on screen.
---@return number? u
---@return number? v
---@return integer? patch
function patch_uv() end
