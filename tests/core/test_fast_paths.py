"""The fast paths of a command give what the general ones give: the plain check of a model
file against pydantic's, and the command line's fast path against typer's. Both fast paths
are generated from the general ones (`model.generate_shape`, `cli.generate_options`): the
tests regenerate them and compare, then check that they mean the same."""
from __future__ import annotations

import copy
import inspect
import json
import subprocess
import sys
from pathlib import Path

from typing import Annotated, Literal, Optional, Union

import pytest
from hypothesis import given, strategies as st
from pydantic import BaseModel, Field, StrictBool, StrictFloat, StrictInt, ValidationError

from kinematika.cams.spec import FollowerSpec

from kinematika.cli import fast, generate_options
from kinematika.model import generate_shape, schema, shape
from kinematika.model.files import read_tree

from fuzz.forks import run_forked
from tests.conftest import KINDS, sampled

from .models import four_bar

EXAMPLES = Path(__file__).parents[2] / "examples"
EXAMPLE_FILES = sorted(EXAMPLES.glob("*.yaml"))


def plain(x):
    """A checked spec as plain data, with each record's class name."""
    if isinstance(x, BaseModel):
        return {"class": type(x).__name__, **{k: plain(getattr(x, k)) for k in type(x).model_fields}}
    if isinstance(x, shape.Record):
        return {"class": type(x).__name__, **{k: plain(getattr(x, k)) for k in x.FIELDS}}
    if isinstance(x, dict):
        return {k: plain(v) for k, v in x.items()}
    if isinstance(x, list):
        return [plain(v) for v in x]
    return (type(x).__name__, x)


def pydantic_spec(tree):
    try:
        return schema.ModelSpec.model_validate(tree)
    except ValidationError:
        return None


# the model file's plain check -----------------------------------------------------------
def test_the_plain_check_is_generated_from_the_schema():
    assert generate_shape.source() == generate_shape.TARGET.read_text(encoding="utf-8"), \
        f"model/shape.py is out of date: run {generate_shape.COMMAND}"


def _has_a_cam(tree):
    return any(isinstance(body, dict) and "cam" in body for body in tree["bodies"].values())


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=[p.stem for p in EXAMPLE_FILES])
def test_the_plain_check_reads_every_example_as_pydantic_does(path):
    """Every example but those with a cam's design (checked by `cams.spec`, whose design is
    built with pydantic anyway) is read by the plain check, as pydantic reads it."""
    tree = read_tree(path)
    spec = shape.spec_of(tree)
    if _has_a_cam(tree):
        assert spec is None
        assert schema.ModelSpec.model_validate(tree)
        return
    assert spec is not None, "an example taken by pydantic, not by the plain check"
    assert plain(spec) == plain(schema.ModelSpec.model_validate(tree))


def test_the_records_have_schemas_fields_and_defaults():
    for record in shape.RECORDS:
        model = getattr(schema, record.__name__)
        fields = model.model_fields
        assert tuple(fields) == record.FIELDS, record.__name__
        for name, field in fields.items():
            mine = record.DEFAULTS[name]
            if field.is_required():
                assert mine is shape.REQUIRED, (record.__name__, name)
            else:
                theirs = field.get_default(call_default_factory=True)
                assert (mine() if callable(mine) else mine) == theirs, (record.__name__, name)
    assert shape.JOINT_KEYS == schema.JOINT_KEYS
    assert {r.__name__ for r in shape.RECORDS} == {"ModelSpec", "ParameterSpec", "PolarSpec", "FrameSpec",
                                                     "CirclesSpec", "CircleLineSpec", "LineSpec", "LinesSpec",
                                                     "BodySpec", "CircleSpec", "DiscSpec", "PlaneSpec", "CurveSpec",
                                                     "JointSpec", "OmegaDriver", "JointDriver", "VelocityDriver",
                                                     "QuestionSpec", "SweepSpec", "SimulateSpec",
                                                     "ExerciseSpec", "DimensionSpec", "LanguageNames"}  # all but the cam's design


def test_exact_lists_and_mappings_checked_at_once_refuse_what_one_by_one_refused():
    """`listed` and `mapping` of exact checks test the values' types at once: a bool among
    numbers, a subclass, a key not text, a wrong length are still refused; what is accepted
    is a copy with the same values; `optional` of an exact check takes None too."""
    from kinematika.model.plain import Refused, exact, listed, mapping, optional

    class Text(str):
        pass

    numbers, pair, names = listed(exact(int, float)), listed(exact(str), 2, 2), mapping(exact(str))
    given = [1, 2.5]
    assert numbers(given) == [1, 2.5] and numbers(given) is not given and numbers([]) == []
    assert pair(["a", "b"]) == ["a", "b"]
    assert names({"a": "x"}) == {"a": "x"}
    assert optional(exact(str))(None) is None and optional(exact(str))("a") == "a"
    for check, value in [(numbers, [1, True]), (numbers, (1, 2)), (pair, ["a"]), (pair, ["a", Text("b")]),
                         (names, {1: "x"}), (names, {"a": 1}), (optional(exact(str)), 1)]:
        with pytest.raises(Refused):
            check(value)


def test_a_number_written_twice_is_one_expression_with_its_own_text():
    """The build makes one `Expr` per number written (`_Builder.expr`), keyed by its text: 1
    and 1.0, 0.0 and -0.0 stay apart."""
    from kinematika.model.build import build_model

    tree = four_bar()
    tree["points"] = {"O2": [0.0, 0.0], "A": [-0.0, 1.0], "B": [1, 1.0], "O4": [4.0, 0]}
    model = build_model(tree)
    assert [[e.text for e in model.points[p]] for p in ("O2", "A", "B", "O4")] == \
        [["0.0", "0.0"], ["-0.0", "1.0"], ["1", "1.0"], ["4.0", "0"]]
    assert model.points["O2"][0] is model.points["O2"][1] and model.points["A"][0] is not model.points["O2"][0]
    assert model.points["A"][1] is model.points["B"][1]


@pytest.mark.parametrize("annotation, code", [
    (Union[StrictInt, StrictFloat, str], "value"),                          # schema's named type
    (Union[StrictInt, StrictBool], "exact(int, bool)"),
    (Optional[Annotated[list[str], Field(min_length=2, max_length=3)]], "optional(listed(exact(str), 2, 3))"),
    (Literal["a", 1], "one_of('a', 1)"),
    (Annotated[StrictInt, Field(gt=0)], "pydantic_decides"),                # a bound plain tests do not check
    (Union[list[str], list[StrictInt]], "pydantic_decides"),                # members taking the same values
    (dict[int, str], "pydantic_decides"),
    (FollowerSpec, "pydantic_decides"),                                     # another file format's class
])
def test_the_generator_writes_only_what_plain_tests_check_as_pydantic(annotation, code):
    assert generate_shape._Writer().annotation(annotation, []).code == code


ODD_VALUES = [True, False, None, 0, 2, 3, 1.5, float("inf"), "", "x", "revolute", [], {}, [1, "a"],
              ["A", "B"], ["A", "B", "C"], {"value": 1}, {"points": ["A"]}, (1, 2), 10 ** 30]


def _leaves(tree, path=()):
    yield path
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from _leaves(v, path + (k,))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _leaves(v, path + (i,))


def _set(tree, path, value):
    node = tree
    for part in path[:-1]:
        node = node[part]
    node[path[-1]] = value


def _base_trees():
    return [four_bar(), four_bar(ask=[{"velocity": "B", "relative_to": "crank"}, {"icr": "coupler"}],
                                 sweep={"joint": "j1", "by": 90, "steps": 4}),
            read_tree(EXAMPLES / "fan_absolute.yaml"), read_tree(EXAMPLES / "planetary_gears.yaml"),
            read_tree(EXAMPLES / "coin_rolling.yaml"),
            read_tree(EXAMPLES / "quick_return.yaml"), read_tree(EXAMPLES / "jansen_leg.yaml"),  # constructions
            _with_a_curve()]


def _with_a_curve():
    tree = four_bar()
    tree["bodies"]["ground"] = {"points": tree["bodies"]["ground"], "curve": {"through": [[0, 0], [1, 1], "O4"], "closed": False}}
    return tree


@given(st.data())
def test_a_changed_tree_is_accepted_only_as_pydantic_accepts_it(data):
    tree = copy.deepcopy(data.draw(st.sampled_from(_base_trees())))
    for _ in range(data.draw(st.integers(1, 3))):
        paths = [p for p in _leaves(tree) if p]
        path = data.draw(st.sampled_from(paths))
        action = data.draw(st.sampled_from(["replace", "add", "delete"]))
        if action == "replace":
            _set(tree, path, copy.deepcopy(data.draw(st.sampled_from(ODD_VALUES))))
        else:
            parent = tree
            for part in path[:-1]:
                parent = parent[part]
            if isinstance(parent, dict) and action == "delete":
                del parent[path[-1]]
            elif isinstance(parent, dict):
                parent[data.draw(st.sampled_from(["extra", "id", "along", "alpha", "relative_to"]))] = \
                    copy.deepcopy(data.draw(st.sampled_from(ODD_VALUES)))
    mine, theirs = shape.spec_of(tree), pydantic_spec(tree)
    if theirs is None:
        assert mine is None
        _every_error_is_placed_in_the_tree(tree)
    elif mine is not None:
        assert plain(mine) == plain(theirs)


def _every_error_is_placed_in_the_tree(tree):
    """An error's place is a path in the user's tree (up to a missing or unknown key): none
    of pydantic's names for a union's members (`BodySpec`, `LineSpec`…) is left in it."""
    from kinematika.model.build import _clean

    try:
        schema.ModelSpec.model_validate(tree)
    except ValidationError as err:
        for error in err.errors():
            node = tree
            for part in _clean(error["loc"])[:-1]:
                assert isinstance(node, (dict, list)), (error["loc"], part)
                node = node[part]


def _dict_paths(tree, path=()):
    if isinstance(tree, dict):
        yield path
    children = tree.items() if isinstance(tree, dict) else enumerate(tree) if isinstance(tree, list) else ()
    for key, child in children:
        yield from _dict_paths(child, path + (key,))


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=[p.stem for p in EXAMPLE_FILES])
def test_an_unknown_key_anywhere_is_placed_in_the_tree(path):
    """An unknown key added to each mapping of an example: every error's place is a path in
    the tree — the union members' names pydantic adds are all left out (they are read from
    `schema`, not listed by hand)."""
    base = read_tree(path)
    for where in _dict_paths(base):
        tree = copy.deepcopy(base)
        node = tree
        for part in where:
            node = node[part]
        node["zz_unknown"] = [True]
        _every_error_is_placed_in_the_tree(tree)


def test_a_construction_lines_key_is_placed_in_the_line():
    """`LineSpec` (a construction's line given as through + direction) is not in the place."""
    from kinematika import KinematikaError
    from kinematika.model.build import build_model

    tree = read_tree(EXAMPLES / "quick_return.yaml")
    tree["points"]["C"]["line"]["dir"] = [1, 0]
    with pytest.raises(KinematikaError) as info:
        build_model(tree)
    assert (info.value.kind, info.value.where) == ("schema", "points.C.line.dir")
    assert info.value.message.startswith("unknown key 'dir'")


# the command line's fast path ------------------------------------------------------------
def test_the_fast_options_are_generated_from_the_typer_commands():
    assert generate_options.source() == generate_options.TARGET.read_text(encoding="utf-8"), \
        f"cli/fast_options.py is out of date: run {generate_options.COMMAND}"


def test_the_fast_options_are_the_typer_commands_options():
    import typer.main

    from kinematika.cli import app, fast_options, run as commands

    group = typer.main.get_command(app)
    assert set(fast_options.OPTIONS) == {"solve", "centres", "sweep", "simulate"}
    for name, table in fast_options.OPTIONS.items():
        command = group.commands[name]
        body = inspect.signature(getattr(commands, f"{name}_command")).parameters
        options = {opt: p for p in command.params for opt in p.opts}
        for opt, spec in table.items():
            param = options[opt]
            assert param.name == spec[0] and spec[0] in body, (name, opt)
            assert body[spec[0]].default == param.default, (name, opt)
            kind = spec[1]
            annotation = param.type_descriptor.annotation
            if kind == fast.FLAG:
                assert param.is_flag and param.default is False and annotation is bool
            else:
                assert not param.multiple and not param.is_flag, (name, opt)
                assert annotation is {fast.TEXT: str, fast.PATH: Path, fast.FLOAT: float,
                                      fast.INT: int}[kind], (name, opt)
                limits = spec[2:] if kind == fast.INT else (None, None)
                assert (param.min, param.max) == limits, (name, opt)
        arguments = [p for p in command.params if not getattr(p, "opts", [""])[0].startswith("-")]
        assert [p.name for p in arguments] == ["model"]


def _one_command(**option):
    import typer
    import typer.main

    app = typer.Typer()

    @app.command()
    def solve(model: Path, as_json: bool = typer.Option(False, "--json", **option)) -> None:
        """A command as `kinematika solve`, its --json changed."""

    return typer.main.get_command(app)


@pytest.mark.parametrize("option", [{"envvar": "KINEMATIKA_JSON"}, {"callback": lambda value: value},
                                    {"is_eager": True}],
                         ids=["envvar", "callback", "eager"])
def test_an_option_typer_reads_otherwise_is_an_error_of_the_generator(option):
    with pytest.raises(TypeError, match="--json"):
        generate_options._options("solve", _one_command(**option))


def test_an_integer_option_bounded_on_one_side():
    spec = ("assembly", fast.INT, 1, None)
    assert [fast._convert(v, spec) for v in ("1", "+7", "0", "-2", "10000000000000")] == \
        [1, 7, None, None, 10000000000000]


@pytest.mark.parametrize("argv", [
    ["solve"], ["solve", "--help"], ["solve", "a.yaml", "b.yaml"], ["solve", "a.yaml", "--jsonx"],
    ["solve", "a.yaml", "--json", "--json"], ["sweep", "a.yaml", "--steps", "abc"],
    ["sweep", "a.yaml", "--steps", "0"], ["sweep", "a.yaml", "--steps", "-3"], ["sweep", "a.yaml", "--steps", "10000001"],
    ["sweep", "a.yaml", "--by", "1_0"], ["sweep", "a.yaml", "--by"], ["sweep", "a.yaml", "--json=1"],
    ["draw", "a.yaml", "-o", "x.png"], ["sweep", "a.yaml", "--csv", ""], [],
    ["simulate", "a.yaml", "--steps", "0"], ["simulate", "a.yaml", "--time", "1e"],
    ["simulate", "a.yaml", "--set", "v=3"], ["simulate", "a.yaml", "--lang", "eu"],
])
def test_the_fast_path_leaves_anything_unusual_to_typer(argv):
    assert fast.parse(argv) is None


def test_the_fast_path_reads_plain_options():
    name, kwargs = fast.parse(["sweep", "--by", "-90", "m.yaml", "--steps=3", "--json", "-o", "x.npz"])
    assert name == "sweep"
    assert kwargs == {"by": -90.0, "model": Path("m.yaml"), "steps": 3, "as_json": True,
                      "output": Path("x.npz")}


def _fast(*args: str, fresh: bool = False) -> subprocess.CompletedProcess:
    """`kinematika ARGS` as a process runs it (`cli.main`, which takes the fast path): a new
    `python -m kinematika` with `fresh`, else a fork of this process (`fuzz.forks`, the
    modules already imported: the same path, without the start-up)."""
    if fresh:
        return subprocess.run([sys.executable, "-m", "kinematika", *args], capture_output=True, text=True)
    run = run_forked(list(args))
    return subprocess.CompletedProcess(run.args, run.status, run.stdout, run.stderr)


@pytest.mark.parametrize("args", [
    ["solve", "{ex}/four_bar.yaml", "--json"], ["solve", "{ex}/four_bar.yaml"],
    ["centres", "{ex}/watt_six_bar.yaml", "--json"],
    ["sweep", "{ex}/four_bar.yaml", "--steps", "8", "--json"],
    ["sweep", "{ex}/rssr_spatial_four_bar.yaml", "--steps=6", "--by", "-90", "--json"],
    ["sweep", "{ex}/four_bar.yaml", "--steps", "8"],
    ["solve", "{ex}/missing.yaml", "--json"],
    ["simulate", "{ex}/tractor_trailer_turning.yaml", "--time", "2", "--steps", "4", "--json"],
    ["simulate", "{ex}/tractor_trailer_turning.yaml", "--time=2", "--steps", "4"],
    ["simulate", "{ex}/tractor_trailer.yaml", "--time", "5", "--steps", "5", "--json"],
    ["simulate", "{ex}/tractor_trailer.yaml", "--time", "-1"],
], ids=["solve-json", "solve", "centres", "sweep-json", "sweep-3d", "summary", "missing", "simulate-json",
        "simulate", "simulate-stopped", "simulate-negative-time"])
def test_the_fast_path_prints_what_typer_prints(args):
    from typer.testing import CliRunner

    from kinematika.cli import app

    args = [a.format(ex=EXAMPLES) for a in args]
    quick = _fast(*args, fresh=args[0] == "solve" and "--json" not in args)     # one in a new process
    slow = CliRunner().invoke(app, args)
    assert quick.returncode == slow.exit_code
    if "--json" in args:
        assert json.loads(quick.stdout) == json.loads(slow.stdout)
    else:
        assert quick.stdout == slow.stdout
    assert quick.stderr.strip() == slow.stderr.strip()


def test_the_fast_path_imports_only_what_the_command_uses():
    code = ("import sys; from kinematika.cli import fast; "
            f"name, kw = fast.parse(['sweep', {str(EXAMPLES / 'four_bar.yaml')!r}, '--json']); "
            "import io, contextlib; out = io.StringIO(); sys.stdout = out; "
            "fast.command(name)(**kw); sys.stdout = sys.__stdout__; "
            "print(sorted({m.split('.')[0] for m in sys.modules} & "
            "{'typer', 'click', 'pydantic', 'scipy', 'sympy', 'matplotlib', 'rich'}))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


# YAML read in one pass ------------------------------------------------------------------
PLAIN_DOCUMENTS = [
    "points: {O: [0, 0], A: [1.5, -2e-3]}\nbodies: {ground: [O]}\n",
    "a: yes\nb: No\nc: on\nd: ~\ne: null\nf: ''\ng: '1'\nh: \"2.0\"\ni: 0x1f\nj: 1_000\nk: 0o17\n",
    "a: .inf\nb: -.Inf\nc: 2001-12-14\nd: 2001-12-14t21:59:43.10-05:00\ne: 1:30\nf: 190:20:30.15\n",
    "- [1, [2, [3, {x: y}]]]\n- {}\n- []\n- ''\n- |\n  two\n  lines\n- >\n  folded\n  text\n",
    "---\nname: 'ünïcödé θ'\n1: one\n2.5: two\nfalse: three\nnull: four\n...\n",
    "x: !!str 12\n", "x: &a [1]\ny: *a\n", "<<: {a: 1}\nb: 2\n", "a: 1\n---\nb: 2\n",
    "a: 1\na: 2\n", "? [1, 2]\n: pair\n", "x: !!binary aGk=\n", "",
]


@pytest.mark.parametrize("text", PLAIN_DOCUMENTS)
def test_the_one_pass_yaml_reader_gives_what_yaml_load_gives(text):
    """The one-pass reader gives yaml.load's tree, or leaves the text to the full reader
    (anchors, tags, merge keys, several documents, duplicate or unhashable keys)."""
    import yaml

    from kinematika.model.files import _UNUSUAL, _plain_yaml

    tree = _plain_yaml(text)
    unusual = any(mark in text for mark in ("!!", "&", "<<", "\n---\n", "a: 1\na:", "? ")) or not text
    assert (tree is _UNUSUAL) == unusual
    if tree is not _UNUSUAL:
        expected = yaml.load(text, Loader=yaml.SafeLoader)
        assert repr(tree) == repr(expected)
        assert json.dumps(tree, default=str) == json.dumps(expected, default=str)


NUMBER_TEXTS = ["0", "-0", "+7", "42", "007", "08", "0o17", "0x1f", "0b101", "1_000", "-1_0.5", "4.", "-4.50",
                "+.5", ".5", "-.5", "1e5", "1.0e5", "1.0e+5", "1.0E-5", "00.5", "-0.0", "+0.", "12:30", "1:30.5",
                "1.5.2", "9" * 30, "-" + "9" * 30 + ".25", "1" * 400 + ".0", ".inf", "-.Inf", ".nan", "1.5x", "'4.0'",
                '"7"', "0.1000000000000000055511151231257827", "1.0e999", "-" + "1" * 400 + ".5"]


@pytest.mark.parametrize("number", NUMBER_TEXTS)
def test_the_one_pass_reader_reads_numbers_as_yaml_load_does(number):
    """Plain decimal integers and numbers with a point are converted without the resolver's
    search: the values (their types, signs, infinities) are yaml.load's, in a mapping and in a
    list."""
    import yaml

    from kinematika.model.files import _UNUSUAL, _plain_yaml

    for text in (f"a: {number}\n", f"- [{number}, {number}]\n"):
        tree = _plain_yaml(text)
        assert tree is not _UNUSUAL
        expected = yaml.load(text, Loader=yaml.SafeLoader)
        assert repr(tree) == repr(expected), text         # the values, their types and signs


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=[p.stem for p in EXAMPLE_FILES])
def test_every_example_is_read_in_one_pass_as_yaml_load_reads_it(path):
    import yaml

    from kinematika.model.files import _plain_yaml

    text = path.read_text()
    assert repr(_plain_yaml(text)) == repr(yaml.load(text, Loader=yaml.SafeLoader))


# the answer's tables from arrays ----------------------------------------------------------
def _tables_one_by_one(sol):
    """The bodies' and points' tables as the general path writes them: every value from the
    tuple formulas (`Solution.velocity`…), rounded one scalar at a time."""
    from kinematika.report.values import plain

    speed, accel, length = sol.speed_scale(), sol.accel_scale(), sol.inst.scale
    bodies = {name: {"omega": plain(sol.state(name).omega, False, sol.rate_scale()),
                     "alpha": plain(sol.state(name).alpha, False, accel / length)}
              for name in sol.model.bodies}
    points = {str(ref): {"position": plain(sol.position(ref), False, length),
                         "velocity": plain(sol.velocity(ref), False, speed),
                         "acceleration": plain(sol.acceleration(ref), False, accel)}
              for ref in sol.model.material_points()}
    return bodies, points


# one example of each kind (every example in a deep run)
NUMERIC_EXAMPLES = sampled([p for p in EXAMPLE_FILES if "symbolic" not in p.stem], KINDS)


@pytest.mark.parametrize("path", NUMERIC_EXAMPLES, ids=[p.stem for p in NUMERIC_EXAMPLES])
def test_the_answer_tables_from_arrays_are_the_one_by_one_tables(path):
    from kinematika import KinematikaError, solve
    from kinematika.report.json_answer import solution_json

    try:
        sol = solve(path)
    except KinematikaError:
        pytest.skip("the example is an error case")
    if sol.symbolic:
        pytest.skip("symbolic")
    data = solution_json(sol)
    bodies, points = _tables_one_by_one(sol)
    assert json.dumps(data["bodies"]) == json.dumps(bodies)
    assert json.dumps(data["points"]) == json.dumps(points)
    for q, answer in zip(sol.model.questions, data["answers"]):
        if q.kind in ("velocity", "acceleration") and q.relative_to in (None, sol.model.frame):
            assert answer["value"] == points[str(q.target)][q.kind]


def test_a_large_chains_answer_is_its_hand_derivation():
    """Every loop a parallelogram: rockers turn as the crank (ω, α), couplers translate, and
    every pin A_i = (4i, 1) moves as the crank pin: v = ω k × (0, 1) = (−ω, 0),
    a = α k × (0, 1) − ω² (0, 1) = (−α, −ω²); the pivots O_i stand still. (The sparse LU
    leaves round-off of about 1e-11 in the accelerations of the far loops.)"""
    sys.path.insert(0, str(EXAMPLES.parent / "benchmarks"))
    from chain import four_bar_chain

    from kinematika.commands import solve_data

    w, alpha = 10.0, 3.0
    tree = four_bar_chain(301, w=w, alpha=alpha)
    del tree["ask"]                     # the default questions: every body and point
    data = solve_data(tree)
    assert data["dof"] == 1 and len(data["bodies"]) == 302
    for i in range(1, 151):
        assert data["bodies"][f"rocker{i}"] == {"omega": w, "alpha": pytest.approx(alpha, rel=1e-9)}
        assert data["bodies"][f"coupler{i}"] == {"omega": 0.0, "alpha": 0.0}
        for ref in (f"A{i}@rocker{i}", f"A{i}@coupler{i}", f"A{i - 1}@coupler{i}"):
            assert data["points"][ref]["velocity"] == [-w, 0.0]
            assert data["points"][ref]["acceleration"] == pytest.approx([-alpha, -w * w], rel=1e-9)
        assert data["points"][f"O{i}@rocker{i}"] == {"position": [4.0 * i, 0.0], "velocity": [0.0, 0.0],
                                                     "acceleration": [0.0, 0.0]}
    answers = {(a["ask"].get("velocity") or a["ask"].get("omega") or a["ask"].get("acceleration")
                or a["ask"].get("alpha"), next(iter(a["ask"]))): a["value"] for a in data["answers"]}
    assert answers[("A150@rocker150", "velocity")] == [-w, 0.0]
    assert answers[("rocker150", "alpha")] == pytest.approx(alpha, rel=1e-9)


def test_a_motions_arrays_are_read_once_and_read_only():
    """`Motion.arrays` (ω, v₀, α, a₀ of every body) is read from the states once and shared:
    the same arrays at every call, not writable (a reader that changed them would change
    every later reader's). Their values, in the plane, by hand for a chain of parallelogram
    loops (`benchmarks/chain.py`; v₀, a₀ at the motion's reference point R): the crank and
    every rocker turn at ω, α, pivoted at O_i = (4i, 0), so with d = R − O_i, v₀ = ω k × d
    = ω (−d_y, d_x) and a₀ = α (−d_y, d_x) − ω² d; the couplers translate as the pins A_i
    move, v₀ = (−ω, 0), a₀ = (−α, −ω²)."""
    import numpy as np

    sys.path.insert(0, str(EXAMPLES.parent / "benchmarks"))
    from chain import four_bar_chain

    from kinematika import solve

    w, alpha = 10.0, 3.0
    sol = solve(four_bar_chain(7, w=w, alpha=alpha))
    arrays = sol.motion.arrays()
    assert sol.motion.arrays() is arrays
    omega, v0, acc, a0 = arrays
    assert all(not part.flags.writeable for part in arrays)
    with pytest.raises(ValueError):
        omega[0, 0] = 1.0
    row = {name: i for i, name in enumerate(sol.motion.states)}
    assert omega.shape == (len(row), 1) and v0.shape == (len(row), 2)
    for i in range(1, 4):
        r, c = row[f"rocker{i}"], row[f"coupler{i}"]
        assert (omega[r, 0], acc[r, 0]) == pytest.approx((w, alpha), rel=1e-9)
        dx, dy = sol.motion.ref[0] - 4.0 * i, sol.motion.ref[1]
        assert v0[r] == pytest.approx([-w * dy, w * dx], rel=1e-9)
        assert a0[r] == pytest.approx([-alpha * dy - w * w * dx, alpha * dx - w * w * dy], rel=1e-9)
        assert (omega[c, 0], acc[c, 0]) == pytest.approx((0.0, 0.0), abs=1e-9)
        assert v0[c] == pytest.approx([-w, 0.0], rel=1e-9)
        assert a0[c] == pytest.approx([-alpha, -w * w], rel=1e-9)
    assert np.array_equal(omega[:, 0], [sol.state(b).omega for b in sol.motion.states])
