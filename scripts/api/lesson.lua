---@meta lesson
-- LuaLS type descriptions of the globals a lesson file sees (engine/script/lesson_api.h), for editors only.
-- A lesson also has the whole `meshedit` module (meshedit.lua). lesson{} and step() only at the top level;
-- the others only while a step runs (lesson_file anywhere).

---@class LessonInfo
---@field title? string defaults to the file's stem
---@field summary? string

---@param info LessonInfo
function lesson(info) end

---Steps run in the order they are defined.
---@param title string
---@param body fun()
function step(title, body) end

---Adds a markdown block to the panel: # heading, **bold**, *italic*, `code`, [link](url), "- " lists.
---@param markdown string
function say(markdown) end

---What a step can wait for (give exactly one of key, click, selection, condition, button).
---@class WaitSpec
---@field key? string "F", "shift+L", "ctrl+Z" (case ignored); returns the key as pressed
---@field click? string|Element "vertex", "e7", "any" or a handle; returns the clicked element
---@field selection? string|Element "e7", "edge", "any" or a handle; returns the selected element
---@field condition? fun(): any checked now, then once per frame; returns its first truthy value
---@field button? string a button label; returns the label
---@field hint? string one line under the text

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
---@param what Mesh|Curve|Patch|Patch[]|point[]|point[][]
function show(what) end

---@alias Colour string|number[] "red" ... (colour-blind-safe palette colours), "#rrggbb" or {r, g, b} in [0, 1]

---@param element Element|string|(Element|string)[]
---@param colour? Colour default: the last-edit colour (vermillion)
function highlight(element, colour) end

---@param element Element|string
---@param text string
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

---Turns parts of the mesh view on or off; fields left out keep what the student chose.
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
