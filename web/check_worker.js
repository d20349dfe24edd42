// The page's Check my work worker: a copy of the program (meshedit.js, its .wasm and .data) loaded in a Web Worker
// without its window (main never runs), running one test at a time for the page's thread
// (engine/app/check_process_web.cpp), which scores each run, stops a test past its time limit by ending this worker,
// and makes the report. Student code runs here, never on the page's thread.
//
// A message from the page: {run, suite, index, files: [{relative, bytes}]}: test `index` of the packaged suite file
// `suite` on the submission `files`, written to /check/submission when `run` is a new check's. The worker answers
// {kind: 'started'} as the test begins and {kind: 'result', seconds, text} (the TestRun as grade/report_json.h's text)
// as it ends; {kind: 'log', text} for what the program printed on stderr, {kind: 'crash', text} when it aborted.
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
  const text = ccall('meshedit_check_test', 'string', ['string', 'string', 'number'],
                     [message.suite, kFolder, message.index]);
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
    for (const message of waiting.splice(0)) runTest(message);
  },
};

onmessage = (event) => {
  if (ready) runTest(event.data);
  else waiting.push(event.data);
};

importScripts('meshedit.js');
