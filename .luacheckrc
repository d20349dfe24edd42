-- luacheck's settings for every Lua file of the repository (scripts/lua_check.sh runs it; CI runs that script).
-- Each kind of file gets the globals the C++ gives the state that runs it, and may define only the globals the app
-- reads back from it. Every warning is on: unused variables, values and arguments (an argument named `_` or
-- `_name` is unused on purpose), shadowing, undefined and unknown globals, line length; an ignore below names the
-- files it is for and says why.

std = "lua54"
max_line_length = 120

-- The sandbox every state runs in (engine/script/lua_runtime.cpp, open_whitelist): no io, package, require, debug,
-- dofile, loadfile or warn; os keeps only clock, time, date and difftime; string.dump is removed. luacheck applies
-- not_globals after the top level's globals, so os and string come back, narrowed, in a files section for all.
not_globals = { "io", "package", "require", "debug", "dofile", "loadfile", "warn", "os", "string" }
files["**/*.lua"] = {
  read_globals = {
    os = { fields = { "clock", "time", "date", "difftime" } },
    string = {
      fields = {
        "byte", "char", "find", "format", "gmatch", "gsub", "len", "lower", "match", "pack", "packsize", "rep",
        "reverse", "sub", "unpack", "upper",
      },
    },
    -- Every state has the module (engine/script/mesh_bindings.cpp); student code sees it with the hidden calls of
    -- engine/exercise/student_api.h replaced by functions that raise.
    "meshedit",
  },
}

-- The lesson globals: engine/lesson/lesson_api.cpp (open_lesson_api and its prelude's wait_for and animate),
-- lesson_questions.cpp (choose, pick, answer), lesson_displays.cpp (live, plot, arrow, curve_t, curve_points,
-- patch_uv) and lesson_your_turn.cpp (your_turn).
local lesson_globals = {
  "lesson", "step", "say", "wait_for", "animate", "show", "highlight", "label", "clear", "camera", "view",
  "current_mesh", "selection", "lesson_file", "choose", "pick", "answer", "live", "plot", "arrow", "curve_t",
  "curve_points", "patch_uv", "your_turn",
}

-- The functions student files define for the app to call: the built-in exercises (engine/exercise/exercises.h) and
-- the exercises defined in Lua (scripts/exercises/*.lua, their `call`).
local student_functions = {
  "evaluate_step", "evaluate", "vertex_normal", "flip_edge", "split_edge", "upsample", "collapse_edge",
  "catmull_clark_level", "hodograph", "patch_normal",
}

-- A grading suite's globals (engine/grade/suite.cpp, Suite::from_text): suite{}, test{}, include(), exercise{}
-- and SUITE_DIR, the suite's folder.
local suite_globals = { "suite", "test", "include", "exercise", "SUITE_DIR" }

-- A student's file defines the function of its exercise with the exercise's signature (flip_edge(mesh, e)); a walk
-- from the element may not need the mesh, and the argument keeps the name the signature gives it.
local student = { globals = student_functions, ignore = { "212/mesh" } }

-- Syntax errors on purpose (the grader's and the page's tests of a file that does not compile), and the build
-- folders.
exclude_files = { "tests/grading/broken/syntax_error.lua", "tests/web/broken_lesson/syntax_error.lua", "build*/**" }

files["lessons/"] = { read_globals = lesson_globals }
files["tests/lesson/lessons/asking_demo.lua"] = { read_globals = lesson_globals }  -- the answers files are data
files["tests/web/broken_lesson/"] = { read_globals = lesson_globals }
files["tests/web/turn_lesson/"] = { read_globals = lesson_globals }

-- The templates the class fills in: each function is a stub returning nil, so every argument of its signature is
-- unused until the student writes the body.
files["scripts/student/"] = {
  globals = student_functions,
  ignore = { "212/mesh", "212/e", "212/v", "212/points", "212/t", "212/patch", "212/u" },
}
-- The reference solutions and the submissions the grader's and the window's tests grade. upsample reads the
-- reference flip_edge and split_edge (engine/script/reference_functions.h) as globals, which the file may define.
files["tests/exercise/solutions/"] = student
files["tests/grading/students/"] = student
files["tests/grading/scripted/"] = student
files["tests/web/upload/"] = student
files["tests/grading/broken/"] = student
files["tests/grading/broken/broken_suite.lua"] = { read_globals = suite_globals }

-- Submissions whose mistake is a value computed and then forgotten: the unused local is the bug the test names
-- (a flip that never moves a.halfedge and b.halfedge; a collapse that never moves a to the middle).
files["tests/grading/students/flip_forgets_vertices.lua"] = { ignore = { "211/a", "211/b" } }
files["tests/grading/scripted/collapse_keeps_position.lua"] = { ignore = { "211/middle" } }
-- Lines the tests quote by number (file:LINE in the grader's and the window's messages) stay where they are, so a
-- fixture's over-long line is not wrapped: the upsample submissions (one line of 121 columns each, copied from
-- upsample_correct.lua) and the upload page's flip.lua, the template with its whole body on one line.
files["tests/grading/students/upsample_*.lua"] = { max_line_length = 121 }
files["tests/web/upload/flip.lua"] = { max_line_length = false }

-- Student files that run away on purpose (the window's and the page's limits stop them): they never read their
-- element, and the allocation one keeps its tables only to fill memory; memory_at_load.lua likewise, at load.
files["tests/web/runaway_student/"] = { globals = student_functions, ignore = { "212/mesh", "212/e" } }
files["tests/web/runaway_student/allocation/flip.lua"] = { ignore = { "241/kept" } }
files["tests/grading/broken/memory_at_load.lua"] = { ignore = { "241/cache" } }

-- The hostile submissions (tests/grade/hostile_test.cpp): each split.lua attacks the grader instead of splitting,
-- so its split_edge rarely reads its arguments, and most reach for what the sandbox removed or for the grader's
-- own globals on purpose. Each file is allowed exactly what it attacks, and nothing else.
files["tests/grading/hostile/"] = { globals = student_functions, ignore = { "212/mesh", "212/e" } }
files["tests/grading/hostile/hostile_suite.lua"] = { read_globals = suite_globals }
files["tests/grading/hostile/coroutine_bomb.lua"] = { ignore = { "241/all" } }  -- kept only to keep them alive
files["tests/grading/hostile/debug_library.lua"] = { read_globals = { "debug" } }
files["tests/grading/hostile/io_open_results.lua"] = { read_globals = { "io" } }
files["tests/grading/hostile/os_execute.lua"] = { read_globals = { os = { fields = { "execute" } } } }
files["tests/grading/hostile/os_exit.lua"] = { read_globals = { os = { fields = { "exit" } } } }
files["tests/grading/hostile/require_module.lua"] = { read_globals = { "require", "package" } }
files["tests/grading/hostile/string_dump.lua"] = {
  read_globals = { string = { fields = { "dump" } }, "flip_edge" },  -- flip_edge: flip.lua's, the other file
}
files["tests/grading/hostile/string_metatable.lua"] = { globals = { string = { fields = { "format" } } } }
files["tests/grading/hostile/overwrite_globals.lua"] = {
  globals = { "expect", "test", "suite", "student", "validate", meshedit = { fields = { "cube" } } },
}
files["tests/grading/hostile/read_hidden_tests.lua"] = {
  read_globals = { "loadfile", "dofile", "SUITE_DIR" },
  max_line_length = 124,  -- hostile_test.cpp quotes its line 7
}

-- An exercise defined in Lua (engine/exercise/scripted_exercise.cpp): its one global is exercise{}.
files["scripts/exercises/"] = { read_globals = { "exercise" } }

files["tests/grading/suites/"] = { read_globals = suite_globals }

-- Scripts run by `meshedit run` (engine/script/lua_runtime.cpp gives them `arg`).
files["tests/script/conventions/"] = { read_globals = { "arg" } }

-- The LuaLS descriptions of the API (---@meta files, for editors only): they define the globals they describe,
-- as stubs with empty bodies (every argument unused) on class tables that only the annotations read.
files["scripts/api/"] = { ignore = { "212", "241", "211/Edge" } }
files["scripts/api/lesson.lua"] = { globals = lesson_globals }
files["scripts/api/grading.lua"] = { globals = suite_globals }
files["scripts/api/meshedit.lua"] = { globals = { "meshedit" } }
