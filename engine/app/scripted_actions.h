// Scripted actions: how GUI tests (and bug reports) drive the window without a person, through the same
// handlers a key press or a click reaches. `meshedit FILE --actions script.txt` runs one action per line
// between frames, then closes the window; the exit status is 0 when every `expect` held, 3 otherwise.
//
//   # comment                      frames N            key F | key ctrl+Z | key shift+S
//   select h12                     click X Y           (view pixels, below)
//   hover X Y                      open PATH           save PATH           screenshot PATH
//   open-repaired         (File > Open a repaired copy of the mesh file `open` last refused)
//   triangulate           (Edit > Triangulate)
//   repair-row K          (clicks the Repairs tab's K-th change, 1 the first: selects its first spot; fails when
//                          there is no such row, it has no spot, or the spots are stale)
//   expect-selected h12            expect-field h0 next h3                expect-changed h0 next
//   expect-message TEXT...         expect-valid        quit
//   console LUA CODE...            expect-console TEXT...   (the console's last line contains TEXT)
//   lesson-next   lesson-back   lesson-button LABEL...
//   expect-lesson-step 3 waiting|finished|failed   expect-lesson-said TEXT...  (the step said TEXT)
//   lesson-choose OPTION...   (presses that option of the choose{} the step asks, as its button in the panel does)
//   lesson-answer TEXT...     (types TEXT into the answer{} box and presses Check; a pick{} is answered by click-on)
//   expect-lesson-feedback TEXT...   (the feedback on the last wrong answer to the question asked, or the diagnosis of
//                                     the your_turn waited on, contains TEXT)
//   lesson-show-mine      (presses the your_turn's "Show mine vs reference": fails when the step waits on no wrong
//                          your_turn)
//   expect-exercise-run TEXT...   (the Exercises tab's last run, as "LABEL (INPUT): SUMMARY" ("mine: flip e0 (e0 of a
//                                  mesh with 2 faces): different: ..."), contains TEXT)
//   expect-lesson-hint TEXT...       (the question's hint is shown, and contains TEXT)
//   expect-lesson-live TEXT...       (a live() text of the step contains TEXT, as the last frame evaluated it)
//   curve-t T             (the curve view's t, as its slider sets it)
//   exercise flip FOLDER   run-mine   run-reference   replay-start   replay-step K   replay-finish
//   exercise curve|patch FOLDER   (where the curve and patch views' "mine", key M, reads curve.lua, patch.lua)
//   expect-mine TEXT...   (the "mine" line of the curve or patch view on screen contains TEXT; computed when a
//                          frame draws the view, so the check waits for the frame after the action before it)
//   orbit DX DY           (the camera turns as a drag of DX, DY pixels would turn it)
//   expect-gpu-update patch|rebuild   (how the mesh view's last geometry update went: the slots an edit touched
//                          rewritten in place, or everything rebuilt; made by the next frame, which the check
//                          waits for)
//   click X Y             (view pixels: framebuffer pixels from the view's top-left corner, as picking counts them)
//   click-on h12          (a click where the element's label anchor is on screen: a vertex's position, an edge's
//                          midpoint, a face's centre, a halfedge's arrow; fails when it is not in the view)
//   layout-json PATH      (writes the window's layout as JSON: app/layout_report.h)
//   window-size W H       (asks the window system to resize the window before the next frame)
//   key names: a letter, space, escape, grave, equal (=), minus (-), 0, [ and ], with ctrl+ and shift+
//   up-axis from-file|y|z  (View > Up axis: the file's, or Y or Z up; refits the view)
//   expect-up-axis X|Y|Z [TEXT...]   (the camera's up axis, and the status bar's up-axis words contain TEXT)
//   animate-edits on|off  (flip, split, collapse and their undo and redo play for a quarter second, as in a window a
//                          person uses, whatever the settings say; a scripted run starts with them off)
#pragma once

#include <string>
#include <vector>

namespace meshedit {

struct ScriptedAction {
  std::string verb;
  std::vector<std::string> args;
  std::string source;  // "script.txt:12", for messages
};

// Parses a script; throws std::runtime_error("script.txt:4: unknown action 'klick'") on a bad line.
std::vector<ScriptedAction> parse_actions(const std::string& text, const std::string& name);
std::vector<ScriptedAction> read_actions(const std::string& path);

}  // namespace meshedit
