"""The libraries the server's computations import, imported once, alone, before the first.

The server computes several requests at once, in threads (`server.create_app`). A library
imported for the first time by two threads together can be seen half made by one of them:
sympy's modules import one another, and a thread asking for `sympy.printing` while another
is still importing sympy gets "cannot import name 'sstr' from partially initialized module"
— an internal error (500) for a request that is right, on a page opened at a busy moment
(the page sends its first four requests together). Python's import lock orders the imports
of one module, not a package's circular web of them. So the server's first request imports
them all before any request is read or computed (`warmed`); later requests find them made.
The answers never depend on it: only whether a cold server could fail.
"""
from __future__ import annotations

import importlib
import threading

MODULES = (
    # the exact algebra and what it reaches lazily (sympify's parser, printing, polynomials)
    "sympy", "sympy.parsing.sympy_parser", "sympy.printing", "sympy.polys", "sympy.simplify",
    "sympy.combinatorics", "sympy.sets.setexpr", "sympy.tensor.tensor", "mpmath",
    # numbers, motion in time, fitting
    "numpy", "scipy.optimize", "scipy.integrate", "scipy.interpolate", "scipy.sparse", "scipy.spatial",
    # figures and their files
    "matplotlib", "matplotlib.figure", "matplotlib.backends.backend_agg", "matplotlib.backends.backend_svg",
    "PIL.Image",
    # the files and the words
    "yaml", "ruamel.yaml", "tomlkit", "orjson", "pydantic", "fluent.runtime",
    # this package's computations (no import cycle among them: import-linter's contract)
    "kinematika.commands", "kinematika.model.schema", "kinematika.draw.build", "kinematika.explain",
    "kinematika.sweep.run", "kinematika.simulate.run", "kinematika.cams.program", "kinematika.web.build",
)

_lock = threading.Lock()
_done = False


def warmed() -> None:
    """Import `MODULES`, once per process; a caller arriving meanwhile waits until it is done."""
    global _done
    if _done:
        return
    with _lock:
        if not _done:
            for name in MODULES:
                importlib.import_module(name)
            _done = True
