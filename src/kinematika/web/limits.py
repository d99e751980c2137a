"""The bounds of the page's server, in one place.

A request larger than `MAX_BODY` is refused (413) before it is read; at most `WORKERS`
requests compute at once, off the event loop, and at most `MAX_WAITING` wait for a turn
(more are answered 503 at once); a computation that takes longer than `MAX_SECONDS`
answers 503 (the work itself is bounded by the engine's own limits). The answers to the
last identical requests are kept, up to `CACHE_BYTES`.
"""
from __future__ import annotations

MAX_BODY = 1_000_000        # bytes of a request body: a model is a few kilobytes
MAX_SECONDS = 30.0          # a request's computation
WORKERS = 4                 # computations at once (threads of a bounded pool)
MAX_WAITING = 256           # requests waiting for a worker before the server says it is busy
MAX_STEPS = 20_000          # rows of a sweep asked through the API
CACHE_BYTES = 64_000_000    # answers kept for identical requests (a class opening one example)
