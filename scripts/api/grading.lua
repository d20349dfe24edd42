---@meta grading
-- LuaLS type descriptions of a grading suite's globals (engine/grade/suite.h, expectations.h), for editors
-- only. A suite also has the whole `meshedit` module (meshedit.lua).

---@alias Visibility "visible"|"hidden"|"after_due_date"|"after_published"
---@alias ReferenceFunction "flip_edge"|"split_edge"|"upsample"|"vertex_normal"|"evaluate_step"|"evaluate"

---Defaults for every test of the file (all optional).
---@class SuiteSpec
---@field name? string
---@field files? string[] student files to load, in order ("flip.lua")
---@field time_limit? number seconds
---@field memory_mb? number
---@field visibility? Visibility
---@field reference? ReferenceFunction[] reference functions given to student code
---@field allow_api? string[] exercise operations student code may call: "mesh:flip", "meshedit.curve", ...
---@field partial? boolean
---@field output_kb? number
---@field language? "en"|"zh" suite{} only: the feedback's language (default "en"; `meshedit grade --language` wins)

---@param spec SuiteSpec
function suite(spec) end

---@class TestSpec: SuiteSpec
---@field name string required
---@field run fun(student: Student, expect: Expect) required
---@field points? number
---@field number? string "1.1"
---@field tags? string[]
---@field extra_credit? boolean its points add on top of the base points (max_score 0 in results.json)

---Declares a test. Unknown fields are errors.
---@param spec TestSpec
function test(spec) end

---Runs another suite file of the same folder here; suite{} defaults merge field by field.
---@param file string
function include(file) end

---One fixture of an exercise defined in Lua: one test of its suite.
---@class ExerciseFixture
---@field name? string the test's name
---@field mesh? Mesh the mesh as it is before the call (an exercise on a mesh)
---@field element? Element|string|integer the element the function takes (a handle, "e7" or 7); not for takes = "mesh"
---@field control? point[] takes = "points": the control points ({x, y} or {x, y, z} each)
---@field patch? point[]|point[][]|Patch takes = "patch": 16 points row by row, 4 rows of 4, or meshedit.patch(...)
---@field args? any[] takes = "points" or "patch": numbers, points or lists of them, passed after the input
---@field points? number the test's score, default 1

---What the definition's diagnose is given when the student's answer differs (copies: changing them changes nothing).
---On a mesh: before, mine, reference (meshes), element, returned. On points or a patch: input, args, mine, reference
---(the values returned; one that is not a number, a point or a list of them is nil).
---@class ExerciseRun
---@field before? Mesh
---@field mine Mesh|number|vec3|table|nil
---@field reference Mesh|number|vec3|table|nil
---@field element? Element the input's element, of run.before
---@field returned? string what the student's function returned, described (on a mesh)
---@field input? vec3[]|{points: vec3[]} the control points, or the patch as the function got it
---@field args? any[] the values passed after the input

---An exercise defined in Lua alone (a file of scripts/exercises). See scripts/api/README.md.
---@class ExerciseSpec
---@field name string a word; not a built-in exercise's name
---@field title? string
---@field file string the student's file, "collapse.lua"
---@field call string the student's function, "collapse_edge"
---@field signature? string "collapse_edge(mesh, e) -> the vertex that remains, or nil"
---@field takes "vertex"|"edge"|"face"|"halfedge"|"mesh"|"points"|"patch"
---@field allow? string[] hideable API the student's code may call: "mesh:flip", ...
---@field reference fun(...): any on a mesh (mesh, element?) -> Element?, string? (nil and the mesh unchanged: a
---refusal); on points or a patch the student's arguments -> the value to compare with
---@field tolerance? number points or a patch: within how much numbers and points agree (default 1e-9 x the input's
---size)
---@field diagnose? fun(run: ExerciseRun): string|string[]|nil the likely mistakes first
---@field hint? string shown under a run that did not finish
---@field fixtures? ExerciseFixture[] what grading checks, one test each

---Defines an exercise (in scripts/exercises/NAME.lua). In a suite it also declares the suite: the student file, the
---allowed API and one test per fixture.
---@param spec ExerciseSpec
function exercise(spec) end

---The folder of the suite file, for fixtures: meshedit.load(SUITE_DIR .. "/cow.dae"). Load fixtures at the top
---level: a running test cannot open files.
---@type string
SUITE_DIR = ""

---The submission, seen from a test. student.NAME(...) calls the submission's function NAME in its sandbox
---(arguments and results are copied; meshes are shared).
---@class Student
---@field [string] fun(...): ...
local Student = {}

---@param name string
---@return boolean
function Student.has(name) end

---Same as student[name](...).
---@param name string
---@return ...
function Student.call(name, ...) end

---What the student's code printed so far.
---@return string
function Student.output() end

---The checks. Each records one result and returns true when it passed. expect(value, message) = expect.truthy.
---@class Expect
---@overload fun(value: any, message?: string): boolean
local Expect = {}

---@param value any
---@param message? string
---@return boolean
function Expect.truthy(value, message) end

---@param value any
---@param message? string
---@return boolean
function Expect.falsy(value, message) end

---@param value any
---@param message? string
---@return boolean
function Expect.is_nil(value, message) end

---Deep equality of plain values, tables, vec3s, handles and meshes.
---@param actual any
---@param expected any
---@param message? string
---@return boolean
function Expect.equal(actual, expected, message) end

---Numbers, points, and lists of those item by item.
---@param actual number|point|(number|point)[]
---@param expected number|point|(number|point)[]
---@param tolerance number
---@param message? string
---@return boolean
function Expect.near(actual, expected, tolerance, message) end

---validate() finds nothing.
---@param mesh Mesh
---@param message? string
---@return boolean
function Expect.valid(mesh, message) end

---Equal up to renumbering.
---@param yours Mesh
---@param reference Mesh
---@param tolerance number
---@param message? string
---@return boolean
function Expect.mesh_equal(yours, reference, tolerance, message) end

---Equal pointer for pointer, same ids.
---@param yours Mesh
---@param reference Mesh
---@param tolerance number
---@param message? string
---@return boolean
function Expect.same_pointers(yours, reference, tolerance, message) end

---@param mesh Mesh
---@param counts {vertices?: integer, edges?: integer, faces?: integer, halfedges?: integer, boundaries?: integer}
---@param message? string
---@return boolean
function Expect.counts(mesh, counts, message) end

---@param message? string
---@return boolean
function Expect.pass(message) end

---@param message? string
---@return boolean
function Expect.fail(message) end

---The test's share of its points in [0, 1] (the last call wins).
---@param fraction number
---@param message? string
---@return boolean
function Expect.score(fraction, message) end

---The window's own check of one exercise: the core's answer as the reference, and on failure the window's
---diagnosis ("f0.halfedge is h0, but h0.face is f1"). `input` is what the student's function was given, meshes as
---they were before the call: {points=, t=}, {patch=, u=, v=}, {mesh=, vertex=}, {mesh=, edge=} or {mesh=};
---`yours` is the mesh the student's function worked on (nil for evaluate_step and evaluate).
---@param exercise "evaluate_step"|"evaluate"|"vertex_normal"|"flip_edge"|"split_edge"|"upsample"
---@param input table
---@param returned any what the student's function returned
---@param yours? Mesh
---@param message? string
---@return boolean
function Expect.exercise(exercise, input, returned, yours, message) end
