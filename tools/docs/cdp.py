"""A headless Chromium driven through the DevTools protocol (Debian's `chromium` and
`python3-websocket`; no npm, no PyPI): start it, open a page, and collect what a reader's browser
would complain about while it loads.

Chromium runs with a fresh profile in a temporary directory and picks its own debugging port,
which it writes to DevToolsActivePort there; the page's target is then driven over one
websocket. Events that arrive while waiting for a command's answer are kept in order."""
import base64
import json
import os
import shutil
import subprocess
import tempfile
import time
import urllib.request

import websocket

CHROMIUM_NAMES = ("chromium", "chromium-browser", "google-chrome")
START_TIMEOUT_S = 30
LOAD_TIMEOUT_S = 60


class BrowserError(RuntimeError):
    pass


def find_chromium():
    for name in CHROMIUM_NAMES:
        path = shutil.which(name)
        if path:
            return path
    return None


class Chromium:
    """One headless browser with one page; use as a context manager."""

    def __init__(self, exe, width=1280, height=900):
        self.exe, self.size = exe, (width, height)
        self.events, self.next_id = [], 0

    def __enter__(self):
        self.profile = tempfile.mkdtemp(prefix="springblock-chromium-")
        # --disable-dev-shm-usage: containers often give /dev/shm too little room for a renderer.
        args = [self.exe, "--headless=new", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
                "--no-default-browser-check", "--remote-debugging-port=0", "--remote-allow-origins=*", f"--user-data-dir={self.profile}",
                f"--window-size={self.size[0]},{self.size[1]}", "--hide-scrollbars", "about:blank"]
        if os.geteuid() == 0:  # Chromium refuses to run as root inside its sandbox
            args.insert(1, "--no-sandbox")
        self.log = open(os.path.join(self.profile, "chromium.log"), "w")
        self.proc = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT)
        try:
            self.ws = websocket.create_connection(self._page_socket(), timeout=LOAD_TIMEOUT_S)
        except BaseException:
            self.__exit__(None, None, None)
            raise
        return self

    def __exit__(self, *exc):
        if getattr(self, "ws", None):
            self.ws.close()
        self.proc.terminate()
        try:
            self.proc.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
        self.log.close()
        shutil.rmtree(self.profile, ignore_errors=True)

    def _port(self):
        """The debugging port Chromium chose, once it has written it (None before)."""
        try:
            with open(os.path.join(self.profile, "DevToolsActivePort")) as f:
                first = f.read().split()
        except FileNotFoundError:
            return None
        return int(first[0]) if first else None

    def _page_socket(self):
        deadline = time.monotonic() + START_TIMEOUT_S
        while self._port() is None:
            if self.proc.poll() is not None or time.monotonic() > deadline:
                with open(os.path.join(self.profile, "chromium.log")) as f:
                    tail = f.read()[-2000:]
                raise BrowserError(f"chromium did not start (exit {self.proc.poll()}):\n{tail}")
            time.sleep(0.1)
        port = self._port()
        while True:
            with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=10) as r:
                pages = [t for t in json.load(r) if t.get("type") == "page"]
            if pages:
                return pages[0]["webSocketDebuggerUrl"]
            if time.monotonic() > deadline:
                raise BrowserError("chromium started with no page to drive")
            time.sleep(0.1)

    def call(self, method, **params):
        """Send one command and return its result; events received meanwhile are kept."""
        self.next_id += 1
        my_id = self.next_id
        self.ws.send(json.dumps({"id": my_id, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == my_id:
                if "error" in msg:
                    raise BrowserError(f"{method}: {msg['error']}")
                return msg.get("result", {})
            if "method" in msg:
                self.events.append(msg)

    def wait_for(self, event, timeout=LOAD_TIMEOUT_S):
        """Read events until `event` arrives (kept like the others)."""
        deadline = time.monotonic() + timeout
        while not any(e["method"] == event for e in self.events):
            if time.monotonic() > deadline:
                raise BrowserError(f"no {event} within {timeout} s")
            self.ws.settimeout(max(0.1, deadline - time.monotonic()))
            msg = json.loads(self.ws.recv())
            if "method" in msg:
                self.events.append(msg)

    def settle(self, seconds):
        """Keep reading events for a while (late console messages, lazy images)."""
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            self.ws.settimeout(max(0.05, deadline - time.monotonic()))
            try:
                msg = json.loads(self.ws.recv())
            except websocket.WebSocketTimeoutException:
                break
            if "method" in msg:
                self.events.append(msg)

    def open(self, url):
        for domain in ("Page", "Runtime", "Log", "Network"):
            self.call(f"{domain}.enable")
        self.call("Page.navigate", url=url)
        self.wait_for("Page.loadEventFired")
        self.settle(0.5)

    def evaluate(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in r:
            raise BrowserError(f"evaluate: {r['exceptionDetails'].get('text')}")
        return r["result"].get("value")

    def screenshot(self, path):
        data = base64.b64decode(self.call("Page.captureScreenshot", format="png")["data"])
        tmp = path + ".tmp"
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
