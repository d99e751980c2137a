"""Hypothesis strategies for hostile models: the examples mutated in structure and values,
names a hostile user would choose, and files that are not models at all.

Every strategy draws data (a model tree, or the bytes of a file); `tests/fuzz/test_fuzz.py`
runs commands on them under the contract, and `tests/fuzz/run.py` does the same at scale.
"""
from __future__ import annotations

import copy
from pathlib import Path
from collections.abc import Iterator, Mapping
from typing import Any

import yaml
from hypothesis import strategies as st

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


class _Trees(Mapping):
    """Each example's tree by file name, read when first asked for (not when the module is
    imported: every xdist worker imports every test module, and reading all the examples
    takes about a second of CPU); a tree is read once a process."""

    def __init__(self, paths: list[Path]) -> None:
        self._paths = {p.name: p for p in paths}
        self._trees: dict[str, Any] = {}

    def __getitem__(self, name: str) -> Any:
        if name not in self._trees:
            self._trees[name] = yaml.safe_load(self._paths[name].read_text(encoding="utf-8"))
        return self._trees[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._paths)

    def __len__(self) -> int:
        return len(self._paths)


TREES = _Trees(sorted(EXAMPLES.glob("*.yaml")))

# names that have broken something somewhere: markup, terminal controls, bidi overrides,
# lone surrogates, NFKC look-alikes, keywords, the old keyword mangling, very long ones
HOSTILE_NAMES = [
    "[/]", "[bold]x[/bold]", "\x1b]0;owned\x07\x1b[2J", "a\nb", "a\rb", "\t", " ", "", "@", "A@B",
    "\u202eevil", "\u200b", "\ud800", "😀", "中文", "𝑟", "ﬁ", "ℝ", "Ａ", "lambda", "_kw_lambda_",
    "pi", "sqrt", "None", "True", "__import__", "0", "1e5", "x" * 300, "-x", "$x$", "\\frac{a}{b}",
    "<b>x</b>", "&amp;", "%s", "{0}", "'", '"', "a b",
]
HOSTILE_NUMBERS = [
    0, -0.0, 1e-12, -1e-12, 1e-200, 1e200, 1e-320, 1.7e308, -1.7e308, 2 ** 63, 2 ** 1000,
    10 ** 400, 1e-50, 1e50, 3e110, 0.1, 1 / 3, 123456789.123456789,
]
HOSTILE_EXPRESSIONS = [
    "1e308*10", "(1e-308)**2", "1e-320*1e-10", "r**1000", "(w+1)**1000", "w**(1/1000)",
    "sqrt(-1)", "0/0", "1/0", "log(0)", "exp(1000)", "exp(-1000)", "asin(2)", "10**10**10",
    "2**2**2**2**2", "((((((((((1))))))))))", "-" * 500 + "1", "sqrt(" * 80 + "1" + ")" * 80,
    "__import__('os')", "().__class__", "lambda: 1", "x if y else z", "[1]", "'a'", "1j",
    "nan", "inf", "1e5000", "0x" + "f" * 400, "9" * 5000, "deg(1e300)", "atan2(0, 0)",
    "sin(1e300)", "cos(1e22)", "1_000", "2r", "𝑟", "ﬁ*2", "lambda", "a.b", "abs", "pi*pi",
]
ANY_SCALAR = st.one_of(st.sampled_from(HOSTILE_NUMBERS), st.sampled_from(HOSTILE_EXPRESSIONS),
                       st.sampled_from(HOSTILE_NAMES), st.floats(allow_nan=True, allow_infinity=True),
                       st.integers(), st.none(), st.booleans(), st.text(max_size=30))
ANY_VALUE = st.recursive(ANY_SCALAR, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=8), inner, max_size=3)), max_leaves=8)


def _paths(tree: Any, prefix: tuple = ()) -> list[tuple]:
    """Every place in the tree: its path of keys and indices."""
    out = [prefix]
    if isinstance(tree, dict):
        for k, v in tree.items():
            out += _paths(v, prefix + (k,))
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            out += _paths(v, prefix + (i,))
    return out


def _get(tree: Any, path: tuple) -> Any:
    for part in path:
        tree = tree[part]
    return tree


def _set(tree: Any, path: tuple, value: Any) -> Any:
    if not path:
        return value
    _get(tree, path[:-1])[path[-1]] = value
    return tree


def _scaled_number(value: Any, power: int) -> Any:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return f"({value})*1e{power}" if isinstance(value, str) else value
    return value * 10.0 ** power if abs(power) < 300 else f"({value})*1e{power}"


@st.composite
def mutated(draw: Any, structural: bool = True) -> tuple[str, dict]:
    """An example model with a few mutations: values replaced by hostile ones, scaled by
    powers of ten, names renamed (everywhere, or in one place), keys deleted or added,
    items duplicated, types changed."""
    name = draw(st.sampled_from(sorted(TREES)))
    tree = copy.deepcopy(TREES[name])
    for _ in range(draw(st.integers(1, 4))):
        paths = _paths(tree)[1:]
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        node = _get(tree, path)
        ops = ["value", "scale", "rename"] + (["delete", "duplicate", "type", "add"] if structural else [])
        op = draw(st.sampled_from(ops))
        if op == "value":
            tree = _set(tree, path, draw(ANY_SCALAR if structural else st.one_of(
                st.sampled_from(HOSTILE_NUMBERS), st.sampled_from(HOSTILE_EXPRESSIONS))))
        elif op == "scale":
            tree = _set(tree, path, _scaled_number(node, draw(st.integers(-330, 330))))
        elif op == "rename":
            tree = renamed(tree, draw(st.sampled_from(HOSTILE_NAMES)), draw(st.booleans()))
        elif op == "delete" and len(path) > 0:
            parent = _get(tree, path[:-1])
            del parent[path[-1]]
        elif op == "duplicate" and isinstance(node, list) and node:
            node.append(copy.deepcopy(node[draw(st.integers(0, len(node) - 1))]))
        elif op == "type":
            tree = _set(tree, path, draw(st.sampled_from([[node], {"x": node}, str(node), None, 1])))
        elif op == "add" and isinstance(node, dict):
            node[draw(st.sampled_from(HOSTILE_NAMES + ["description", "sweep", "move"]))] = draw(ANY_VALUE)
    return name, tree


def names_in(tree: dict) -> list[str]:
    """The names of the model's points, bodies and parameters."""
    return [n for section in ("points", "bodies", "parameters") for n in (tree.get(section) or {})
            if isinstance(n, str)]


def renamed(tree: dict, new: str, everywhere: bool = True, old: str | None = None) -> dict:
    """A point, body or parameter (`old`, else the longest name) renamed to `new`:
    everywhere it is written (the same model under another name: its answers must not
    change), or in its definition only."""
    names = names_in(tree)
    if not names:
        return tree
    old = old if old is not None else sorted(names, key=len)[-1]
    if not everywhere:
        for section in ("points", "bodies", "parameters"):
            items = tree.get(section)
            if isinstance(items, dict) and old in items:
                items[new] = items.pop(old)
                return tree
    return rename(tree, old, new)


def rename(node: Any, old: str, new: str) -> Any:
    """Every occurrence of the name `old` (alone, or as either side of `P@body`) as `new`;
    names inside expressions too when the name is a parameter's (whole identifiers only)."""
    import re

    word = re.compile(r"(?<![\w])" + re.escape(old) + r"(?![\w])")

    def text(s: str) -> str:
        if s == old:
            return new
        if "@" in s:
            return "@".join(new if part == old else part for part in s.split("@"))
        return word.sub(lambda m: new, s) if new.isidentifier() else s

    if isinstance(node, dict):
        return {(text(k) if isinstance(k, str) else k): rename(v, old, new) for k, v in node.items()}
    if isinstance(node, list):
        return [rename(v, old, new) for v in node]
    return text(node) if isinstance(node, str) else node


# files that are not models -----------------------------------------------------------------
def alias_bomb(levels: int, width: int, where: str = "description") -> str:
    lines = [f'  - &a0 [{", ".join(["lol"] * width)}]']
    lines += [f'  - &a{i} [{", ".join([f"*a{i - 1}"] * width)}]' for i in range(1, levels)]
    return f"{where}:\n" + "\n".join(lines) + f"\nname: *a{levels - 1}\npoints: {{O: [0, 0]}}\n"


HOSTILE_FILES = {
    "alias_bomb.yaml": alias_bomb(9, 9),
    "alias_bomb_key.yaml": alias_bomb(8, 8) + "bodies: {? *a7 : [O]}\n",
    "recursive_alias.yaml": "points: &p {O: [0, 0], P: *p}\n",
    "undefined_alias.yaml": "points: *nowhere\n",
    "deep_list.yaml": "points: " + "[" * 30000 + "]" * 30000 + "\n",
    "deep_map.yaml": "points: " + "{a: " * 20000 + "1" + "}" * 20000 + "\n",
    "deep.json": "[" * 200000 + "]" * 200000,
    "deep.toml": "a = " + "[" * 5000 + "]" * 5000 + "\n",
    "long_int.yaml": "points: {O: [" + "9" * 100000 + ", 0]}\n",
    "hex_int.yaml": "points: {O: [0x" + "f" * 100000 + ", 0]}\n",
    "long_int.toml": "[points]\nO = [0x" + "f" * 100000 + ", 0]\n",
    "python_tag.yaml": "points: !!python/object/apply:os.system ['touch pwned']\n",
    "binary.yaml": "points: !!binary aGVsbG8=\n",
    "set.yaml": "points: !!set {a, b}\n",
    "timestamp_names.yaml": "points: {2001-12-14: [0, 0]}\nbodies: {ground: [2001-12-14]}\n",
    "merge.yaml": "base: &b {O: [0, 0]}\npoints: {<<: *b, A: [1, 0]}\n",
    "two_docs.yaml": "points: {}\n---\npoints: {}\n",
    "nul.yaml": "points: {O: [0,\x00 0]}\n",
    "bom_utf16.json": "\ufeff{}".encode("utf-16").decode("latin-1"),
    "bad_utf8.yaml": "points: {\xff\xfe: [0, 0]}\n",
    "surrogate.json": '{"name": "\\ud800", "points": {"\\udfff": [0, 0]}}',
    "control.yaml": "name: \"\\e]0;owned\\a\\e[2J\"\npoints: {O: [0, 0]}\n",
    "crlf.yaml": "points:\r\n  O: [0, 0]\r\n",
    "tabs.yaml": "points:\n\tO: [0, 0]\n",
    "only_comments.yaml": "# nothing\n# here\n",
    "empty.json": "",
    "not_a_mapping.yaml": "- 1\n- 2\n",
    "scalar.json": "3",
    "huge_float.yaml": "points: {O: [1.0e400, 0]}\n",
    "nan.yaml": "points: {O: [.nan, 0]}\n",
    "many_keys.yaml": "points: {" + ", ".join(f"p{i}: [{i}, 0]" for i in range(20000)) + "}\n",
    "dup_keys.yaml": "points: {O: [0, 0], O: [1, 0]}\n",
    "dup_keys.json": '{"points": {"O": [0, 0], "O": [1, 0]}}',
}
