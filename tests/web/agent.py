#!/usr/bin/env python3
"""A browser agent for tests/serve_web.rs: headless Chromium through
selenium, one browser per student, driven by JSON commands on stdin (one a
line), each answered by one JSON line on stdout:

  {"op": "open", "name": "ada", "url": "http://…/?name=ada", "w": 1200, "h": 800}
  {"op": "open", …, "mobile": true}   a phone: Chromium's mobile emulation at
                                       w×h CSS pixels, touch, an Android agent
  {"op": "tap", "name": "ada", "label": "more"}   a finger's tap on the
                                       element of that aria-label
  {"op": "shot", "name": "ada", "path": "/tmp/a.png"}   a screenshot
  {"op": "text", "name": "ada"}        the terminal's text (screen-reader rows)
  {"op": "keys", "name": "ada", "keys": ["Right", "S-Right", "Enter", "q"]}
  {"op": "resize", "name": "ada", "w": 400, "h": 800}
  {"op": "js", "name": "ada", "script": "return …"}
  {"op": "close", "name": "ada"}       the tab closes (its WebSocket with it)
  {"op": "quit"}

Answers: {"ok": true, "value": …} or {"ok": false, "error": "…"}.
"""
import json
import sys
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.options import Options
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.actions import interaction
from selenium.webdriver.common.actions.action_builder import ActionBuilder
from selenium.webdriver.common.actions.pointer_input import PointerInput
from selenium.webdriver.common.keys import Keys

FLAGS = [
    "--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic",
    "--no-first-run", "--disable-background-networking",
    "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage",
]

KEYS = {
    "Enter": Keys.ENTER, "Left": Keys.ARROW_LEFT, "Right": Keys.ARROW_RIGHT,
    "Up": Keys.ARROW_UP, "Down": Keys.ARROW_DOWN, "Escape": Keys.ESCAPE,
    "Tab": Keys.TAB,
}

ANDROID = ("Mozilla/5.0 (Linux; Android 14; Pixel 8) AppleWebKit/537.36 "
           "(KHTML, like Gecko) Chrome/126.0 Mobile Safari/537.36")

browsers = {}
homes = []

TEXT = """
const t = document.querySelector('.xterm-accessibility-tree');
if (!t) { return null; }
return Array.from(t.children).map(r => r.textContent.replace(/\\u00a0/g, ' ')).join('\\n');
"""


def open_browser(c):
    o = Options()
    home = tempfile.TemporaryDirectory(prefix="roughtui-chromium-")
    homes.append(home)
    for f in FLAGS + [f"--user-data-dir={home.name}", f"--window-size={c['w']},{c['h']}"]:
        o.add_argument(f)
    o.binary_location = "/usr/bin/chromium"
    if c.get("mobile"):
        o.add_experimental_option("mobileEmulation", {
            "deviceMetrics": {"width": c["w"], "height": c["h"], "pixelRatio": 2.0,
                              "touch": True},
            "userAgent": ANDROID,
        })
    d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=o)
    d.set_page_load_timeout(30)
    d.get(c["url"])
    browsers[c["name"]] = d
    return True


def keys(c):
    d = browsers[c["name"]]
    area = d.find_element("css selector", ".xterm-helper-textarea")
    a = ActionChains(d)
    for k in c["keys"]:
        if k.startswith("S-"):
            a.key_down(Keys.SHIFT, area).send_keys(KEYS[k[2:]]).key_up(Keys.SHIFT)
        else:
            a.send_keys_to_element(area, KEYS.get(k, k))
    a.perform()
    return True


def tap(c):
    d = browsers[c["name"]]
    el = d.find_element("css selector", f'[aria-label="{c["label"]}"]')
    finger = PointerInput(interaction.POINTER_TOUCH, "finger")
    a = ActionBuilder(d, mouse=finger)
    a.pointer_action.move_to(el).pointer_down().pause(0.05).pointer_up()
    a.perform()
    return True


def run(c):
    op = c["op"]
    if op == "open":
        return open_browser(c)
    if op == "quit":
        for d in browsers.values():
            d.quit()
        return True
    d = browsers[c["name"]]
    if op == "text":
        return d.execute_script(TEXT)
    if op == "keys":
        return keys(c)
    if op == "tap":
        return tap(c)
    if op == "shot":
        return d.save_screenshot(c["path"])
    if op == "resize":
        d.set_window_size(c["w"], c["h"])
        return True
    if op == "js":
        return d.execute_script(c["script"])
    if op == "close":
        d.quit()
        del browsers[c["name"]]
        return True
    raise ValueError(f"no such op {op}")


for line in sys.stdin:
    try:
        c = json.loads(line)
        out = {"ok": True, "value": run(c)}
    except Exception as e:  # the test prints it
        out = {"ok": False, "error": f"{type(e).__name__}: {e}".splitlines()[0]}
    print(json.dumps(out), flush=True)
    if c.get("op") == "quit":
        break
