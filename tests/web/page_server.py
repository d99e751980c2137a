"""The page's server on a free port of 127.0.0.1, in a thread, for the browser tests."""
from __future__ import annotations

import socket
import sys
import threading
import time

import uvicorn

from kinematika.cli.page import KEEP_ALIVE
from kinematika.web.server import Start, bundled_examples, create_app
from tests.conftest import HANG_CPU_SECONDS, HANG_SECONDS

POLL_MS = 2000      # how long one look at the page waits before the server's work is counted


class PageServer:
    """uvicorn serving `create_app(start)` until `stop()`; `url` is its address."""

    def __init__(self, start: Start) -> None:
        start.examples = start.examples or bundled_examples()
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(64)
        self.url = f"http://127.0.0.1:{self.sock.getsockname()[1]}/"
        # the served page's keep-alive (`kinematika page`'s), not uvicorn's 5 s: on a loaded
        # machine a test's pause between two requests passes 5 s, and a POST sent on a
        # connection the server is closing failed (a page with no figure, once in a run)
        config = uvicorn.Config(create_app(start, hosts=["127.0.0.1", "localhost"]),
                                log_level="warning", access_log=False, timeout_keep_alive=KEEP_ALIVE)
        self.server = uvicorn.Server(config)
        self.thread = threading.Thread(target=self.server.run, kwargs={"sockets": [self.sock]},
                                       daemon=True)
        self.thread.start()
        deadline = time.monotonic() + HANG_SECONDS
        while not self.server.started:
            if time.monotonic() > deadline:
                raise RuntimeError("the page's server did not start")
            time.sleep(0.02)

    def computing(self) -> bool:
        """Whether a worker thread is computing an answer now."""
        return any(_computing(t) for t in threading.enumerate())

    def wait(self, page, condition: str, arg=None) -> None:
        """Wait until the page's JavaScript `condition` holds, whatever the machine's load.
        While the server computes (in this process), the wait is bounded by this process's
        CPU time (`HANG_CPU_SECONDS` of it: the work itself, which load does not stretch);
        while it is idle — the browser's own work, or a page waiting for nothing — by
        `HANG_SECONDS` of wall time, far above what a page takes to paint."""
        from playwright.sync_api import TimeoutError as PlaywrightTimeout

        cpu, idle = time.process_time(), 0.0
        while True:
            began, busy = time.monotonic(), self.computing()
            try:
                page.wait_for_function(condition, arg=arg, timeout=POLL_MS)
                return
            except PlaywrightTimeout:
                pass
            if busy or self.computing():
                if time.process_time() - cpu > HANG_CPU_SECONDS:
                    raise AssertionError(f"the server computed for {HANG_CPU_SECONDS:.0f} s of CPU time "
                                         f"and the page still waits for: {condition}")
            else:
                idle += time.monotonic() - began
                if idle > HANG_SECONDS:
                    raise AssertionError(f"the page waited {HANG_SECONDS:.0f} s with the server idle for: {condition}; "
                                         f"the page then: {_seen(page)}")

    def stop(self) -> None:
        """Stop serving, and wait for the computations of requests the browser abandoned
        (they go on in the server's worker threads, drawing with matplotlib): the tests that
        follow in this process must not share matplotlib with them."""
        self.server.should_exit = True
        self.thread.join(10)
        self.sock.close()
        self.idle("since it stopped")

    def idle(self, since: str = "") -> None:
        """Wait until no worker thread computes (requests a page left behind included), for
        as long as it takes a loaded machine: bounded by `HANG_CPU_SECONDS` of this process's
        CPU time, the work itself."""
        cpu = time.process_time()
        while self.computing():
            if time.process_time() - cpu > HANG_CPU_SECONDS:
                raise RuntimeError(f"the page's server still computes after {HANG_CPU_SECONDS:.0f} s of CPU time "
                                   f"{since}".strip())
            time.sleep(0.05)


def _seen(page) -> str:
    """What the page shows of its state, for a wait that failed to say why: with the last
    calls to the API and their HTTP status (0: failed before any answer)."""
    return page.evaluate("""() => { const s = window.kinematika && window.kinematika.state;
        const text = (id) => { const e = document.getElementById(id); return e ? (e.hidden ? "(hidden)" : e.textContent) : null; };
        return JSON.stringify({gen: s && s.gen, solution: !!(s && s.solution), sweep: !!(s && s.sweep),
            sweepError: s && s.sweepError, input: s && s.input, busy: text("busy"), error: text("error"),
            example: document.getElementById("example").value, notes: text("notes"), missing: text("missing"),
            calls: performance.getEntriesByType("resource").filter((r) => r.name.includes("/api/")).slice(-8)
                .map((r) => `${r.name.split("/api/")[1]} ${r.responseStatus ?? "?"}`)}); }""")


def _computing(thread: threading.Thread) -> bool:
    """A worker thread of AnyIO that is running a computation. An idle worker waits for its
    next task in `queue.get`: those of another event loop of this process (the API tests'
    TestClient, alive for the whole session) stay idle and are not waited for."""
    if not (thread.name.startswith("AnyIO worker") and thread.is_alive()):
        return False
    frame = sys._current_frames().get(thread.ident)
    while frame is not None:
        if frame.f_code.co_name == "get" and frame.f_code.co_filename.endswith("queue.py"):
            return False
        frame = frame.f_back
    return True
