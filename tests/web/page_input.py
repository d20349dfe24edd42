"""page_input.py: what page_driver.py gives the page as a person at the keyboard and mouse would, over the DevTools
protocol: clicks and key presses the browser delivers to the page as real input events (the program's GLFW callbacks
receive them as they receive a person's), a file the program wrote in its in-memory file system, and the middle of a
panel in the program's layout (`layout-json PATH`, engine/app/layout_report.h).

Dear ImGui 1.86, the page's, reads a key's state once a frame: a press and its release within one frame would be
missed, so each event is followed by a pause of a few frames.
"""
import json
import time

# Between two input events: a few of the page's frames (SwiftShader draws one in about 70 ms).
PAUSE_SECONDS = 0.4

# The keys a --keys word may name besides the letters: DOM key, code and virtual key code.
CONTROL = {"key": "Control", "code": "ControlLeft", "windowsVirtualKeyCode": 17, "location": 1}
SHIFT = {"key": "Shift", "code": "ShiftLeft", "windowsVirtualKeyCode": 16, "location": 1}
MODIFIER_BITS = {"ctrl": 2, "shift": 8}


def pause(browser, seconds=PAUSE_SECONDS):
    """Lets `seconds` pass, keeping the browser's events for the driver's loop."""
    deadline = time.monotonic() + seconds
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            return
        message = browser.receive(left)
        if message is None:
            return
        if "method" in message:
            browser.events.append(message)


def read_page_file(browser, session, path):
    """The text of `path` in the program's file system, or "" while it does not exist."""
    expression = "(() => { try { return FS.readFile(%s, {encoding: 'utf8'}); } catch (e) { return ''; } })()" % (
        json.dumps(path))
    reply = browser.call("Runtime.evaluate", {"expression": expression, "returnByValue": True}, session)
    return reply["result"].get("value") or ""


def panel_middle(layout_text, name):
    """The middle of the panel `name` of a layout-json text, in window pixels."""
    for panel in json.loads(layout_text)["panels"]:
        if panel["name"] == name:
            x, y, width, height = panel["rect"]
            return x + width / 2, y + height / 2
    raise RuntimeError("the layout has no panel '%s'" % name)


def click(browser, session, x, y):
    """The mouse moves to (x, y) in CSS pixels, then the left button is pressed and released there."""
    browser.call("Input.dispatchMouseEvent", {"type": "mouseMoved", "x": x, "y": y}, session)
    pause(browser)
    for kind, buttons in (("mousePressed", 1), ("mouseReleased", 0)):
        browser.call("Input.dispatchMouseEvent",
                     {"type": kind, "x": x, "y": y, "button": "left", "buttons": buttons, "clickCount": 1}, session)
        pause(browser)


def letter_key(letter):
    upper = letter.upper()
    if len(upper) != 1 or not "A" <= upper <= "Z":
        raise ValueError("a --keys word is a letter with ctrl+ or shift+ before it, not '%s'" % letter)
    return {"key": letter.lower(), "code": "Key" + upper, "windowsVirtualKeyCode": ord(upper)}


def press_key(browser, session, word):
    """The key `word` (S, ctrl+S, shift+L) as a person presses it: the modifiers held down first, the key pressed
    and released, the modifiers released. No text goes with it, as none goes with a Ctrl combination."""
    *modifiers, letter = word.split("+")
    held = []
    bits = 0
    for modifier in modifiers:
        if modifier not in MODIFIER_BITS:
            raise ValueError("unknown modifier '%s' in '%s'" % (modifier, word))
        bits |= MODIFIER_BITS[modifier]
        held.append(CONTROL if modifier == "ctrl" else SHIFT)
    key = letter_key(letter)
    presses = [("rawKeyDown", modifier, bits) for modifier in held]
    presses += [("rawKeyDown", key, bits), ("keyUp", key, bits)]
    presses += [("keyUp", modifier, 0) for modifier in reversed(held)]
    for kind, which, modifier_bits in presses:
        browser.call("Input.dispatchKeyEvent", dict(which, type=kind, modifiers=modifier_bits,
                                                    nativeVirtualKeyCode=which["windowsVirtualKeyCode"]), session)
        pause(browser)
