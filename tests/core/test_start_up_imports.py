"""What the fast commands import: the listed modules, and no more (issue 34, part 5).

A command's start is mostly its imports (`benchmarks/start_up.py` measures it against
`python -c "import numpy"`), so each fast command line is run here with `python -X
importtime`, whose report names every module imported, and the modules are compared with
the lists below: kinematika's own, by name; the project's heavy libraries (none for an
instant or a sweep, scipy for a motion in time); and how many other modules (the standard
library's, and what the allowed libraries bring) may be loaded. Counts and names, never
times: a test never depends on speed.

A module added to a command's path on purpose is added to its list here, with the reason
in the commit; one that arrived by accident (an import at the top of a module that only a
view needs, a library imported where a function would do) is moved into the function that
needs it.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

# what `solve --json` imports of kinematika (and `QUESTIONS` when the model asks a question whose
# answer is not in the tables); the other commands list what they add
SOLVE = {
    "kinematika", "kinematika.algebra", "kinematika.algebra.backend", "kinematika.algebra.vectors",
    "kinematika.api", "kinematika.budget", "kinematika.cli", "kinematika.cli.fast", "kinematika.cli.fast_options",
    "kinematika.cli.run", "kinematika.cli.shared", "kinematika.commands", "kinematika.engine",
    "kinematika.engine.blocks", "kinematika.engine.dense", "kinematika.engine.drivers", "kinematika.engine.idle", "kinematika.engine.instant",
    "kinematika.engine.joints", "kinematika.engine.levels", "kinematika.engine.linear", "kinematika.engine.linsolve",
    "kinematika.engine.mobility", "kinematika.engine.motion", "kinematika.engine.positions",
    "kinematika.engine.ranges", "kinematika.engine.system", "kinematika.engine.terms", "kinematika.errors",
    "kinematika.errors.said", "kinematika.expressions", "kinematika.joints", "kinematika.joints.base",
    "kinematika.joints.capabilities",       # the capabilities' words, typed (issue 34, part 2)
    "kinematika.joints.derivatives", "kinematika.joints.positions",
    "kinematika.languages", "kinematika.limits", "kinematika.memo", "kinematika.model", "kinematika.model.build",
    "kinematika.model.builder", "kinematika.model.figure_hints", "kinematika.model.point_order",
    "kinematika.model.files", "kinematika.model.model", "kinematika.model.overrides", "kinematika.model.plain",
    "kinematika.model.point_ref",
    "kinematika.model.shape", "kinematika.model.source", "kinematika.model.wording", "kinematika.report", "kinematika.report.json_answer",
    "kinematika.report.json_text", "kinematika.report.values", "kinematika.registry", "kinematika.shapes", "kinematika.solution",
    "kinematika.sweep", "kinematika.sweep.posing", "kinematika.text",
    # the question kinds' registry: an answer's tables read what each asked kind is (issue 34, part 3)
    "kinematika.questions", "kinematika.questions.base", "kinematika.questions.motion",
}
# a model with `parameters:` (every example here but spherical_four_bar.yaml), a model that asks
# (its `ask`, or none written: every body and point by default); not the 1000-body chain, whose
# `ask` is empty and which has no parameters (`test_a_model_without_parameters_or_questions...`)
PARAMETERS = {"kinematika.model.parameter"}
ASKED = {"kinematika.model.question"}
QUESTIONS = {"kinematika.questions", "kinematika.questions.axis", "kinematika.questions.contact",
             "kinematika.questions.curvature", "kinematika.questions.decompose", "kinematika.questions.icr",
             "kinematika.questions.inflection", "kinematika.questions.motion", "kinematika.questions.pole"}
# not imported by a model without a constructed point, a body with a shape, or a drawing (docs/architecture.md:
# the imports left inside functions): `model.constructions`, `model.body_shapes`, `shapes`, `joints.symbols`
CONSTRUCTED = {"kinematika.model.constructions"}
# a direction given by two points (spherical_four_bar.yaml's axes, inverted_slider_crank.yaml's slide, the
# tractor-trailer's wheels); four_bar.yaml and the 1000-body chain have none
POINT_PAIRS = {"kinematika.point_pair"}        # four_bar.yaml's coupler pin: two circles
# a model's `sweep:` or `simulate:` section, or a moved model's turns (four_bar.yaml and spherical_four_bar.yaml
# have a `sweep:`, tractor_trailer_turning.yaml a `simulate:`); inverted_slider_crank.yaml, like the 1000-body
# chain, has neither, and its solve must not load the module
SECTIONS = {"kinematika.model.motion_sections"}
SWEEP_RUN = {"kinematika.memory", "kinematika.sweep.coincident", "kinematika.sweep.plan", "kinematika.sweep.result",
             "kinematika.sweep.run",
             "kinematika.sweep.joint_rates"}       # a 3D ω along a revolute's axis is its rate (issue 31)
SIMULATE = {"kinematika.joints.holonomic", "kinematika.simulate", "kinematika.simulate.clock", "kinematika.simulate.holonomic",
            "kinematika.simulate.result", "kinematika.simulate.run", "kinematika.simulate.state",
            "kinematika.simulate.timed", "kinematika.sweep.poses", "kinematika.sweep.progress"}
HEAVY = {"scipy", "sympy", "pydantic", "typer", "click", "rich", "matplotlib", "pyarrow", "starlette", "uvicorn",
         "fluent", "babel", "dask", "distributed", "ezdxf", "playwright", "PIL", "pandas"}

# command line, kinematika's modules, heavy libraries allowed, most other modules
COMMANDS = {
    "solve": (["solve", "{ex}/four_bar.yaml", "--json"], SOLVE | PARAMETERS | ASKED | QUESTIONS | CONSTRUCTED | SECTIONS, set(), 145),
    "solve-no-questions": (["solve", "{ex}/spherical_four_bar.yaml", "--json"], SOLVE | ASKED | SECTIONS | POINT_PAIRS, set(), 145),
    "solve-no-sections": (["solve", "{ex}/inverted_slider_crank.yaml", "--json"],
                           SOLVE | PARAMETERS | ASKED | CONSTRUCTED | POINT_PAIRS, set(), 145),
    "centres": (["centres", "{ex}/four_bar.yaml", "--json"],
                SOLVE | PARAMETERS | ASKED | QUESTIONS | CONSTRUCTED | SECTIONS | {"kinematika.questions.centres",
                                                              "kinematika.report.centres_table"},
                set(), 145),
    "sweep": (["sweep", "{ex}/four_bar.yaml", "--steps", "8", "--json"],
              SOLVE | PARAMETERS | ASKED | SWEEP_RUN | CONSTRUCTED | SECTIONS | {"kinematika.structure", "kinematika.structure.assur",
                                                 "kinematika.sweep.closed_form"},
              set(), 145),
    "simulate": (["simulate", "{ex}/tractor_trailer_turning.yaml", "--time", "1", "--steps", "2", "--json"],
                 SOLVE | PARAMETERS | ASKED | SWEEP_RUN | SIMULATE | SECTIONS | POINT_PAIRS, {"scipy"}, 245),
}


def imported(args: list[str]) -> list[str]:
    """Every module the command line imports, as `python -X importtime` reports them."""
    run = subprocess.run([sys.executable, "-X", "importtime", "-m", "kinematika", *args],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stdout + run.stderr
    lines = [line for line in run.stderr.splitlines() if line.startswith("import time:")]
    return [line.split("|")[2].strip() for line in lines if "self [us]" not in line]


@pytest.mark.parametrize("command", list(COMMANDS))
def test_a_fast_command_imports_only_its_listed_modules(command):
    args, listed, heavy, most_others = COMMANDS[command]
    modules = imported([a.format(ex=EXAMPLES) for a in args])
    ours = {m for m in modules if m.split(".")[0] == "kinematika"}
    assert not ours - listed, f"`kinematika {command}` imports modules not on its list: {sorted(ours - listed)}"
    libraries = {m.split(".")[0] for m in modules} & HEAVY
    assert libraries <= heavy, f"`kinematika {command}` imports {sorted(libraries - heavy)}"
    others = [m for m in modules if m.split(".")[0] not in {"kinematika", "numpy", *heavy}]
    assert len(others) <= most_others, (f"`kinematika {command}` imports {len(others)} other modules "
                                        f"(at most {most_others})")
    assert len(ours) >= len(listed) // 2          # the report was read (the lists are not vacuous)


PLAIN_CHAIN = """\
points: {O: [0, 0], A: [0, 1], B: [2, 1], C: [2, 0]}
bodies: {ground: [O, C], crank: [O, A], coupler: [A, B], rocker: [B, C]}
joints:
- {type: revolute, bodies: [ground, crank], at: O}
- {type: revolute, bodies: [crank, coupler], at: A}
- {type: revolute, bodies: [coupler, rocker], at: B}
- {type: revolute, bodies: [rocker, ground], at: C}
drivers:
- {omega: crank, value: 10.0, alpha: 0.0}
ask: []
"""


def test_a_model_without_parameters_or_questions_defines_neither(tmp_path):
    """A model like the 1000-body chain (numbers only, `ask: []`, pins only) makes no `Parameter`,
    no `Question` and no `PointPair`, so its solve does not import (define) them, nor a joint's
    `Holonomic`."""
    model = tmp_path / "plain_chain.yaml"
    model.write_text(PLAIN_CHAIN, encoding="utf-8")
    modules = set(imported(["solve", str(model), "--json"]))
    assert "kinematika.model.build" in modules          # the report was read
    assert not modules & (PARAMETERS | ASKED | POINT_PAIRS | {"kinematika.joints.holonomic"})


def test_a_large_chain_solved_sparse_defines_no_dense_analysis(tmp_path):
    """A chain of 101 bodies (303 unknowns, above `linsolve.LARGE`) is solved by its sparse LU:
    its solve does not import `engine.dense` (the dense `Analysis`); the small four-bar, whose
    system is dense, does."""
    import json

    sys.path.insert(0, str(EXAMPLES.parent / "benchmarks"))
    from chain import four_bar_chain

    large, small = tmp_path / "chain101.json", tmp_path / "plain_chain.yaml"
    large.write_text(json.dumps(four_bar_chain(101)), encoding="utf-8")
    small.write_text(PLAIN_CHAIN, encoding="utf-8")
    modules = set(imported(["solve", str(large), "--json"]))
    assert "kinematika.engine.linsolve" in modules          # the report was read
    assert "kinematika.engine.dense" not in modules
    assert "kinematika.engine.dense" in set(imported(["solve", str(small), "--json"]))
