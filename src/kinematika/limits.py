"""Every limit kinematika puts on untrusted input, decided once, here.

A model file is untrusted input (files pasted from the web, handed in by students, sent by
a browser): whatever it holds, the tool answers or says what is wrong in one line, quickly
and in bounded memory. Each limit below is far above anything a real mechanism needs (the
README and docs/model-format.md list them); what goes beyond is refused with an error that
names the limit, never a hang, a crash or a silently different model.
"""
from __future__ import annotations

import os

# reading a model --------------------------------------------------------------------------
FILE_BYTES = 5_000_000       # a model is a few kilobytes; read at most this, whatever the file claims
READ_SECONDS = 5.0           # a pipe or a terminal that gives no end of file within this is refused
NESTING = 64                 # levels of lists and mappings (a model uses 4 to 6)
ALIAS_NODES = 100_000        # values that YAML aliases may add to a file (a "billion laughs" adds 10⁹)
NAME_CHARS = 200             # a name of a point, body, joint or parameter; a model's title is shown cut to it

# expressions ------------------------------------------------------------------------------
EXPRESSION_CHARS = 2000      # characters of one expression
EXPRESSION_DEPTH = 60        # nesting of operations and calls in one expression
EXPONENT = 1000              # |y| in x**y when y is a number
EXACT_DIGITS = 60            # decimal digits of an exact number (numerator or denominator) in
                             # symbolic work: 1e-200 written in a symbolic model is refused
DEGREE = 60                  # degree of a formula in the symbols (r**1000, (w + 1)**100**2)

# the size of a mechanism ------------------------------------------------------------------
SCALE = 1e50                 # lengths and rates (ω, v/length, √(a/length)) between 1/SCALE and
                             # SCALE in the model's units: their squares and cubes stay floats

# sweeps -----------------------------------------------------------------------------------
SWEEP_STEPS = 10_000_000     # increments of one sweep
SWEEP_VALUES = 32_000_000    # rows × numbers per row held at once: 480 000 rows of a four-bar (under 1 GB on every path)
SWEEP_LIMITS = 10_000        # limit positions one sweep passes through (a four-bar's cycle has 2;
                             # the motion stops when it is back at the drawing)
CONTINUATION_STEPS = 2_000   # arclength steps between two rows of a sweep on Newton's path (a limit
                             # position of the examples takes under 50)
SWEEP_TRAVEL = 1_000_000     # a sweep's or a move's travel (`by`, a `move` amount): at most this many turns of a
                             # revolute, or times the mechanism's size along a prismatic (angles stay exact to 1e-9 rad)

# motion in time (`kinematika simulate`) ----------------------------------------------------
SIMULATE_STEPS = 1_000_000   # rows of one simulation (each is solved by the engine: about a millisecond)
SIMULATE_EVALUATIONS = 200_000   # velocity solutions the ODE solver may ask for in one simulation (a smooth
                             # motion takes a few per second of motion: the tractor and trailer over
                             # 60 s, a few hundred); beyond, the motion is too stiff or too nearly
                             # singular to follow, and the rows computed so far are kept

# symbolic work ----------------------------------------------------------------------------
EXACT_WORK = 1_500_000       # steps of exact algebra a command may take (terms formed, products of
                             # terms): a count, so whether a model is answered is the model's own
                             # matter (the most any shipped model needs: 440 000, Jansen's leg
                             # explained in its crank angle, 13 s of CPU time)
SYMBOLIC_SECONDS = 180.0     # CPU time of exact formulas: a safety net only, far above what the
                             # counts admit (about 45 s here); KINEMATIKA_SYMBOLIC_SECONDS overrides
POINT_OPS = 2000             # operations of a constructed point's exact coordinate, in named
                             # coordinates (engine.positions.NAME_OPS): a four-bar's coupler pin
                             # has 84; Jansen's leg in its 15 lengths, under 400 in its names

PRINT_SECONDS = 600.0        # Chromium's wait for a sheet to load and print (exercise sheets, PDF and
                             # PNG), wall clock: a safety net only (Playwright's own is 30 s, which a
                             # busy machine can meet)

# the page's server (`kinematika app`) -----------------------------------------------------
REQUEST_BYTES = FILE_BYTES   # a request's body (a model's text and a few options); 413 beyond
REQUEST_SECONDS = 600.0      # a request's computation, wall clock: a safety net only (503 beyond); the
                             # work is bounded by counts (EXACT_WORK, PAGE_SWEEP_STEPS), so what is
                             # answered does not depend on the server's load
SERVER_THREADS = 4           # computations at once in a server process, off its event loop
WAITING = 256                # requests waiting for a thread before the server answers 503 (busy)
PAGE_SWEEP_STEPS = 20_000    # increments of a sweep asked through the API
ANSWER_CACHE_BYTES = 64_000_000   # answers kept for identical requests (a class opening one example)

# messages ---------------------------------------------------------------------------------
MESSAGE_CHARS = 300          # an error message is one line, cut beyond this (with …): a translation runs longer
WHERE_CHARS = 120            # an error's place (a file path, `joints[2] (j3)`) likewise


def symbolic_seconds() -> float:
    """The time budget of symbolic work: `SYMBOLIC_SECONDS`, or the environment's override."""
    raw = os.environ.get("KINEMATIKA_SYMBOLIC_SECONDS", "")
    try:
        value = float(raw)
    except ValueError:
        return SYMBOLIC_SECONDS
    return value if value > 0 else SYMBOLIC_SECONDS
