"""The languages kinematika speaks (explanations, figures' numbers, the page, errors and
warnings): their codes, the check of a code given by a user, and the language a command
line's messages are said in (its `--lang`, else the environment's locale)."""
from __future__ import annotations

from typing import Mapping, Sequence

from .errors import KinematikaError

LANGS = ("en", "es", "ca", "eu")


def known(lang: str, where: str = "--lang", kind: str = "schema") -> str:
    """`lang` when it is one of LANGS, else the one-line error of `kind` naming its place
    `where` (an option, a model's key such as ``names.fr``, a request's field)."""
    if lang not in LANGS:
        raise KinematikaError(kind, "unknown-language", where, lang=lang, langs=list(LANGS))
    return lang


LOCALE_VARIABLES = ("LC_ALL", "LC_MESSAGES", "LANG")     # POSIX's order: the first one set decides


def from_locale(environ: Mapping[str, str]) -> str:
    """The language of a locale such as the environment's (`eu_ES.UTF-8` → eu, `ca_ES@valencia`
    → ca): the first of LC_ALL, LC_MESSAGES, LANG that is set and not empty decides, as POSIX
    has it; a language kinematika does not speak, `C` or `POSIX` is English."""
    for name in LOCALE_VARIABLES:
        value = environ.get(name, "")
        if value:
            code = value.split(".")[0].split("@")[0].split("_")[0].split("-")[0].lower()
            return code if code in LANGS else "en"
    return "en"


def from_command_line(argv: Sequence[str], environ: Mapping[str, str]) -> str:
    """The language a command line's errors and warnings are said in: its `--lang` (`--lang eu`
    or `--lang=eu`, when it is one of LANGS; a wrong value is then the command's own `usage`
    error, said in the locale's language), else the locale's (`from_locale`)."""
    for i, arg in enumerate(argv):
        if arg == "--":
            break
        value = argv[i + 1] if arg == "--lang" and i + 1 < len(argv) else arg[7:] if arg.startswith("--lang=") else None
        if value in LANGS:
            return value
    return from_locale(environ)
