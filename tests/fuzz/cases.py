"""The campaign's inputs: command lines on generated files, drawn from a seeded random source
(so that a failure is reproduced from its seed and number), in classes.

- `structural`: an example with keys deleted, added, items duplicated, types changed,
  values replaced, names renamed (every example, every command);
- `values`: an example with hostile numbers and expressions in its values;
- `symbolic`: the same, solved with `--symbolic` (exact formulas);
- `file`: files that are not models (alias bombs, deep nesting, huge numbers, tags,
  control characters, markup, lone surrogates, bad encodings) and paths that are not files
  (links to /dev/zero and /dev/urandom, FIFOs, folders, names with control characters);
- `scaled`: an example (its parameters given numbers) scaled in length and in time by
  10^±k; within the documented range its answers must be the original's scaled with their
  dimensions (checked by `campaign`), beyond it (10^±200, 10^±300) a clear error;
- `renamed`: an example with a point, body or parameter renamed everywhere to a hostile
  name: the same mechanism, so the same answers;
- `cli`: bad command-line values (every option of every command).
"""
from __future__ import annotations

import copy
import json
import math
import random
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from . import mutations
from .mutations import (HOSTILE_EXPRESSIONS, HOSTILE_FILES, HOSTILE_NAMES, HOSTILE_NUMBERS, TREES,
                        _get, _paths, _scaled_number, _set, alias_bomb, names_in)
from .scaling import numeric, scaled

COMMANDS = ["solve", "centres", "sweep", "explain", "draw", "assemblies"]
CLASSES = {"structural": 26, "values": 18, "symbolic": 8, "file": 12, "scaled": 16, "renamed": 8,
           "cli": 12}          # relative frequencies


@dataclass
class Case:
    """One input: the command line (with `{dir}` for the case's folder) and its files."""

    number: int
    klass: str
    args: list[str]
    files: dict[str, Any] = field(default_factory=dict)   # name -> text | bytes | ("link", target) | ("fifo",) | ("dir",)
    base: str | None = None       # the key of the run this one must agree with (scaled, renamed)
    length: float = 1.0
    rate: float = 1.0
    strict: bool = False          # must answer (exit 0) when its base answers
    name: str = ""                # the new name of a renamed model
    note: str = ""

    def materialise(self, folder: Path) -> list[str]:
        """Write the files into `folder`; the command line with its paths."""
        import os

        for name, content in self.files.items():
            path = folder / name
            if isinstance(content, tuple):
                if content[0] == "link":
                    path.symlink_to(content[1])
                elif content[0] == "fifo":
                    os.mkfifo(path)
                elif content[0] == "dir":
                    path.mkdir()
            elif isinstance(content, bytes):
                path.write_bytes(content)
            else:
                path.write_bytes(content.encode("utf-8", "surrogatepass"))
        return [a.replace("{dir}", str(folder)) for a in self.args]


# writing trees as files ---------------------------------------------------------------------
def as_file(rng: random.Random, tree: Any) -> tuple[str, Any]:
    """A model tree as a file: JSON (ASCII escapes, or raw text) or YAML."""
    choice = rng.random()
    try:
        if choice < 0.35:
            return "model.json", json.dumps(tree, ensure_ascii=rng.random() < 0.5, default=str)
        return "model.yaml", yaml.safe_dump(tree, allow_unicode=rng.random() < 0.5, sort_keys=False)
    except (ValueError, yaml.YAMLError, TypeError, OverflowError, RecursionError):
        return "model.json", json.dumps(tree, default=str)


def options(rng: random.Random, command: str, symbolic: bool | None = None) -> list[str]:
    """Ordinary options of `command` (the model's own are what is under test)."""
    out = []
    if command in ("solve", "centres", "sweep", "assemblies") and rng.random() < 0.6:
        out.append("--json")
    if command in ("solve", "centres", "explain") and (symbolic if symbolic is not None else rng.random() < 0.15):
        out.append("--symbolic")
    if command == "sweep":
        out += ["--steps", str(rng.choice([3, 10, 36]))]
    if command == "draw":
        out += ["-o", "{dir}/figure." + rng.choice(["png", "svg"])]
    if command == "explain":
        if rng.random() < 0.4:
            out += ["--lang", rng.choice(["en", "es", "ca", "eu"])]
        if rng.random() < 0.3:
            out += ["--format", rng.choice(["md", "html", "tex"])]
    return out


def pick_command(rng: random.Random, symbolic: bool = False) -> str:
    if symbolic:
        return rng.choice(["solve", "solve", "centres", "explain"])
    return rng.choices(COMMANDS, weights=[30, 12, 14, 10, 6, 8])[0]


# mutations -----------------------------------------------------------------------------------
SCALARS = HOSTILE_NUMBERS + HOSTILE_EXPRESSIONS


def scalar(rng: random.Random) -> Any:
    kind = rng.random()
    if kind < 0.35:
        return rng.choice(HOSTILE_NUMBERS)
    if kind < 0.7:
        return rng.choice(HOSTILE_EXPRESSIONS)
    if kind < 0.8:
        return rng.choice(HOSTILE_NAMES)
    if kind < 0.85:
        return rng.choice([None, True, False, [], {}, [1, 2, 3, 4], {"value": None}])
    if kind < 0.9:
        return rng.choice([math.nan, math.inf, -math.inf, 5e-324, -2 ** 53 - 1])
    power = rng.choice([-330, -308, -300, -200, -50, 50, 200, 300, 308, 330])
    return f"{rng.choice(['', '-'])}{rng.randint(1, 9)}e{power}"


def mutate(rng: random.Random, tree: dict, count: int, structural: bool) -> dict:
    """`count` mutations of `tree` (see the module's classes)."""
    for _ in range(count):
        paths = _paths(tree)[1:]
        if not paths:
            break
        path = rng.choice(paths)
        node = _get(tree, path)
        ops = ["value", "value", "scale", "rename"]
        if structural:
            ops += ["delete", "duplicate", "type", "add", "add"]
        op = rng.choice(ops)
        try:
            if op == "value":
                tree = _set(tree, path, scalar(rng))
            elif op == "scale":
                tree = _set(tree, path, _scaled_number(node, rng.randint(-330, 330)))
            elif op == "rename":
                tree = renamed(rng, tree, rng.choice(HOSTILE_NAMES), rng.random() < 0.5)
            elif op == "delete":
                parent = _get(tree, path[:-1])
                del parent[path[-1]]
            elif op == "duplicate" and isinstance(node, list) and node:
                node.append(copy.deepcopy(rng.choice(node)))
            elif op == "type":
                tree = _set(tree, path, rng.choice([[node], {"x": node}, str(node), None, 1, [node, node]]))
            elif op == "add" and isinstance(node, dict):
                key = rng.choice(HOSTILE_NAMES + ["description", "sweep", "move", "symbolic", "value",
                                                  "relative_to", "near", "side", "dimension", "up"])
                node[key] = scalar(rng) if rng.random() < 0.7 else copy.deepcopy(node)
            elif op == "add" and isinstance(node, list):
                node.append(scalar(rng))
        except (KeyError, IndexError, TypeError):
            continue
    return tree


def renamed(rng: random.Random, tree: dict, new: str, everywhere: bool = True) -> dict:
    """A point, body or parameter (chosen at random) renamed to `new`, everywhere or in its
    definition only."""
    names = [n for n in names_in(tree) if n != "ground"]
    if not names:
        return tree
    return mutations.renamed(tree, new, everywhere, rng.choice(sorted(names)))


# the classes ---------------------------------------------------------------------------------
def structural(rng: random.Random, n: int) -> Case:
    name = rng.choice(sorted(TREES))
    tree = mutate(rng, copy.deepcopy(TREES[name]), rng.randint(1, 4), True)
    command = pick_command(rng)
    file, text = as_file(rng, tree)
    return Case(n, "structural", [command, "{dir}/" + file, *options(rng, command)], {file: text}, note=name)


def values(rng: random.Random, n: int, symbolic: bool = False) -> Case:
    name = rng.choice(sorted(TREES))
    tree = mutate(rng, copy.deepcopy(TREES[name]), rng.randint(1, 3), False)
    command = pick_command(rng, symbolic)
    file, text = as_file(rng, tree)
    return Case(n, "symbolic" if symbolic else "values",
                [command, "{dir}/" + file, *options(rng, command, symbolic or None)], {file: text}, note=name)


def _text_with(rng: random.Random, what: str) -> str:
    base = yaml.safe_dump(TREES[rng.choice(sorted(TREES))], sort_keys=False, allow_unicode=True)
    if what == "control":
        junk = "".join(chr(rng.choice([0, 7, 8, 9, 11, 12, 13, 27, 127, 0x85, 0x9b, 0x202e, 0x2028, 0xfeff]))
                       for _ in range(rng.randint(1, 6)))
        return base.replace("name: ", "name: " + json.dumps(junk) + " # ", 1) if rng.random() < 0.5 \
            else f"name: {json.dumps('x' + junk + '[/]')}\n" + "\n".join(
                line for line in base.splitlines() if not line.startswith("name:"))
    if what == "markup":
        return base.replace("name: ", "name: '[bold red]x[/][link=file:///etc/passwd]y[/link] ", 1)
    return base


def hostile_file(rng: random.Random, n: int) -> Case:
    command = pick_command(rng)
    opts = options(rng, command)
    kind = rng.random()
    if kind < 0.3:
        name = rng.choice(sorted(HOSTILE_FILES))
        return Case(n, "file", [command, "{dir}/" + name, *opts], {name: HOSTILE_FILES[name]}, note=name)
    if kind < 0.45:
        where = rng.choice(["description", "name", "points", "bogus", "parameters"])
        levels, width = rng.randint(3, 12), rng.randint(2, 12)
        return Case(n, "file", [command, "{dir}/bomb.yaml", *opts],
                    {"bomb.yaml": alias_bomb(levels, width, where)}, note=f"alias {levels}x{width} in {where}")
    if kind < 0.55:
        depth = rng.choice([10, 50, 63, 64, 65, 100, 1000, 100_000])
        opener, closer = rng.choice([("[", "]"), ("{a: ", "}")])
        file = rng.choice(["deep.yaml", "deep.json"]) if opener == "[" else "deep.yaml"
        return Case(n, "file", [command, "{dir}/" + file, *opts],
                    {file: "points: " + opener * depth + closer * depth + "\n" if file.endswith("yaml")
                     else '{"points": ' + "[" * depth + "]" * depth + "}"}, note=f"nesting {depth}")
    if kind < 0.65:
        target = rng.choice(["/dev/zero", "/dev/urandom", "/dev/null", "/dev/full", "/proc/self/mem",
                             "/proc/self/environ", "/etc/passwd", "/nonexistent"])
        file = rng.choice(["model.yaml", "model.json", "model.toml"])
        return Case(n, "file", [command, "{dir}/" + file, *opts], {file: ("link", target)}, note=target)
    if kind < 0.7:
        file, what = rng.choice([("fifo.yaml", ("fifo",)), ("folder.yaml", ("dir",))])
        return Case(n, "file", [command, "{dir}/" + file, *opts], {file: what}, note=what[0])
    if kind < 0.75:
        path = rng.choice(["a\nb.yaml", "\x1b[2J.yaml", "x" * 300 + ".yaml", "[/].yaml", "-", "",
                           "\u202e.yaml", "dir/../../etc/passwd", "model.yaml\x00"])
        return Case(n, "file", [command, "{dir}/" + path if path not in ("-", "") else path, *opts],
                    note="path " + repr(path[:20]))
    if kind < 0.85:
        what = rng.choice(["control", "markup"])
        return Case(n, "file", [command, "{dir}/model.yaml", *opts], {"model.yaml": _text_with(rng, what)}, note=what)
    # numbers and expressions written straight into the text
    example = rng.choice(sorted(TREES))
    text = yaml.safe_dump(TREES[example], sort_keys=False)
    lines = text.splitlines()
    spot = rng.randrange(len(lines))
    token = rng.choice(["9" * rng.choice([20, 400, 5000, 100_000]), "1e99999", "0x" + "f" * 5000, ".inf",
                        "-.nan", "1e-400", "!!binary aGk=", "*undefined", "&a x", "!!python/name:os.system",
                        "~", "'''", '"\\ud800"', '"\\U0010ffff"', "2001-01-01", "0o777", "1_0", "+.5e+3"])
    if ":" in lines[spot]:
        key = lines[spot].split(":", 1)[0]
        lines[spot] = f"{key}: {token}"
    else:
        lines[spot] = lines[spot].rsplit(" ", 1)[0] + " " + token
    return Case(n, "file", [command, "{dir}/model.yaml", *opts], {"model.yaml": "\n".join(lines) + "\n"},
                note=f"{example} line {spot} {token[:20]}")


IN_RANGE = 40       # 10^±k with k at most this: answers required (the documented range is 1e±50)
BEYOND = [200, -200, 300, -300, 100, -100, 60, -60]


def scaled_case(rng: random.Random, n: int) -> Case:
    name = rng.choice(sorted(TREES))
    tree = numeric(TREES[name])
    if rng.random() < 0.6:
        length = 10.0 ** rng.randint(-IN_RANGE, IN_RANGE)
        rate = 10.0 ** rng.randint(-IN_RANGE, IN_RANGE) if rng.random() < 0.5 else 1.0
        if rng.random() < 0.3:
            length, rate = 1.0, 10.0 ** rng.randint(-IN_RANGE, IN_RANGE)
        strict = True
    else:
        length = 10.0 ** rng.choice(BEYOND) if rng.random() < 0.7 else 1.0
        rate = 10.0 ** rng.choice(BEYOND) if length == 1.0 or rng.random() < 0.3 else 1.0
        strict = False
    file, text = as_file(rng, scaled(tree, length, rate))
    command = rng.choice(["solve", "solve", "solve", "centres", "sweep", "explain", "draw"])
    args = [command, "{dir}/" + file, "--json"] if command in ("solve", "centres", "sweep") else \
        [command, "{dir}/" + file, *options(rng, command, False)]
    if command == "sweep":
        args += ["--steps", "4"]
    base = f"base:{name}" if command == "solve" else None
    return Case(n, "scaled", args, {file: text}, base=base, length=length, rate=rate,
                strict=strict, note=f"{name} L={length:g} T=1/{rate:g}")


def renamed_case(rng: random.Random, n: int) -> Case:
    name = rng.choice(sorted(TREES))
    new = rng.choice(HOSTILE_NAMES + ["x" * rng.randint(1, 250), "p_" + str(rng.randint(0, 999))])
    tree = renamed(rng, numeric(TREES[name]), new, True)
    file, text = as_file(rng, tree)
    command = rng.choice(["solve", "solve", "centres", "explain", "draw"])
    args = [command, "{dir}/" + file] + (["--json"] if command == "solve" else options(rng, command, False))
    return Case(n, "renamed", args, {file: text}, base=f"base:{name}" if command == "solve" else None,
                name=new, note=f"{name} -> {new[:20]!r}")


BAD_VALUES = ["", " ", "nope", "-1", "0", "1e400", "nan", "inf", "-inf", "1e-400", "9" * 40, "1.5",
              "\x1b[2J", "[/]", "\ud800", "--json", "=", "a=b=c", "x=", "=1", "w2=1e999", "w2=nan",
              "j1=1e308", "j1=", "99999999999999999999", "-0", "0x10", "１"]
BAD_OPTIONS = {
    "solve": ["--set", "--move", "--assembly"],
    "centres": ["--set", "--move", "--assembly"],
    "sweep": ["--joint", "--by", "--steps", "--csv", "--plot", "-o", "--format", "--set", "--move", "--assembly"],
    "explain": ["--lang", "--format", "-o", "--length-unit", "--set", "--move", "--assembly"],
    "draw": ["--points", "--view", "--width", "--set", "--move", "--assembly", "-o"],
    "assemblies": ["--set"],
}
OUTPUTS = ["/dev/full", "/nonexistent/x.png", "{dir}", "{dir}/x.docx", "{dir}/x", "/proc/version",
           "{dir}/\x1b[2J.png", "{dir}/a\nb.csv", ""]


def cli_case(rng: random.Random, n: int) -> Case:
    command = rng.choice(sorted(BAD_OPTIONS))
    example = rng.choice(["four_bar.yaml", "slider_crank.yaml", "quick_return.yaml", "hooke_joint.yaml",
                          "wheel_rolling.yaml", "watt_six_bar.yaml"])
    args = [command, f"examples/{example}"]
    if command == "draw":
        args += ["-o", "{dir}/f.png"]
    for _ in range(rng.randint(1, 3)):
        option = rng.choice(BAD_OPTIONS[command] + ["--bogus", "--json", "--symbolic", "-x", "--help"])
        if option in ("-o", "--csv", "--plot"):
            value = rng.choice(OUTPUTS)
        elif option in ("--set", "--move"):
            value = rng.choice(BAD_VALUES + ["w2=3", "theta2=1e300", "j1=45", "nope=1", "a=1e-320"])
        else:
            value = rng.choice(BAD_VALUES)
        args += [option] if option in ("--json", "--symbolic", "--help") else [option, value]
    if rng.random() < 0.1:
        args.insert(rng.randrange(1, len(args) + 1), rng.choice(["extra.yaml", "--", "-"]))
    return Case(n, "cli", args, note=example)


def case(seed: int, n: int) -> Case:
    """Input number `n` of the campaign with `seed` (independent of the others)."""
    rng = random.Random(f"{seed}:{n}")
    klass = rng.choices(list(CLASSES), weights=list(CLASSES.values()))[0]
    if klass == "structural":
        return structural(rng, n)
    if klass == "values":
        return values(rng, n)
    if klass == "symbolic":
        return values(rng, n, symbolic=True)
    if klass == "file":
        return hostile_file(rng, n)
    if klass == "scaled":
        return scaled_case(rng, n)
    if klass == "renamed":
        return renamed_case(rng, n)
    return cli_case(rng, n)


def bases() -> list[Case]:
    """Every example with its parameters given numbers, solved: what scaled and renamed
    cases are compared with."""
    out = []
    for name in sorted(TREES):
        out.append(Case(-1, "base", ["solve", "{dir}/model.json", "--json"],
                        {"model.json": json.dumps(numeric(TREES[name]))}, note=f"base:{name}"))
    return out


def symbolic_examples() -> list[Case]:
    """Every shipped example solved with `--symbolic` as it is (the issue's bar: under 5 s)."""
    return [Case(-1, "example", ["solve", f"examples/{name}", "--symbolic", "--json"], note=name)
            for name in sorted(TREES)]
