"""Errors and warnings in the reader's language (issue 30, item 12): the errors' catalogues
(`kinematika/errors/locales`) say the same messages with the same variables in en, es, ca
and eu; every place that raises names a message of them; an error of every kind, from a
real bad input, reads in each language — no English word of the message's own left, its
place (`where`) the same; the command line takes `--lang` or the locale; the page's API
takes the request's `lang`.

The words a message must hold in each language are the course's (the Basque and Catalan
notes, the explanations' glossaries), written here by hand, not read from the catalogues."""
from __future__ import annotations

import ast
import json
import os
import re
import subprocess
import sys
from pathlib import Path
from unittest import mock

import pytest
from fluent.syntax import ast as fluent
from fluent.syntax import parse

from kinematika import KinematikaError
from kinematika.errors import KinematikaWarning, Said, speaking
from kinematika.errors.said import LOCALES
from kinematika.languages import LANGS, from_command_line, from_locale

from fuzz.forks import run_forked

from .models import four_bar

SRC = Path(__file__).parents[2] / "src" / "kinematika"
# the words of other programs (an operating system's reason, a reader's complaint, pydantic's,
# click's): English says them in the program's own words, the others by their code, with the
# details the code passes (errors.reason, errors.parser_problem, errors.pydantic_problem,
# cli._click_said)
OTHERS = {"reason": {"errno", "text"}, "problem": {"code", "text"},
          "pydantic": {"type", "text", "ctx_min_length", "ctx_max_length", "ctx_gt", "ctx_ge", "ctx_lt",
                       "ctx_le"},
          "click": {"code", "text", "name", "suggestions", "count"}}


def _messages(lang: str) -> dict[str, fluent.Message]:
    resource = parse((LOCALES / f"{lang}.ftl").read_text(encoding="utf-8"))
    junk = [e.content[:60] for e in resource.body if isinstance(e, fluent.Junk)]
    assert not junk, (lang, junk)
    return {e.id.name: e for e in resource.body if isinstance(e, fluent.Message)}


def _variables(node) -> set[str]:
    found: set[str] = set()

    def walk(n) -> None:
        if isinstance(n, fluent.VariableReference):
            found.add(n.id.name)
        if isinstance(n, fluent.BaseNode):
            for value in vars(n).values():
                for item in value if isinstance(value, list) else [value]:
                    if isinstance(item, fluent.BaseNode):
                        walk(item)
    walk(node)
    return found


class _Catalogues(dict):
    """Each language's messages, parsed when a test first reads them (not when the module is
    imported: every xdist worker imports every test module, and the four catalogues take
    about a second of CPU to parse)."""

    def __missing__(self, lang: str) -> dict[str, fluent.Message]:
        self[lang] = _messages(lang)
        return self[lang]


CATALOGUES = _Catalogues()


@pytest.mark.parametrize("lang", [lang for lang in LANGS if lang != "en"])
def test_every_language_has_every_message_with_the_same_variables(lang):
    english, mine = CATALOGUES["en"], CATALOGUES[lang]
    assert set(mine) == set(english), (sorted(set(english) - set(mine)), sorted(set(mine) - set(english)))
    for key, message in english.items():
        if key in OTHERS:       # English: the program's words; the others: by code, with its details
            assert _variables(message) | _variables(mine[key]) <= OTHERS[key], key
            assert _variables(mine[key]) == _variables(CATALOGUES["es"][key]), (key, lang)
        else:
            assert _variables(mine[key]) == _variables(message), (key, lang)


RAISERS = {"KinematikaError": 1, "KinematikaWarning": 0, "ExpressionError": 0, "Failure": 2, "Said": 0}


def _said_keys() -> list[tuple[str, int, str]]:
    """Every message a call in the source names: (file, line, key or a key's pattern)."""
    out = []
    for path in sorted(SRC.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        if not any(name in text for name in RAISERS):     # no call to name: nothing to parse
            continue
        for node in ast.walk(ast.parse(text)):
            if not isinstance(node, ast.Call):
                continue
            name = getattr(node.func, "id", None) or getattr(node.func, "attr", None)
            if name not in RAISERS or len(node.args) <= RAISERS[name]:
                continue
            arg = node.args[RAISERS[name]]
            where = (str(path.relative_to(SRC)), node.lineno)
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                out.append((*where, arg.value))
            elif isinstance(arg, ast.JoinedStr):       # `unknown-{kind}`: the keys it can name
                out.append((*where, "".join(v.value if isinstance(v, ast.Constant) else "*" for v in arg.values)))
            elif isinstance(arg, ast.IfExp):
                out += [(*where, a.value) for a in (arg.body, arg.orelse) if isinstance(a, ast.Constant)]
    return out


def test_every_raise_names_a_message_of_the_catalogue():
    """No sentence is written in code: every error, warning and message names a key of the
    catalogue (a merge that brings an English sentence back fails here)."""
    keys = set(CATALOGUES["en"])
    said = _said_keys()
    assert len(said) > 400
    wrong = []
    for file, line, key in said:
        pattern = re.compile(re.escape(key).replace(r"\*", "[a-z0-9-]+") + r"\Z")
        if not any(pattern.match(k) for k in keys):
            wrong.append(f"{file}:{line}: {key!r}")
    assert not wrong, "\n".join(wrong)


def test_every_message_of_the_catalogue_is_said_somewhere():
    source = "\n".join(p.read_text(encoding="utf-8") for p in SRC.rglob("*.py"))
    dynamic = {"unknown-body", "unknown-point", "unknown-joint"}      # `unknown-{kind}` (model/wording.py)
    unused = [k for k in CATALOGUES["en"] if f'"{k}"' not in source and k not in dynamic | set(OTHERS)
              and k not in ("none", "more", "or-word", "and-word")]     # said.Names's own words
    assert not unused, unused


# errors of every kind, from real bad inputs ------------------------------------------------------
def _syntax(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("points:\n  A: [0, 0\n  B: [1, 1]\n")
    from kinematika import solve

    solve(bad)


def _schema(tmp_path):
    from kinematika import solve

    solve(four_bar(drivers=[{"omega": "crankk", "value": 1}]))


def _geometry(tmp_path):
    from kinematika import solve

    tree = four_bar()
    tree["points"]["B"] = {"circles": [["A", 1], ["O4", 1]], "side": "left"}     # AO4 is √2+…: far apart
    tree["points"]["A"] = [0, 5]
    solve(tree)


def _mobility(tmp_path):
    from kinematika import solve

    solve(four_bar(drivers=[]))


def _singular(tmp_path):
    from kinematika import solve

    solve(Path(__file__).parents[1] / "cases" / "tb_err_toggle_singular.yaml")


def _assembly(tmp_path):
    from kinematika.sweep.run import Sweeper

    tree = four_bar()
    tree["points"]["A"] = [0, 3]     # crank 3, coupler 3.49, rocker 2.96, ground 4: 3 + 4 > 3.49 + 2.96, no full turn
    Sweeper(tree).run(360, 36, through=False)     # a move past its limit position: the old stop


def _output(tmp_path):
    from kinematika.cli.shared import output_file

    output_file(tmp_path / "no-such-folder" / "sweep.csv", "-o")


def _usage(tmp_path):
    from kinematika.api import as_model
    from kinematika.model.overrides import with_parameters

    with_parameters(as_model(four_bar()), {"zz": "1"})


def _limit(tmp_path):
    from kinematika import limits, solve
    from kinematika.engine import positions
    from kinematika.model.files import parse_text

    tree = parse_text((Path(__file__).parents[1] / "cases" / "tb_fourbar_symbolic_theta.yaml").read_text(), "yaml")
    saved = limits.POINT_OPS, positions.NAME_OPS      # a constructed point's exact size, past lowered limits
    limits.POINT_OPS, positions.NAME_OPS = 1, 0
    try:
        solve(tree)
    finally:
        limits.POINT_OPS, positions.NAME_OPS = saved


# kind: how to make it, its place, and a word the message must hold in each language (the
# course's term for what went wrong)
KINDS = {
    "syntax": (_syntax, "bad.yaml", {"en": "line", "es": "línea", "ca": "línia", "eu": "lerroan"}),
    "schema": (_schema, "drivers[0].omega", {"en": "body", "es": "sólido", "ca": "sòlid", "eu": "solido"}),
    "geometry": (_geometry, "points.B", {"en": "circles", "es": "circunferencias", "ca": "circumferències",
                                          "eu": "zirkunferentziak"}),
    "mobility": (_mobility, "drivers", {"en": "degree", "es": "grado de libertad", "ca": "grau de llibertat",
                                        "eu": "askatasun-gradu"}),
    "singular": (_singular, "drivers", {"en": "dead point", "es": "punto muerto", "ca": "punt mort",
                                        "eu": "puntu hil"}),
    "assembly": (_assembly, "sweep", {"en": "assembled", "es": "montar", "ca": "muntar", "eu": "muntatu"}),
    "output": (_output, "-o", {"en": "folder", "es": "carpeta", "ca": "carpeta", "eu": "karpeta"}),
    "usage": (_usage, "--set", {"en": "parameter", "es": "parámetro", "ca": "paràmetre", "eu": "parametro"}),
    "limit": (_limit, "points.A", {"en": "operations", "es": "operaciones", "ca": "operacions",
                                   "eu": "eragiketa"}),
}
# words a language shares with English (the code's own words are removed before comparing)
SHARED = {"es": {"error", "final", "normal", "total", "real", "alias", "base", "fundamental", "singular",
                 "vector", "vertical", "bits", "byte", "bytes"},
          "ca": {"error", "final", "normal", "total", "real", "centres", "increment", "angle", "arc", "base", "byte",
                 "bits", "bytes", "centre", "component", "components", "constants", "disc", "document", "exponent",
                 "expressions", "figures", "format", "independent", "instant", "interval", "intervals", "model",
                 "models", "moment", "per", "port", "singular", "text", "variant", "variants", "vector",
                 "vertical", "zero"},
          "eu": {"error", "formula", "base"}}
# the words of the model file, the commands and other programs, written as they are in every
# language (keys, values, metrics, file types, programs)
CODE_WORDS = {"points", "bodies", "joints", "drivers", "cam", "follower", "program", "profile", "speed", "base",
              "face", "pivot", "arm", "omega", "alpha", "velocity", "rpm", "circle", "line", "decompose", "steps",
              "sweep", "vary", "seed", "lang", "true", "false", "null", "spline", "grashof", "transmission",
              "animate", "dict", "mechanism", "sympy", "vdot", "unicode", "csv", "npz", "parquet", "pdf", "png",
              "svg", "gif", "dask", "ffmpeg", "conda", "apt", "install", "debian", "kinematika",
              "phidot"}
CODE = re.compile(r"`[^`]*`|'[^']*'|\"[^\"]*\"|--?[a-z][\w-]*|\S*[=/_@\[\]{}:|]\S*|\b[A-Z][A-Z0-9]+\b|"
                  r"\b\w+\.\w+\b")


UNITS = {"deg", "rad"}        # the sweep's unit as its rows name it


def _words(text: str) -> set[str]:
    return {w.lower() for w in re.findall(r"[^\W\d_]{3,}", CODE.sub(" ", text))} - UNITS


def _error(kind, tmp_path) -> KinematikaError:
    make = KINDS[kind][0]
    with pytest.raises(KinematikaError) as info:
        make(tmp_path)
    return info.value


@pytest.mark.parametrize("kind", list(KINDS))
def test_an_error_of_every_kind_reads_in_every_language_and_names_its_place(kind, tmp_path):
    """The same error, read in en, es, ca and eu: its kind is the contract's English word, its
    place the same (a place in the model or an option, never empty), its message holds the
    course's term in that language and no English word of the English message's own."""
    err = _error(kind, tmp_path)
    assert err.kind == kind
    place, markers = KINDS[kind][1], KINDS[kind][2]
    assert err.where.endswith(place) and err.where
    said = {}
    for lang in LANGS:
        with speaking(lang):
            said[lang] = (err.as_json()["error"], str(err))
    english = _words(said["en"][0]["message"]) - _words(four_bar_names())
    for lang, (json_error, line) in said.items():
        assert json_error["kind"] == kind and json_error["where"] == err.where
        assert line.startswith(f"{err.where}: ")          # the line names the place first
        message = json_error["message"]
        assert markers[lang] in message.lower(), (lang, message)
        if lang != "en":
            left = (english & _words(message)) - SHARED.get(lang, set())
            assert not left, (lang, left, message)
            assert message != said["en"][0]["message"]


def four_bar_names() -> str:
    """The model's own names (bodies, points), which stay as the model writes them."""
    tree = four_bar()
    return " ".join([*tree["bodies"], *tree["points"], "rocker", "crank", "coupler", "ground"])


def test_a_warning_reads_in_every_language_and_names_its_place():
    """The radians warning (an angle of 30 where 30° was meant), in each language: the place,
    the numbers written as the language writes them, the fix as the model writes it."""
    from kinematika import solve

    tree = four_bar()
    tree["points"]["A"] = {"from": "O2", "distance": 1, "angle": 30.5}
    with pytest.warns(KinematikaWarning) as caught:
        sol = solve(tree)
    warning = caught[0].message
    assert warning.where == "points.A.angle"
    words = {"en": "radians", "es": "radianes", "ca": "radiants", "eu": "radianetan"}
    decimal = {"en": "30.5", "es": "30,5", "ca": "30,5", "eu": "30,5"}
    for lang in LANGS:
        with speaking(lang):
            shown = sol.inst.warnings[0].as_json()
        assert shown["where"] == "points.A.angle"
        assert words[lang] in shown["message"] and decimal[lang] in shown["message"]
        assert "deg(30.5)" in shown["message"]          # the fix as the model file writes it


def test_english_is_the_default_and_a_key_reads_as_before():
    err = KinematikaError("schema", "unknown-point", "points.A", point="Q", points=["A", "B"])
    assert err.message == "unknown point 'Q' (points: A, B)"
    assert KinematikaError("schema", "a sentence kept as it is", "x").message == "a sentence kept as it is"
    assert str(Said("none")) == "none"
    with speaking("eu"):
        assert err.message == "puntu ezezaguna 'Q' (puntuak: A, B)"
    assert err.message.startswith("unknown point")


def test_a_pickled_error_keeps_its_message_key():
    import pickle

    err = pickle.loads(pickle.dumps(KinematikaError("mobility", "mobility-free", "drivers", dof=1, conditions=0,
                                                    count=0, free=[])))
    assert (err.kind, err.where) == ("mobility", "drivers")
    with speaking("ca"):
        assert "grau de llibertat" in err.message


# the command line -------------------------------------------------------------------------
@pytest.mark.parametrize("environ, argv, lang", [
    ({"LANG": "eu_ES.UTF-8"}, [], "eu"),
    ({"LC_ALL": "ca_ES@valencia", "LANG": "en_GB.UTF-8"}, [], "ca"),
    ({"LC_ALL": "", "LC_MESSAGES": "es_ES", "LANG": "eu_ES"}, [], "es"),
    ({"LC_ALL": "C", "LANG": "eu_ES.UTF-8"}, [], "en"),           # the first one set decides
    ({"LANG": "fr_FR.UTF-8"}, [], "en"),
    ({}, [], "en"),
    ({"LANG": "es_ES"}, ["solve", "m.yaml", "--lang", "eu"], "eu"),
    ({"LANG": "es_ES"}, ["solve", "m.yaml", "--lang=ca"], "ca"),
    ({"LANG": "es_ES"}, ["solve", "m.yaml", "--lang", "fr"], "es"),  # then the command's usage error
])
def test_the_command_line_takes_lang_else_the_locale(environ, argv, lang):
    assert from_command_line(argv, environ) == lang
    if not argv:
        assert from_locale(environ) == lang


def _kinematika(*args: str, lang_env: str = "C.UTF-8", fresh: bool = False) -> subprocess.CompletedProcess:
    """`kinematika ARGS` in a process of its own under the locale `lang_env`: a fresh
    `python -m kinematika` with `fresh`, else a fork of this process (`fuzz.forks`: the same
    `cli.main`, which reads the environment as a new process does, without the start-up)."""
    env = {k: v for k, v in os.environ.items() if k not in ("LC_ALL", "LC_MESSAGES", "LANGUAGE")}
    env["LANG"] = lang_env
    if fresh:
        return subprocess.run([sys.executable, "-m", "kinematika", *args], capture_output=True, text=True,
                              env=env, timeout=300)
    with mock.patch.dict(os.environ, env, clear=True):
        run = run_forked(list(args))
    return subprocess.CompletedProcess(run.args, run.status, run.stdout, run.stderr)


@pytest.fixture
def models(tmp_path):
    import yaml

    free = tmp_path / "free.yaml"
    free.write_text(yaml.safe_dump(four_bar(drivers=[])))
    radians = tmp_path / "radians.yaml"
    tree = four_bar()
    tree["points"]["A"] = {"from": "O2", "distance": 1, "angle": 30}
    radians.write_text(yaml.safe_dump(tree))
    return free, radians


@pytest.mark.parametrize("how", ["--lang", "LANG"])
def test_the_command_line_says_errors_and_warnings_in_basque(models, how):
    free, radians = models
    extra, env = (["--lang", "eu"], "C.UTF-8") if how == "--lang" else ([], "eu_ES.UTF-8")
    run = _kinematika("solve", str(free), *extra, lang_env=env, fresh=how == "LANG")      # the locale in a new process
    assert run.returncode == 2
    assert run.stderr.startswith("errorea (mobility): drivers: mekanismoak askatasun-gradu 1 du, baina eragileek "
                                 "0 baldintza independente ematen dituzte"), run.stderr
    run = _kinematika("solve", str(free), "--json", *extra, lang_env=env)
    error = json.loads(run.stdout)["error"]
    assert (error["kind"], error["where"]) == ("mobility", "drivers") and "askatasun-gradu" in error["message"]
    run = _kinematika("solve", str(radians), *extra, lang_env=env)
    assert run.returncode == 0
    assert "abisua: points.A.angle: 30 angelua radianetan dago: 1719°, 4,8 bira" in run.stderr, run.stderr
    run = _kinematika("solve", str(radians), "--json", *extra, lang_env=env)
    warned = json.loads(run.stdout)["warnings"][0]
    assert warned["where"] == "points.A.angle" and "radianetan" in warned["message"]


def test_the_command_line_says_its_own_complaints_in_the_language(models):
    free, _ = models
    run = _kinematika("solve", str(free), "--nope", "--lang", "ca")
    assert run.returncode == 2 and run.stderr.startswith("error (usage): no existeix l’opció --nope"), run.stderr
    run = _kinematika("solve", str(free), "--lang", "fr", lang_env="es_ES.UTF-8")
    assert run.returncode == 2
    assert "idioma desconocido 'fr'" in run.stderr and "--lang" in run.stderr, run.stderr
    run = _kinematika("solve", str(free), "--json")           # nothing said: English, as ever
    assert "degree of freedom" in json.loads(run.stdout)["error"]["message"]


@pytest.mark.parametrize("lang", [lang for lang in LANGS if lang != "en"])
def test_no_message_keeps_an_english_word_of_its_own(lang):
    """Every message of the catalogue, said with stand-in values: no English word of the
    English message is left in the translation, but for the file's and the programs' own words
    (`CODE_WORDS`) and the words the language shares with English (`SHARED`)."""
    from fluent.runtime.types import fluent_number

    from kinematika.errors.said import catalogue

    english, mine = catalogue("en"), catalogue(lang)
    left = {}
    for key, message in CATALOGUES["en"].items():
        if key in OTHERS:
            continue
        args = {v: fluent_number(2) for v in _variables(message) | _variables(CATALOGUES[lang][key])}
        words = (_words(english.format(key, args)) & _words(mine.format(key, args))) - SHARED[lang] - CODE_WORDS
        if words:
            left[key] = sorted(words)
    assert not left, left
