"""One lock for every use of matplotlib in the process.

matplotlib is not thread-safe: its mathtext parser keeps a stack of states that two threads
parsing at once corrupt ("exception raised in parse action"), and text extents and canvases
share caches. The page's server answers requests in threads, Jupyter may draw while a
server runs, and an abandoned request's thread may still be drawing when the next one
starts; so everything that lays out or writes a figure takes `MATPLOTLIB` (re-entrant: a
command that draws several figures holds it once), and solving stays parallel.
"""
from __future__ import annotations

import threading

MATPLOTLIB = threading.RLock()
