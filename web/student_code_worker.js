// The page's worker for student code: a copy of the program (meshedit.js, its .wasm and .data) loaded in a Web Worker
// without its window (main never runs), so student code runs here, never on the page's thread. It does one of two
// kinds of job, one message at a time:
// - Check my work (engine/app/check_process_web.cpp, which scores each run, stops a test past its time limit by
//   ending this worker, and makes the report): {run, suite, index, files: [{relative, bytes}]} is test `index` of the
//   packaged suite file `suite` on the submission `files`, written to /check/submission when `run` is a new check's.
//   The worker answers {kind: 'started'} as the test begins and {kind: 'result', seconds, text} (the TestRun as
//   grade/report_json.h's text) as it ends.
// - A job of bytes (engine/document/page_worker_job.h, which ends this worker on Stop or past the job's time):
//   {call, entry} is bytes for the program's C function `entry`, which leaves its answer's bytes in the same room:
//   meshedit_student_call (Run mine, a lesson's your_turn: the call's bytes, exercise/student_call_text.h) or
//   meshedit_writeup (File > Write-up: the request's bytes, writeup/writeup_text.h). The worker answers
//   {kind: 'started'}, then {kind: 'result', bytes} with the answer's bytes.
// Either way {kind: 'log', text} is what the program printed on stderr, {kind: 'crash', text} that it aborted.
'use strict';

const kFolder = '/check/submission';
let ready = false;
let filesOfRun = null;
const waiting = [];

const removeTree = (path) => {
  if (!FS.analyzePath(path).exists) return;
  for (const name of FS.readdir(path)) {
    if (name === '.' || name === '..') continue;
    const child = path + '/' + name;
    if (FS.isDir(FS.stat(child).mode)) removeTree(child);
    else FS.unlink(child);
  }
  FS.rmdir(path);
};

const runTest = (message) => {
  if (filesOfRun !== message.run) {
    removeTree(kFolder);
    FS.mkdirTree(kFolder);
    for (const file of message.files) {
      const path = kFolder + '/' + file.relative;
      FS.mkdirTree(path.slice(0, path.lastIndexOf('/')));
      FS.writeFile(path, file.bytes);
    }
    filesOfRun = message.run;
  }
  postMessage({kind: 'started'});
  const began = performance.now();
  const text = ccall('meshedit_check_test', 'string', ['string', 'string', 'number', 'string'],
                     [message.suite, kFolder, message.index, message.language || 'en']);
  postMessage({kind: 'result', seconds: (performance.now() - began) / 1000, text});
};

var Module = {  // eslint-disable-line no-var: meshedit.js reads the global Module
  noInitialRun: true,
  print: () => {},  // the student's prints are the grader's to keep (in the test's run)
  printErr: (text) => postMessage({kind: 'log', text}),
  onAbort: (what) => postMessage({kind: 'crash', text: 'the program stopped: ' + what}),
  onRuntimeInitialized: () => {
    FS.chdir('/meshedit');
    ready = true;
    for (const message of waiting.splice(0)) handle(message);
  },
};

const runCall = (message) => {
  postMessage({kind: 'started'});
  const room = ccall('meshedit_student_call_room', 'number', ['number'], [message.call.length]);
  HEAPU8.set(message.call, room);
  const at = ccall(message.entry || 'meshedit_student_call', 'number', [], []);
  if (!at) {
    postMessage({kind: 'crash', text: 'memory ran out in the worker'});
    return;
  }
  const size = ccall('meshedit_student_call_size', 'number', [], []);
  const bytes = HEAPU8.slice(at, at + size);
  postMessage({kind: 'result', bytes}, [bytes.buffer]);
};

const handle = (message) => {
  if (message.call) runCall(message);
  else runTest(message);
};

onmessage = (event) => {
  if (ready) handle(event.data);
  else waiting.push(event.data);
};

importScripts('meshedit.js');
