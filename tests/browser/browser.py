"""A headless Chromium the browser tests drive, over the DevTools protocol on a pipe.

No dependency beyond Python's standard library: Chromium is started with --remote-debugging-pipe,
which makes it read protocol messages (JSON, each ended by a NUL byte) on fd 3 and write its
answers and events on fd 4. A test opens a page, presses keys, clicks, moves range inputs,
evaluates JavaScript and takes screenshots; every console error and uncaught exception the page
raises is collected, and `check_no_errors()` fails the test on any of them.

    with Browser(out_dir) as browser:
        page = browser.open(path)              # a file:// page; waits for its load event
        page.press("ArrowRight")
        assert page.eval("document.title") == "..."
        page.screenshot("after-next.png")      # under out_dir
        page.check_no_errors()

The browser runs in a process group of its own, with a temporary profile; close() (and leaving the
`with`, and a timeout) ends every process of that group, and any other process started with the
profile, and removes the profile.
"""

import base64
import json
import os
import pathlib
import select
import shutil
import signal
import subprocess
import tempfile
import time


class BrowserError(Exception):
    """The browser did not answer, answered with an error, or the page raised one."""


def find_chromium():
    """The Chromium to run: $NUMLAB_CHROMIUM, else `chromium` or `chromium-browser` on PATH; None if none."""
    named = os.environ.get("NUMLAB_CHROMIUM")
    if named:
        return named
    for name in ("chromium", "chromium-browser"):
        found = shutil.which(name)
        if found:
            return found
    return None


# The keys press() knows: DOM key name -> (code, Windows virtual key code).
KEYS = {
    "ArrowLeft": ("ArrowLeft", 37), "ArrowRight": ("ArrowRight", 39), "ArrowUp": ("ArrowUp", 38),
    "ArrowDown": ("ArrowDown", 40), "Home": ("Home", 36), "End": ("End", 35), "Enter": ("Enter", 13),
    " ": ("Space", 32), "Tab": ("Tab", 9), "Escape": ("Escape", 27),
}


class Page:
    """One tab, attached in flat mode: commands carry its session id."""

    def __init__(self, browser, session_id):
        self.browser = browser
        self.session = session_id
        self.errors = []  # one line per console error or uncaught exception
        self.scripts = True

    def send(self, method, params=None):
        return self.browser.send(method, params, session=self.session)

    # 1. Loading.
    def navigate(self, url):
        """Goes to `url` and waits for its load event."""
        self.browser.drain_events()
        reply = self.send("Page.navigate", {"url": url})
        if reply.get("errorText"):
            raise BrowserError(f"cannot open {url}: {reply['errorText']}")
        self.browser.wait_event("Page.loadEventFired", self.session)

    def disable_scripts(self, disabled=True):
        """JavaScript off (or on again) for the next navigation: what a reader without scripts sees."""
        self.send("Emulation.setScriptExecutionDisabled", {"value": disabled})
        self.scripts = not disabled

    def emulate_media(self, media="", reduced_motion=None):
        """CSS media type ('print', 'screen' or '' for none) and prefers-reduced-motion ('reduce' or None)."""
        features = [{"name": "prefers-reduced-motion", "value": reduced_motion or ""}]
        self.send("Emulation.setEmulatedMedia", {"media": media, "features": features})

    # 2. Reading the page.
    def eval(self, expression):
        """The value of a JavaScript expression (awaited if a promise); an exception in it is a BrowserError."""
        reply = self.send("Runtime.evaluate", {"expression": expression, "returnByValue": True,
                                               "awaitPromise": True, "userGesture": True})
        if "exceptionDetails" in reply:
            details = reply["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text")
            raise BrowserError(f"JavaScript error evaluating {expression!r}: {text}")
        return reply["result"].get("value")

    def exists(self, selector):
        return bool(self.eval(f"document.querySelector({json.dumps(selector)}) !== null"))

    def text(self, selector):
        """The textContent of the first element matching `selector` (a BrowserError if there is none)."""
        value = self.eval(f"(e => e ? e.textContent : null)(document.querySelector({json.dumps(selector)}))")
        if value is None:
            raise BrowserError(f"no element matches {selector}")
        return value

    # 3. Acting on it, as a user would.
    def press(self, key, selector=None):
        """Presses and releases `key` (a name from KEYS, or one character), on `selector` focused first if given."""
        if selector is not None:
            self.eval(f"document.querySelector({json.dumps(selector)}).focus()")
        code, vk = KEYS.get(key, (f"Key{key.upper()}", ord(key.upper()) if len(key) == 1 else 0))
        common = {"key": key, "code": code, "windowsVirtualKeyCode": vk, "nativeVirtualKeyCode": vk}
        text = {"text": key} if len(key) == 1 else {}
        self.send("Input.dispatchKeyEvent", {"type": "keyDown", **common, **text})
        self.send("Input.dispatchKeyEvent", {"type": "keyUp", **common})

    def click(self, selector):
        """A real mouse click at the centre of the first element matching `selector`, scrolled into view."""
        box = self.eval(
            f"(e => {{ if (!e) return null; e.scrollIntoView({{block: 'center'}});"
            f" const r = e.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2, r.width]; }})"
            f"(document.querySelector({json.dumps(selector)}))")
        if box is None:
            raise BrowserError(f"nothing to click: no element matches {selector}")
        if box[2] == 0:
            raise BrowserError(f"nothing to click: {selector} is not displayed")
        for kind in ("mousePressed", "mouseReleased"):
            self.send("Input.dispatchMouseEvent",
                      {"type": kind, "x": box[0], "y": box[1], "button": "left", "clickCount": 1})

    def set_range(self, selector, value):
        """Moves a range input to `value` as a drag would: the value set, then its input and change events."""
        self.eval(f"(e => {{ e.value = {json.dumps(str(value))};"
                  f" e.dispatchEvent(new Event('input', {{bubbles: true}}));"
                  f" e.dispatchEvent(new Event('change', {{bubbles: true}})); }})"
                  f"(document.querySelector({json.dumps(selector)}))")

    def screenshot(self, name, full_page=False):
        """Saves a PNG of the viewport (or the whole page) as out_dir/name; returns its path."""
        params = {"format": "png"}
        if full_page:
            size = self.eval("[document.documentElement.scrollWidth, document.documentElement.scrollHeight]")
            params.update(captureBeyondViewport=True,
                          clip={"x": 0, "y": 0, "width": size[0], "height": min(size[1], 16000), "scale": 1})
        data = self.send("Page.captureScreenshot", params)["data"]
        path = pathlib.Path(self.browser.out_dir) / name
        path.write_bytes(base64.b64decode(data))
        return path

    # 4. Errors.
    def check_no_errors(self):
        """Raises BrowserError listing every console error and uncaught exception seen so far."""
        # A round trip through the page's event loop first: what the last action raised has been
        # reported (in order, on the same pipe) before this answer comes. (No timers without scripts.)
        self.eval("new Promise((resolve) => setTimeout(resolve, 0))" if self.scripts else "0")
        self.browser.drain_events()
        if self.errors:
            raise BrowserError("the page reported errors:\n  " + "\n  ".join(self.errors))

    def record_event(self, method, params):
        if method == "Runtime.exceptionThrown":
            details = params["exceptionDetails"]
            text = details.get("exception", {}).get("description") or details.get("text", "")
            self.errors.append(f"uncaught exception: {text} ({details.get('url', '')}:{details.get('lineNumber', 0) + 1})")
        elif method == "Runtime.consoleAPICalled" and params["type"] in ("error", "assert"):
            words = [str(arg.get("value", arg.get("description", ""))) for arg in params.get("args", [])]
            self.errors.append(f"console.{params['type']}: {' '.join(words)}")
        elif method == "Log.entryAdded" and params["entry"]["level"] == "error":
            entry = params["entry"]
            self.errors.append(f"log error ({entry.get('source')}): {entry.get('text')} {entry.get('url', '')}")


class Browser:
    """Headless Chromium on a DevTools pipe. Use as a context manager; `timeout` bounds each wait (s)."""

    def __init__(self, out_dir, chromium=None, timeout=30.0, width=1100, height=900, startup_timeout=120.0,
                 starts=2):
        self.out_dir = pathlib.Path(out_dir)
        self.out_dir.mkdir(parents=True, exist_ok=True)
        self.timeout = timeout
        self.chromium = chromium or find_chromium()
        if self.chromium is None:
            raise BrowserError("no chromium on PATH (Debian: apt-get install chromium; or set NUMLAB_CHROMIUM)")
        self.stderr_path = self.out_dir / "chromium-stderr.txt"
        self.stderr_path.write_bytes(b"")
        self.process = None
        # A cold start (the first on a fresh machine reads the whole browser from disk) can take far
        # longer than one command: the first answer may take `startup_timeout` seconds, and a browser
        # that gives none is ended and started once more (`starts` tries in all) before the test fails.
        for attempt in range(1, starts + 1):
            try:
                self.start(width, height, startup_timeout)
                return
            except BrowserError as error:
                self.close()
                if attempt == starts:
                    raise BrowserError(f"chromium did not start in {starts} tries of {startup_timeout:g} s: {error}; "
                                       f"its stderr ends: {self.stderr_tail()}") from None
                print(f"browser.py: chromium start {attempt} of {starts} failed ({error}); starting it again",
                      flush=True)

    def stderr_tail(self, lines=5):
        """The last lines chromium wrote on stderr, on one line (for an error message)."""
        text = self.stderr_path.read_text(errors="replace").strip().splitlines()
        return " | ".join(text[-lines:]) if text else "(nothing)"

    # 1. Starting and stopping.
    def start(self, width, height, startup_timeout):
        """Starts chromium on a fresh profile and waits for its first answer."""
        self.profile = tempfile.mkdtemp(prefix="numlab-chromium-")
        self.next_id = 0
        self.buffer = b""
        self.events = []  # (method, params, session) not yet consumed
        self.pages = {}   # session id -> Page
        to_browser_r, self.to_browser = os.pipe()
        self.from_browser, from_browser_w = os.pipe()
        arguments = [self.chromium, "--headless", "--remote-debugging-pipe", f"--user-data-dir={self.profile}",
                     "--no-first-run", "--no-default-browser-check", "--disable-extensions", "--disable-gpu",
                     "--disable-dev-shm-usage", "--disable-background-networking", "--disable-sync",
                     "--mute-audio", "--hide-scrollbars", f"--window-size={width},{height}", "about:blank"]
        if os.geteuid() == 0:
            arguments.insert(1, "--no-sandbox")  # Chromium refuses to run as root with its sandbox

        def pipe_to_fds_3_and_4():
            # Moved out of the way first, in case the pipes' own numbers are 3 or 4.
            reads, writes = os.dup(to_browser_r), os.dup(from_browser_w)
            os.dup2(reads, 3)
            os.dup2(writes, 4)

        # Its stderr goes straight to a file (appended over restarts): a pipe nobody reads could fill and stall it.
        with open(self.stderr_path, "ab") as stderr:
            self.process = subprocess.Popen(arguments, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                            stderr=stderr, pass_fds=(3, 4), preexec_fn=pipe_to_fds_3_and_4,
                                            start_new_session=True)
        os.close(to_browser_r)
        os.close(from_browser_w)
        self.send("Target.setDiscoverTargets", {"discover": True}, timeout=startup_timeout)

    def close(self):
        """Asks the browser to close, then ends whatever of it is left (the whole group), and removes the profile."""
        if self.process is None:
            return
        try:
            if self.process.poll() is None:
                self.send("Browser.close", timeout=5)
                self.process.wait(timeout=5)
        except (BrowserError, subprocess.TimeoutExpired, OSError):
            pass
        self.kill_everything()
        for fd in (self.to_browser, self.from_browser):
            try:
                os.close(fd)
            except OSError:
                pass
        self.process = None
        shutil.rmtree(self.profile, ignore_errors=True)

    def kill_everything(self):
        """SIGKILL to the browser's process group and to any process still using its profile; waits for them."""
        try:
            os.killpg(self.process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            pass
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            left = self.processes_left()
            if not left:
                return
            for pid in left:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            time.sleep(0.1)
        raise BrowserError(f"chromium processes still running after 10 s: {self.processes_left()}")

    def processes_left(self):
        """Pids of live processes in the browser's group or started with its profile (zombies excluded)."""
        left = []
        for entry in pathlib.Path("/proc").iterdir():
            if not entry.name.isdigit():
                continue
            try:
                stat = (entry / "stat").read_text()
                fields = stat[stat.rindex(")") + 2:].split()
                state, group = fields[0], int(fields[2])
                command = (entry / "cmdline").read_bytes()
            except (OSError, ValueError):
                continue
            if state != "Z" and (group == self.process.pid or self.profile.encode() in command):
                left.append(int(entry.name))
        return left

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # 2. The protocol.
    def send(self, method, params=None, session=None, timeout=None):
        """Sends one command and returns its result; events arriving meanwhile are kept."""
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        try:
            os.write(self.to_browser, json.dumps(message).encode() + b"\0")
        except BrokenPipeError:
            raise BrowserError(f"chromium closed the pipe waiting for {method}'s answer (see {self.stderr_path})") from None
        wanted = self.next_id
        deadline = time.monotonic() + (timeout or self.timeout)
        while True:
            for reply in self.read_messages(deadline, f"{method}'s answer"):
                if reply.get("id") == wanted:
                    if "error" in reply:
                        raise BrowserError(f"{method}: {reply['error'].get('message')} {reply['error'].get('data', '')}")
                    return reply.get("result", {})

    def read_messages(self, deadline, waiting_for):
        """Whatever whole messages have arrived (waiting for at least one); events are recorded and queued."""
        while b"\0" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                self.kill_everything()
                raise BrowserError(f"timeout waiting for {waiting_for}")
            ready, _, _ = select.select([self.from_browser], [], [], left)
            if ready:
                chunk = os.read(self.from_browser, 1 << 20)
                if not chunk:
                    raise BrowserError(f"chromium closed the pipe waiting for {waiting_for} (see {self.stderr_path})")
                self.buffer += chunk
        *whole, self.buffer = self.buffer.split(b"\0")
        messages = [json.loads(text) for text in whole]
        for message in messages:
            if "method" in message:
                session = message.get("sessionId")
                page = self.pages.get(session)
                if page is not None:
                    page.record_event(message["method"], message.get("params", {}))
                self.events.append((message["method"], message.get("params", {}), session))
        return messages

    def wait_event(self, method, session=None):
        """Waits for (and consumes) event `method`, from `session` if given."""
        deadline = time.monotonic() + self.timeout
        while True:
            for i, (name, params, where) in enumerate(self.events):
                if name == method and (session is None or where == session):
                    del self.events[i]
                    return params
            self.read_messages(deadline, method)

    def drain_events(self):
        """Reads what has arrived without waiting, then forgets queued events (their errors stay recorded)."""
        while True:
            ready, _, _ = select.select([self.from_browser], [], [], 0)
            if not ready:
                break
            chunk = os.read(self.from_browser, 1 << 20)
            if not chunk:
                break
            self.buffer += chunk
            if b"\0" in self.buffer:
                self.read_messages(time.monotonic() + self.timeout, "events")
        self.events.clear()

    # 3. Pages.
    def new_page(self):
        """A new blank tab with page, runtime and log events on."""
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        page = Page(self, session)
        self.pages[session] = page
        for domain in ("Page.enable", "Runtime.enable", "Log.enable"):
            page.send(domain)
        return page

    def open(self, path, scripts=True, media="", reduced_motion=None):
        """A new tab showing the file `path` (or a URL), with scripts on or off; waits for its load event."""
        page = self.new_page()
        if not scripts:
            page.disable_scripts()
        if media or reduced_motion:
            page.emulate_media(media, reduced_motion)
        text = str(path)
        url = text if "://" in text or text.startswith("about:") else pathlib.Path(text).resolve().as_uri()
        page.navigate(url)
        return page
