"""One test per class of hostile input that once broke the contract (issue 12): resource
exhaustion, tracebacks, terminal injection, wrong answers, inconsistent messages. Each runs
the real path (a file on disk, the command line where the class lives there) and checks
the outcome against the contract, with values derived by hand where an answer is expected.

The command line runs in a process of its own: a fork of this one (`forks.run_forked`:
its own streams, exit status, limits, with the modules already imported) for most cases,
and a fresh `python -m kinematika` (`contract.run_cli`) for one case of each path — the
fast path, typer's, a figure — so that the real executable is met too.
"""
from __future__ import annotations

import json
import os
import stat
import time
from pathlib import Path

import pytest
import yaml

from kinematika import KinematikaError
from kinematika import limits
from kinematika.budget import OverBudget, budget, check
from kinematika.commands import How, solve_data
from kinematika.expressions import parse
from kinematika.text import brief, markup, shown

from core.models import four_bar as core_four_bar
from tests.conftest import sampled
from .contract import EXAMPLES, call, check_error, check_run, run_cli
from .forks import run_forked
from .mutations import alias_bomb, rename
from .scaling import is_close, expected, numeric, scaled


def four_bar() -> dict:
    """The crank-rocker of the core tests, by coordinates, with questions and a sweep."""
    return core_four_bar(ask=[{"velocity": "B"}, {"acceleration": "B"}, {"omega": "coupler"},
                              {"icr": "coupler"}, {"velocity": "B@coupler", "relative_to": "crank"}],
                         sweep={"joint": "j1", "by": 360, "steps": 360})


def error_of(source, **kw) -> KinematikaError:
    with pytest.raises(KinematikaError) as info:
        solve_data(source, **kw)
    check_error(info.value)
    return info.value


def write(tmp_path: Path, name: str, text: str | dict) -> Path:
    path = tmp_path / name
    path.write_text(text if isinstance(text, str) else json.dumps(text), encoding="utf-8")
    return path


# resource exhaustion ------------------------------------------------------------------------
@pytest.mark.parametrize("where", ["description", "bogus"])
def test_an_alias_bomb_fails_fast_wherever_it_is(tmp_path, where):
    err = error_of(write(tmp_path, "bomb.yaml", alias_bomb(9, 9, where)))
    assert err.kind == "syntax" and "aliases expand to more than" in err.message


def test_an_alias_that_contains_itself_is_refused(tmp_path):
    err = error_of(write(tmp_path, "loop.yaml", "points: &p {O: [0, 0], P: *p}\n"))
    assert err.kind == "syntax" and "inside what it names" in err.message


def test_nesting_beyond_the_limit_is_refused_not_a_crash(tmp_path):
    # libyaml's composer recurses in C: this depth would crash the process if it were reached
    depth = 200_000
    err = error_of(write(tmp_path, "deep.yaml", "points: " + "[" * depth + "]" * depth))
    assert err.kind == "syntax" and "nested too deeply" in err.message


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_a_link_to_an_endless_device_reads_at_most_the_limit(tmp_path, device):
    if not os.path.exists(device):
        pytest.skip(f"no {device}")
    link = tmp_path / "model.yaml"
    link.symlink_to(device)
    err = error_of(link)
    assert err.kind == "syntax" and "too large" in err.message


def test_a_fifo_without_a_writer_does_not_block(tmp_path, monkeypatch):
    monkeypatch.setattr(limits, "READ_SECONDS", 0.2)
    fifo = tmp_path / "model.yaml"
    os.mkfifo(fifo)
    assert stat.S_ISFIFO(fifo.stat().st_mode)
    err = error_of(fifo)
    assert err.kind == "syntax" and "gave no end" in err.message


def test_a_folder_is_not_a_model(tmp_path):
    folder = tmp_path / "model.yaml"
    folder.mkdir()
    assert error_of(folder).kind == "syntax"


def test_a_sweep_too_large_to_hold_is_a_clear_error_from_the_file_or_the_options(tmp_path):
    from kinematika.commands import sweep_run

    tree = four_bar()
    tree["sweep"]["steps"] = 10_000_000
    with pytest.raises(KinematikaError) as info:
        sweep_run(tree)
    err = info.value
    check_error(err)
    # 4 bodies × (angle, ω, α) + 8 material points × 3 planar vectors = 60 numbers a row
    assert (err.kind, err.where) == ("schema", "sweep.steps")
    assert "of 60 values each" in err.message and f"at most {limits.SWEEP_VALUES // 60 - 1} steps" in err.message
    run = run_forked(["sweep", str(write(tmp_path, "four_bar.json", four_bar())), "--steps", "9000000",
                      "--json"])
    check_run(run)
    assert json.loads(run.stdout)["error"]["where"] == "--steps"


@pytest.mark.parametrize("value", ["1e-200", "(1e-308)**2", "1e-320*1e-10"])
def test_numbers_with_too_many_digits_for_exact_work_are_refused(value):
    tree = four_bar()
    tree["points"]["O2"] = [value, 0]
    err = error_of(tree, symbolic=True)
    assert err.kind == "schema" and err.where == "points.O2[0]" and "too many digits" in err.message


@pytest.mark.parametrize("value", ["(1e-308)**2", "1e-320*1e-10", "exp(-1000)"])
def test_floats_that_underflow_to_zero_are_refused(value):
    tree = four_bar()
    tree["points"]["O2"] = [value, 0]
    err = error_of(tree)
    assert err.kind == "schema" and err.where == "points.O2[0]" and "too small" in err.message


@pytest.mark.parametrize("power", ["r**1000", "(w2 + 1)**1000", "((r**10)**10)**10"])
def test_formulas_of_huge_degree_are_refused_in_exact_work(power):
    tree = four_bar()
    tree["parameters"]["r"] = None
    tree["points"]["A"] = [0, f"1 + 0*{power}"]
    err = error_of(tree, symbolic=True)
    assert err.kind == "schema" and err.where == "points.A[1]" and "degree" in err.message


def test_the_time_budget_stops_cooperative_work_with_a_limit_error():
    with pytest.raises(OverBudget) as info, budget("the exact formulas", 0.05):
        while True:
            check("simplifying the formulas")
    check_error(info.value)
    assert info.value.kind == "limit"
    assert "longer than 0.05 s of CPU time (simplifying the formulas)" in info.value.message


@pytest.mark.parametrize("symbolic", [True, None])
def test_the_budget_message_names_what_made_the_work_exact(monkeypatch, symbolic):
    # the wheel's R, v, vd are null: exact work without --symbolic, whose advice would mislead
    from kinematika.api import as_model
    from kinematika.budget import exact_work

    monkeypatch.setattr(limits, "SYMBOLIC_SECONDS", 0.02)
    monkeypatch.delenv("KINEMATIKA_SYMBOLIC_SECONDS", raising=False)
    with pytest.raises(OverBudget) as info, exact_work(as_model(wheel()), symbolic):
        while True:
            check("solving the equations exactly")
    check_error(info.value)
    message = info.value.message
    if symbolic:
        assert message.endswith("give some parameters numbers, or solve without --symbolic")
    else:
        assert "--symbolic" not in message
        assert message.endswith("give numbers to some of the parameters left as symbols (null: R, v, vd)")


def test_the_budget_counts_cpu_time_not_waiting():
    # a thread that waits (a loaded machine gives it no processor) spends none of its budget
    with budget("the exact formulas", 0.2):
        time.sleep(0.5)
        check("after waiting")


def test_the_time_budget_interrupts_one_long_computation():
    import sympy

    x, y = sympy.symbols("x y")
    start = time.thread_time()                # this thread's CPU time: the machine's load is not in it
    with pytest.raises(OverBudget), budget("the exact formulas", 0.3):
        sympy.factor(sympy.expand((x + 3 * y + 7) ** 60 * (x - y + 1) ** 60 - 1))
    assert time.thread_time() - start < 10    # stopped, not run to its end (minutes)


def test_a_long_name_is_refused_and_a_long_title_is_shown_cut(tmp_path):
    tree = four_bar()
    tree["points"]["P" * 30_000] = [1, 1]
    err = error_of(write(tmp_path, "long.json", tree))
    assert err.kind == "syntax" and f"names have at most {limits.NAME_CHARS}" in err.message
    tree = four_bar()
    tree["name"] = "x" * 30_000
    run = run_forked(["solve", str(write(tmp_path, "title.json", tree))])
    check_run(run)
    assert "x" * limits.NAME_CHARS not in run.stdout.replace("\n", "")


# tracebacks and internal errors -------------------------------------------------------------
def test_a_lone_surrogate_is_refused_not_a_crash(tmp_path):
    tree = four_bar()
    tree["name"] = "\ud800"
    path = tmp_path / "surrogate.json"
    path.write_text(json.dumps(tree))           # ASCII JSON with the escape \ud800
    err = error_of(path)
    assert err.kind == "syntax" and "lone surrogate" in err.message
    check_run(run_forked(["solve", str(path)]))


# one name of each kind in a default run (markup, terminal codes); every name in a deep run
@pytest.mark.parametrize("name", sampled(["[/]", "[bold]x[/bold]", "\x1b]0;owned\x07\x1b[2J", "a\rb"],
                                         {"[/]", "\x1b]0;owned\x07\x1b[2J"}))
def test_names_are_printed_as_written_never_as_markup_or_terminal_codes(tmp_path, name):
    tree = rename(four_bar(), "coupler", name + "c")
    tree["name"] = name
    text = json.dumps(tree)
    run = run_forked(["solve", str(write(tmp_path, "names.json", text))])
    check_run(run)
    assert run.status == 0
    assert "\x1b" not in run.stdout and "\x07" not in run.stdout and "\r" not in run.stdout
    assert shown(name) in run.stdout                            # the escaped name, literally
    run = run_forked(["centres", str(write(tmp_path, "names.json", text))])
    check_run(run)
    assert "\x1b" not in run.stdout and shown(name + "c") in run.stdout


@pytest.mark.parametrize("fmt", ["md", "html", "tex"])
def test_explanations_show_names_with_control_characters_escaped(fmt):
    # found by the campaign: the title and names went raw into every format of explain
    from kinematika.commands import explain_text

    name = "x\x7f\x9b\x0b\ufeff\t\x1b[/]\u202e"
    tree = rename(four_bar(), "coupler", "c\x1b[2J")
    tree["name"] = name
    text = explain_text(tree, fmt=fmt)
    assert not any(c in text for c in "\x7f\x9b\x0b\t\x1b\u202e")
    # the escapes, written as each format writes a backslash (Markdown doubles it)
    import re

    slash = r"(\\+|\\textbackslash\{\})"     # LaTeX writes it \textbackslash{}
    assert re.search(f"x{slash}x7f{slash}x9b{slash}x0b", text) and re.search(f"c{slash}x1b", text)


# format characters with markup, and terminal codes, in a default run; every name in a deep run
@pytest.mark.parametrize("name", sampled(["x\ufeff\u202e[/]", "\x7f[bold]", "\x1b]0;owned\x07"],
                                         {"x\ufeff\u202e[/]", "\x1b]0;owned\x07"}))
def test_the_assemblies_table_shows_names_as_written(tmp_path, name):
    # found by the campaign: its title was read as rich markup ('[/]': MarkupError) and
    # printed control characters raw
    tree = four_bar()
    tree["name"] = name
    run = run_forked(["assemblies", str(write(tmp_path, "named.json", tree))])
    check_run(run)
    assert run.status == 0 and shown(name) in run.stdout.replace("\n", "")
    assert not any(c in run.stdout for c in "\x7f\x1b\x07\u202e\ufeff")


def test_text_helpers_escape_controls_and_markup_and_bound_reprs():
    assert shown("a\x1b[2Jb\nc\u202ed\ud800") == "a\\x1b[2Jb\\nc\\u202ed\\ud800"
    assert markup("[/]") == "\\[/]"
    assert brief("x" * 1000) == repr("x" * 59)[:-1] + "…'"
    assert len(brief([[list(range(10 ** 4))] * 10 ** 3] * 10 ** 3)) <= 60


@pytest.mark.parametrize("change,kinds", [
    ({"parameters": {"w2": 1e12}}, [None]),                       # a fast crank: answered
    ({"parameters": {"w2": 1e300}}, ["schema"]),                  # beyond the rates' range
    ({"points": {"O2": [2 ** 63, 0]}}, ["mobility", "geometry"]),  # the tiny crank is lost
])
def test_large_values_answer_or_give_a_clear_error_never_an_internal_one(change, kinds):
    tree = four_bar()
    for key, value in change.items():
        tree[key].update(value)
    out = call(lambda tree=tree: solve_data(tree))
    assert (out.error.kind if out.error else None) in kinds
    call(lambda: solve_data(tree, True))         # exactly: an answer or a clear error


def wheel() -> dict:
    tree = yaml.safe_load((EXAMPLES / "wheel_rolling.yaml").read_text())
    tree.pop("draw_at", None)
    return tree


def test_an_exact_velocity_driver_of_1e12_agrees_with_the_numbers():
    tree = wheel()
    tree["parameters"] = {"R": 1, "v": 1e12, "vd": 0}
    data = solve_data(tree, symbolic=True)
    assert data["bodies"]["wheel"]["omega"] == "-v/R"         # v = ω R, rolling to +x turns cw
    data = solve_data(tree)
    assert data["bodies"]["wheel"]["omega"] == -1e12


def test_a_value_that_is_complex_at_the_symbols_values_is_a_clear_error():
    import sympy

    from kinematika.api import as_model
    from kinematika.engine.instant import instantiate

    inst = instantiate(as_model(wheel()))
    with pytest.raises(KinematikaError) as info:
        inst.num(sympy.sqrt(-1 - sympy.Symbol("R", positive=True)))
    check_error(info.value)
    assert info.value.kind == "schema" and "not a real number" in info.value.message
    for radius in ("sqrt(sqrt(x))", "x**(1/1000)"):       # once TypeError: complex to float
        tree = wheel()
        tree["parameters"]["x"] = {"value": None, "positive": False}
        tree["bodies"]["wheel"]["circle"]["radius"] = radius
        call(lambda tree=tree: solve_data(tree))


@pytest.mark.parametrize("change", [{"O2": [1.7e308, 0]}, {"A": [0, "3e110"]}])
def test_huge_coordinates_are_out_of_range_not_overflow_or_linalg_errors(change):
    tree = four_bar()
    tree["points"].update(change)
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "points") and "lengths between" in err.message
    assert "nan" not in err.message and "inf" not in err.message.split(":")[0]      # an overflowed size is said in words


def test_a_direction_with_subnormal_components_is_read_numerically():
    tree = wheel()
    tree["parameters"] = {"R": 1, "v": 2, "vd": 0}
    tree["drivers"][0]["along"] = [1, 5e-324]
    assert solve_data(tree)["bodies"]["wheel"]["omega"] == -2.0
    err = error_of(tree, symbolic=True)
    assert err.kind == "schema" and "too many digits" in err.message


def test_a_sweep_by_a_tiny_amount_has_no_nan():
    from kinematika.commands import sweep_run

    out = call(sweep_run(four_bar(), by=1e-308, steps=3)[1].to_json)
    assert out.error is None
    assert out.data["coordinate"][-1] == 1e-308


def test_a_path_with_a_newline_gives_one_line(tmp_path):
    run = run_cli(["solve", str(tmp_path / "a\nb.yaml")])
    check_run(run)
    assert run.status == 2 and "a\\nb.yaml" in run.stderr


@pytest.mark.parametrize("name", ["emoji.png", "cjk.png"])
def test_figures_of_names_without_glyphs_print_no_warnings(tmp_path, monkeypatch, name):
    label = {"emoji.png": "😀\r", "cjk.png": "中文"}[name]
    text = json.dumps(rename(four_bar(), "coupler", label))
    args = ["draw", str(write(tmp_path, "glyphs.json", text)), "-o", str(tmp_path / name)]
    if name == "emoji.png":         # a fresh process: matplotlib's first font lookups happen in it
        run = run_cli(args)
    else:                           # a fork, whose log records reach its standard error as a fresh one's do
        import logging

        monkeypatch.setattr(logging.root, "handlers", [])
        run = run_forked(args)
    check_run(run)
    assert run.status == 0 and "Warning" not in run.stderr and run.stderr.strip() == ""


# wrong answers ------------------------------------------------------------------------------
@pytest.mark.parametrize("twin,name", [("r", "𝑟"), ("fi", "ﬁ"), ("R", "ℝ"), ("A", "Ａ"),
                                        ("lambda", "_kw_lambda_")])
def test_parameter_names_are_matched_exactly_as_written(twin, name):
    tree = four_bar()
    tree["parameters"] = {twin: 3, name: 5}
    tree["drivers"][0]["value"] = name
    assert solve_data(tree)["bodies"]["crank"]["omega"] == 5.0
    tree["drivers"][0]["value"] = twin
    assert solve_data(tree)["bodies"]["crank"]["omega"] == 3.0


def test_a_name_python_would_fold_works_on_its_own():
    tree = four_bar()
    tree["parameters"] = {"𝑟": 5}
    tree["drivers"][0]["value"] = "2*𝑟"
    assert solve_data(tree)["bodies"]["crank"]["omega"] == 10.0
    assert parse("𝑟 + lambda").names() == {"𝑟", "lambda"}


@pytest.mark.parametrize("path,value", [("ask", {"velocity": "B", "relative_to": ""}),
                                        ("drivers", {"omega": "crank", "value": 1, "relative_to": ""}),
                                        ("joints", None)])
def test_an_empty_name_is_an_error_not_the_ground(path, value):
    tree = four_bar()
    if path == "joints":
        tree["joints"][0]["id"] = ""
    elif path == "drivers":
        tree["drivers"] = [value]
    else:
        tree["ask"].append(value)
    err = error_of(tree)
    assert err.kind == "schema"


def test_a_direction_of_1e_12_is_a_direction():
    tree = wheel()
    tree["drivers"][0]["along"] = [1e-12, 0]
    data = solve_data(tree)
    assert data["bodies"]["wheel"]["omega"] == "-v/R"


def _scaled_answers(name: str, length: float, rate: float) -> None:
    tree = numeric(yaml.safe_load((EXAMPLES / name).read_text()))
    base = solve_data(tree)
    got = solve_data(scaled(tree, length, rate))
    for a, b in zip(base["answers"], got["answers"]):
        kind = next(iter(a["ask"]))
        want = expected(a["value"], kind, length, rate)
        top = max([abs(x) for x in _numbers(want)] + [0.0])
        assert is_close(b["value"], want, top), (a["ask"], want, b["value"])


def _numbers(x):
    if isinstance(x, dict):
        return [n for v in x.values() for n in _numbers(v)]
    if isinstance(x, list):
        return [n for v in x for n in _numbers(v)]
    return [x] if isinstance(x, float) else []


@pytest.mark.parametrize("name", ["wheel_rolling.yaml", "fan_absolute.yaml", "gyroscope.yaml",
                                  "quick_return.yaml", "seed_c5_e2_gear_change.yaml"])
@pytest.mark.parametrize("length,rate", [(1e45, 1.0), (1e-45, 1.0), (1.0, 1e45), (1e-40, 1e40),
                                         (1e40, 1e40)])
def test_a_scaled_model_gives_the_same_answers_scaled(name, length, rate):
    _scaled_answers(name, length, rate)


@pytest.mark.parametrize("length,rate", [(1e200, 1.0), (1e-200, 1.0), (1e300, 1.0), (1e-300, 1.0),
                                         (1.0, 1e200), (1.0, 1e-200)])
def test_a_model_scaled_beyond_the_floats_range_is_a_clear_error(length, rate):
    for name in ("wheel_rolling.yaml", "four_bar.yaml", "fan_absolute.yaml"):
        tree = scaled(numeric(yaml.safe_load((EXAMPLES / name).read_text())), length, rate)
        err = error_of(tree)
        assert err.kind == "schema"
        assert any(why in err.message for why in ("between 1e-50 and 1e+50", "not finite", "too large",
                                              "too small"))


def test_the_top_of_a_huge_rolling_wheel_has_a_curved_path():
    # the cycloid's radius of curvature at the top is 4R (R = 1e45, v = 1e45)
    tree = wheel()
    tree["parameters"] = {"R": 1e45, "v": 1e45, "vd": 0}
    answers = {next(iter(a["ask"])): a["value"] for a in solve_data(tree)["answers"]}
    assert answers["curvature"]["radius"] == pytest.approx(4e45)


# one kind for one kind of mistake -----------------------------------------------------------
@pytest.mark.parametrize("args,where", [
    (["explain", "{model}", "--lang", "xx"], "--lang"),
    (["explain", "{model}", "--format", "docx"], "--format"),
    (["draw", "{model}", "-o", "{tmp}/x.png", "--points", "nope"], "--points"),
    (["draw", "{model}", "-o", "{tmp}/x.png", "--view", "bogus"], "--view"),
    (["draw", "{model}", "-o", "{tmp}/x.png", "--set", "w2=abc"], "--set w2"),
    (["sweep", "{model}", "--joint", "nope"], "--joint"),
    (["sweep", "{model}", "--steps", "nope"], "--steps"),
])
def test_every_bad_command_line_value_is_a_usage_error(tmp_path, args, where):
    args = [a.format(model=EXAMPLES / "four_bar.yaml", tmp=tmp_path) for a in args]
    run = (run_cli if where == "--steps" else run_forked)(args)     # one in a fresh process
    check_run(run)
    assert run.status == 2 and run.stderr.startswith("error (usage):"), run.stderr
    assert where in run.stderr


def test_an_output_error_names_the_file(tmp_path):
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full")
    run = run_forked(["explain", str(EXAMPLES / "four_bar.yaml"), "-o", "/dev/full"])
    check_run(run)
    assert run.stderr.startswith("error (output): -o: cannot write /dev/full: ")


def test_messages_never_echo_a_whole_expression():
    tree = four_bar()
    tree["points"]["A"] = [0, "1 + " * 490 + "q"]
    err = error_of(tree)
    assert err.kind == "schema" and len(err.message) <= limits.MESSAGE_CHARS


def test_a_two_dof_fan_with_a_restating_vector_driver_is_mobility():
    tree = yaml.safe_load((EXAMPLES / "fan_absolute.yaml").read_text())
    tree["drivers"] = tree["drivers"][:1]          # ω of the block (restates its shaft's x, z)
    err = error_of(tree)
    assert err.kind == "mobility"
    assert "2 degrees of freedom but the drivers give 1 independent condition" in err.message
    assert err.message.endswith("left free: blades")


# found by the fuzzing campaign (tests/fuzz/campaign.py) ------------------------------------
def test_an_integer_too_long_to_write_is_shown_by_its_size(tmp_path):
    # repr() of an integer past 4300 digits raises ValueError: it became an internal error
    text = (EXAMPLES / "four_bar.yaml").read_text().replace("type: revolute", "type: 0x" + "f" * 5000, 1)
    err = error_of(write(tmp_path, "hex.yaml", text))
    assert err.kind == "schema" and "an integer of 6021 digits is not one of 'revolute'" in err.message
    assert brief(-(16 ** 5000)) == "-an integer of 6021 digits"


@pytest.mark.parametrize("name", ["\u200b", "a\ufeffb", "x\u00ad", "\U000e0001"])
def test_invisible_format_characters_in_names_are_escaped_in_messages(name):
    tree = four_bar()
    tree["bodies"][name] = tree["bodies"].pop("coupler")
    err = error_of(tree)                              # the joints still name 'coupler'
    assert "unknown body 'coupler'" in err.message and shown(name) in err.message
    assert all(c not in err.message for c in name if not c.isprintable())
    assert shown("a\u00a0b\u202fc") == "a\u00a0b\u202fc"    # spaces of any width stay spaces


def test_a_point_name_with_a_dash_is_explained():
    # explanations wrote a segment as 'Q-P' and split it at the first '-': '-x' broke it
    from kinematika.commands import explain_text

    tree = rename(four_bar(), "A", "-x")
    text = explain_text(tree)
    assert "ω" in text and "-x" in text


def test_a_trigonometric_identity_is_zero_in_the_decomposition_check():
    # the pitch axis [sin ψ, 0, 0] makes a component (…)(sin²ψ + cos²ψ − 1)/sin²ψ, which the
    # canonical form does not reduce: the self-check raised AssertionError
    tree = yaml.safe_load((EXAMPLES / "robot_arm_3d.yaml").read_text())
    tree["joints"][1]["axis"] = ["sin(psi)", 0, 0]
    exact = solve_data(tree, symbolic=True)
    numbers = solve_data(tree)
    want = next(a for a in numbers["answers"] if "decompose" in a["ask"])["value"]["acceleration"]
    got = next(a for a in exact["answers"] if "decompose" in a["ask"])["value"]["acceleration"]
    import sympy

    values = {sympy.Symbol(k): sympy.sympify(v) for k, v in
              {"h": 0.5, "L": 0.8, "psi": "pi/6", "th": "pi/4"}.items()}
    for part in ("drag", "relative", "coriolis", "total"):
        evaluated = [float(sympy.sympify(c, locals={str(s): s for s in values}).subs(values)) for c in got[part]]
        assert evaluated == pytest.approx(want[part], abs=1e-12)
    # and by hand: the pitch axis is x, E turns about S at 1 rad/s, the base about z at 0.5
    assert sum(want[k][0] for k in ("drag", "relative", "coriolis")) == pytest.approx(want["total"][0])


def test_figures_show_names_with_control_characters_escaped():
    # the title and the plain labels went raw into matplotlib (a box for ESC, a warning)
    import matplotlib

    matplotlib.use("Agg")
    from kinematika.draw import draw

    name = "t\x1b]0;owned\x07"
    tree = rename(four_bar(), "coupler", "c\x1b[2J")
    tree["name"] = name
    fig = draw(tree)
    texts = [t.get_text() for t in fig.findobj(matplotlib.text.Text)]
    assert shown(name) in texts
    assert any(shown("c\x1b[2J") in t for t in texts)
    assert not any(c in t for t in texts for c in "\x1b\x07")


def test_a_length_that_overflows_the_constructed_positions_is_said_in_words():
    """`--set d=1e308` on a model stated by construction: its positions overflow, and the
    error once said 'the model's size is nan'."""
    err = error_of(EXAMPLES / "four_bar.yaml", how=How(set={"d": 1e308}))
    assert (err.kind, err.where) == ("schema", "points") and "lengths between" in err.message
    assert "beyond what floats hold" in err.message and "nan" not in err.message


def test_a_direction_with_components_1e50_apart_in_a_symbolic_model_is_a_clear_error():
    """Fuzz seed 20261124 case 397: the rolling wheel's ground line along [1, 2e-50] with
    its radius a symbol: normalising it exactly made sympy's integer factoring raise
    ValueError (an internal error); it is a schema error naming the direction."""
    tree = yaml.safe_load((EXAMPLES / "wheel_rolling.yaml").read_text())
    tree["bodies"]["ground"]["line"]["direction"] = [1, 2e-50]
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "bodies.ground.line.direction")
    assert "unit vector" in err.message


def test_a_symbol_drawn_at_a_huge_number_is_a_clear_error():
    """Fuzz seed 5 case 398: the symbolic fan drawn at h = 1.7e308 (`draw_at`) made the
    figure's limits infinite (matplotlib's ValueError: an internal error in explain)."""
    tree = yaml.safe_load((EXAMPLES / "fan_symbolic.yaml").read_text())
    tree["draw_at"]["h"] = 1.7e308
    err = error_of(tree)
    assert (err.kind, err.where) == ("schema", "draw_at.h") and "1e+50" in err.message


def test_drawing_a_model_with_symbols_keeps_the_budget_of_solve(monkeypatch, tmp_path):
    """`draw` solves a model with symbols exactly: within the budget of `solve`, whose
    `limit` error it gives past it (it ran without any budget: Jansen's leg in its crank
    angle was drawn in 2.5 s under a budget of 0.5 s). The page's figure: tests/web."""
    from kinematika.commands import draw_scene

    text = (EXAMPLES / "jansen_leg.yaml").read_text().replace("  theta: deg(90)", "  theta: null")
    path = write(tmp_path, "jansen_theta.yaml", text)
    monkeypatch.setenv("KINEMATIKA_SYMBOLIC_SECONDS", "0.05")
    with pytest.raises(OverBudget) as info:
        draw_scene(path)
    check_error(info.value)
    run = run_forked(["draw", str(path), "-o", str(tmp_path / "leg.svg")])
    assert run.status == 2 and "error (limit)" in run.stderr, run.stderr
