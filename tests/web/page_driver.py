#!/usr/bin/env python3
"""page_driver.py: opens the web page in headless Chromium and drives it over the DevTools protocol (a pipe, the
standard library only), in real time, until the page's test hook reports the verdict of its ?actions= script.

    page_driver.py URL [--pick FILE] [--drop FILE...] [--download NAME --downloads DIR [--download-contains TEXT]]
                       [--ready PATH] [--click-panel NAME] [--keys KEY...] [--viewport WxH] [--screenshot PNG]
                       [--check-results JSON] [--timeout S] [--then ACTIONS]

--pick FILE answers the page's file picker with FILE when the program opens it (the script's `open-picker`): the
  browser's own chooser is intercepted and given the file, as a person choosing it would. Until it opens, the page
  gets a user gesture every poll, as a click would give it (a browser shows a picker only shortly after one).
--drop FILE... drops the files (together, in one drop) on the middle of the page once the program has drawn its first
  frame (or once the script is ready, with --ready), as a person dragging them from a file manager does.
--download NAME expects the page to download a file named NAME into DIR: a .png must be a PNG of the canvas's size;
  with --download-contains TEXT, the downloaded bytes must contain TEXT (a student's .lua).
--ready PATH: the drop, the click and the keys wait until the script has written PATH in the page's file system (its
  `layout-json PATH`), the moment it is ready for what comes from outside; it then waits for them with wait-message.
--click-panel NAME clicks the middle of the panel NAME of that layout ("right column"), as a person's mouse does.
--keys KEY... then presses the keys (ctrl+S: Control held, S pressed and released, Control released), each a key
  event the browser delivers to the page as a person's typing arrives, a few frames apart.
--viewport WxH makes the page's viewport W x H CSS pixels at a device pixel ratio of 1 (the canvas W x H pixels),
  as a desktop window of that size; headless Chromium's own is smaller than its window.
--screenshot PNG keeps what the page shows when the script has ended.
--check-results JSON writes the text of the page's <script id="check-results"> (the last Check my work's
  results.json) to JSON when the script has ended; the page must have one.
--timeout S: the seconds the script may take (120); a page busy in one long frame answers no poll until it ends.
--then ACTIONS loads the page again, once its script held, in the same browser profile (its storage kept, as a
  student's reload keeps it), with the actions of the file ACTIONS in place of the URL's, and waits for their verdict.

Prints what the program printed (<pre id="log">), the first frame's time and the verdict. Exit status: 0 when the
page said "actions: all expectations held" (and the download, if asked for, arrived as expected, and the input asked
for was given); 1 otherwise.
"""
import argparse
import base64
import json
import os
import select
import struct
import subprocess
import sys
import tempfile
import time
import urllib.parse

import page_input

CHROMIUM = ["chromium", "--headless=new", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
            "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--window-size=1280,800", "--remote-debugging-pipe"]


class Browser:
    """Chromium with its DevTools protocol on fds 3 (commands in) and 4 (replies and events out)."""

    def __init__(self, profile):
        commands_r, self.commands = os.pipe()
        self.replies, replies_w = os.pipe()

        def on_fds_3_and_4():
            os.dup2(commands_r, 3)
            os.dup2(replies_w, 4)

        self.process = subprocess.Popen(CHROMIUM + ["--user-data-dir=" + profile, "about:blank"],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                        preexec_fn=on_fds_3_and_4, pass_fds=(3, 4))
        os.close(commands_r)
        os.close(replies_w)
        self.buffer = b""
        self.last_id = 0
        self.events = []

    def send(self, method, params=None, session=None):
        self.last_id += 1
        message = {"id": self.last_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.commands, json.dumps(message).encode() + b"\0")
        return self.last_id

    def receive(self, timeout):
        """The next message, or None after `timeout` seconds without one."""
        deadline = time.monotonic() + timeout
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.replies], [], [], left)[0]:
                return None
            chunk = os.read(self.replies, 1 << 20)
            if not chunk:
                raise RuntimeError("chromium closed its DevTools pipe")
            self.buffer += chunk
        message, _, self.buffer = self.buffer.partition(b"\0")
        return json.loads(message)

    def call(self, method, params=None, session=None, timeout=30):
        wanted = self.send(method, params, session)
        deadline = time.monotonic() + timeout
        while True:
            message = self.receive(max(0.0, deadline - time.monotonic()))
            if message is None:
                raise RuntimeError(method + ": no reply in %d s" % timeout)
            if message.get("id") == wanted:
                if "error" in message:
                    raise RuntimeError(method + ": " + message["error"].get("message", str(message["error"])))
                return message.get("result", {})
            if "method" in message:
                self.events.append(message)

    def take_events(self, timeout):
        message = self.receive(timeout)
        while message is not None:
            if "method" in message:
                self.events.append(message)
            message = self.receive(0)
        events, self.events = self.events, []
        return events

    def close(self):
        try:
            self.send("Browser.close")
            self.process.wait(timeout=10)
        except Exception:
            self.process.kill()
            self.process.wait()


PAGE_STATE = """JSON.stringify({
  actions: document.body.dataset.actions || '',
  firstFrameMs: document.body.dataset.firstFrameMs || '',
  frameMs: document.body.dataset.frameMs || '',
  log: (document.getElementById('log') || {}).textContent || '',
  width: document.getElementById('canvas').width,
  height: document.getElementById('canvas').height,
  cssWidth: window.innerWidth,
  cssHeight: window.innerHeight})"""

# The last Check my work's results.json, or null when the page has none.
CHECK_RESULTS = "(document.getElementById('check-results') || {}).textContent ?? null"


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", head[16:24])


def check_download(path, canvas, contains):
    """"" when the downloaded file at `path` is what was asked for, else what is wrong with it."""
    if path.endswith(".png"):
        size = png_size(path)
        if size is None:
            return "%s is no PNG" % path
        if size != canvas:
            return "%s is %dx%d, the canvas %sx%s" % ((path,) + size + canvas)
        return ""
    with open(path, "rb") as f:
        data = f.read()
    if contains is not None and contains.encode() not in data:
        return "%s (%d bytes) does not contain '%s'" % (path, len(data), contains)
    return ""


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("url")
    parser.add_argument("--pick")
    parser.add_argument("--drop", nargs="+")
    parser.add_argument("--download")
    parser.add_argument("--downloads")
    parser.add_argument("--download-contains")
    parser.add_argument("--ready")
    parser.add_argument("--click-panel")
    parser.add_argument("--keys", nargs="+", default=[])
    parser.add_argument("--viewport")
    parser.add_argument("--screenshot")
    parser.add_argument("--check-results")
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--then")
    args = parser.parse_args()
    if args.download and not args.downloads:
        parser.error("--download needs --downloads DIR")
    if args.click_panel and not args.ready:
        parser.error("--click-panel needs --ready PATH, the layout it reads the panel from")

    profile = tempfile.TemporaryDirectory()
    browser = Browser(profile.name)
    ok = False
    try:
        target = browser.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = browser.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        browser.call("Page.enable", session=session)
        browser.call("Runtime.enable", session=session)
        if args.pick:
            browser.call("Page.setInterceptFileChooserDialog", {"enabled": True}, session)
        if args.download:
            os.makedirs(args.downloads, exist_ok=True)
            stale = os.path.join(args.downloads, args.download)
            if os.path.exists(stale):
                os.remove(stale)
            browser.call("Browser.setDownloadBehavior",
                         {"behavior": "allow", "downloadPath": os.path.abspath(args.downloads), "eventsEnabled": True})
        if args.viewport:
            width, height = (int(n) for n in args.viewport.split("x"))
            browser.call("Emulation.setDeviceMetricsOverride",
                         {"width": width, "height": height, "deviceScaleFactor": 1, "mobile": False}, session)
        browser.call("Page.navigate", {"url": args.url}, session)

        deadline = time.monotonic() + args.timeout
        state = {}
        picked = False
        outside_input = bool(args.drop or args.click_panel or args.keys)
        given = False
        download_done = False
        while time.monotonic() < deadline:
            for event in browser.take_events(0.25):
                method, params = event["method"], event.get("params", {})
                if method == "Page.fileChooserOpened" and args.pick and not picked:
                    browser.call("DOM.setFileInputFiles",
                                 {"files": [os.path.abspath(args.pick)], "backendNodeId": params["backendNodeId"]},
                                 session)
                    picked = True
                    print("page_driver: the page's file picker opened; picked " + args.pick)
                elif method == "Runtime.exceptionThrown":
                    details = params.get("exceptionDetails", {})
                    print("page_driver: uncaught in the page: " +
                          details.get("exception", {}).get("description", details.get("text", "")))
                elif method == "Browser.downloadProgress" and params.get("state") == "completed":
                    download_done = True
            # A frame that runs a long script (a runaway stopped by its budget) holds the page: wait it out.
            reply = browser.call("Runtime.evaluate", {"expression": PAGE_STATE, "returnByValue": True}, session,
                                 timeout=max(30.0, deadline - time.monotonic()))
            state = json.loads(reply["result"].get("value") or "{}")
            if state.get("actions"):
                break
            if not state.get("firstFrameMs"):
                continue
            if args.pick and not picked:
                browser.call("Runtime.evaluate", {"expression": "0", "userGesture": True}, session)
            if not outside_input or given:
                continue
            layout = page_input.read_page_file(browser, session, args.ready) if args.ready else ""
            if args.ready and not layout:
                continue
            if args.drop:
                x, y = state["cssWidth"] / 2, state["cssHeight"] / 2
                data = {"items": [], "files": [os.path.abspath(f) for f in args.drop], "dragOperationsMask": 1}
                for kind in ("dragEnter", "dragOver", "drop"):
                    browser.call("Input.dispatchDragEvent", {"type": kind, "x": x, "y": y, "data": data}, session)
                print("page_driver: dropped " + " ".join(args.drop) + " on the page")
            if args.click_panel:
                x, y = page_input.panel_middle(layout, args.click_panel)
                css_per_pixel = state["cssWidth"] / state["width"]  # the layout counts the canvas's pixels
                x, y = x * css_per_pixel, y * css_per_pixel
                page_input.click(browser, session, x, y)
                print("page_driver: clicked the middle of the %s at %d, %d" % (args.click_panel, x, y))
            for key in args.keys:
                page_input.press_key(browser, session, key)
                print("page_driver: pressed " + key)
            given = True

        print(state.get("log", "").rstrip())
        if state.get("firstFrameMs"):
            print("page_driver: first frame %s ms after the page started" % state["firstFrameMs"])
        if state.get("frameMs"):
            print("page_driver: frames %s ms apart (median of 30)" % state["frameMs"])
        verdict = state.get("actions") or "no verdict in %d s" % args.timeout
        print("page_driver: " + verdict)
        ok = verdict == "actions: all expectations held"
        if outside_input and not given:
            print("page_driver: the script never became ready for the input asked for (%s)" % args.ready)
            ok = False

        # --then ACTIONS: the page loaded again in the same browser profile (its storage kept), with those actions.
        if ok and args.then:
            with open(args.then) as f:
                again = f.read()
            url = urllib.parse.urlsplit(args.url)
            query = [(k, v) for k, v in urllib.parse.parse_qsl(url.query, keep_blank_values=True) if k != "actions"]
            query.append(("actions", again))
            url = url._replace(query=urllib.parse.urlencode(query, quote_via=urllib.parse.quote))
            print("page_driver: the page loaded again with " + args.then)
            browser.call("Page.navigate", {"url": urllib.parse.urlunsplit(url)}, session)
            state = {}
            deadline = time.monotonic() + args.timeout
            while time.monotonic() < deadline:
                browser.take_events(0.25)
                reply = browser.call("Runtime.evaluate", {"expression": PAGE_STATE, "returnByValue": True}, session)
                state = json.loads(reply["result"].get("value") or "{}")
                if state.get("actions"):
                    break
            print(state.get("log", "").rstrip())
            verdict = state.get("actions") or "no verdict in %d s" % args.timeout
            print("page_driver: after loading again: " + verdict)
            ok = verdict == "actions: all expectations held"

        if args.check_results:
            reply = browser.call("Runtime.evaluate", {"expression": CHECK_RESULTS, "returnByValue": True}, session)
            text = reply["result"].get("value")
            if text is None:
                print("page_driver: the page has no <script id=\"check-results\">")
                ok = False
            else:
                with open(args.check_results, "w") as f:
                    f.write(text)
                print("page_driver: the page's check results are in " + args.check_results)
        if args.screenshot:
            shot = browser.call("Page.captureScreenshot", {"format": "png"}, session)
            with open(args.screenshot, "wb") as f:
                f.write(base64.b64decode(shot["data"]))
        if args.download:
            path = os.path.join(args.downloads, args.download)
            wait_until = time.monotonic() + 15
            while not download_done and time.monotonic() < wait_until:
                for event in browser.take_events(0.25):
                    if event["method"] == "Browser.downloadProgress" and event["params"].get("state") == "completed":
                        download_done = True
            canvas = (state.get("width"), state.get("height"))
            wrong = check_download(path, canvas, args.download_contains) if download_done and os.path.exists(
                path) else "nothing downloaded as " + path
            if wrong:
                print("page_driver: " + wrong)
                ok = False
            elif path.endswith(".png"):
                print("page_driver: downloaded %s, a %dx%d PNG (the canvas's size)" % ((path,) + canvas))
            else:
                print("page_driver: downloaded %s (%d bytes)%s" % (path, os.path.getsize(path), "" if
                      args.download_contains is None else ", which contains '%s'" % args.download_contains))
    finally:
        browser.close()
        profile.cleanup()
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
