"""Message catalogues: every word of an explanation, per language, in locales/LANG.ftl.

The catalogues are Project Fluent files (`fluent.runtime`, CLDR plural rules through
Babel): a message names its variables (`{ $body }`), and a translation chooses its own
wording with selectors, so plurals (`{ $n -> [one] … *[other] … }`), Catalan elision
(`{ ELISION($point) -> [vowel] d’{ $point } *[other] de { $point } }`) and Basque case
endings (on a classifier noun, `{ $known } solidotik` / `solidoetatik`) live in the
catalogue, not in code. The code holds keys only (`sec.data` is the Fluent id
`sec-data`). See docs/explain.md for why Fluent rather than gettext.
"""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable, cast

from fluent.runtime import FluentBundle, FluentResource
from fluent.runtime.types import FluentType

from ..errors import KinematikaError
from ..languages import LANGS, known
from ..model.wording import ARTICLES

__all__ = ["LANGS", "LOCALES", "catalogue", "known"]

LOCALES = Path(__file__).resolve().parent / "locales"
VARIABLE = re.compile(r"\{\s*\$(\w+)")
# the letters Catalan elides "de" and "el/la" before, as the Catalan notes write a symbol: the
# vowels (a point named O4 is read "o quatre": d'O4, l'O4), never a consonant whose letter's
# name happens to begin with a vowel (efa, erra, essa …): the notes write "respecte de R",
# "fixa a R", and a page that elided d'S1 beside the model's own "de S1" wrote one name two ways
# (issue 30, twenty-eighth round (e): C5-2.2's "de S1" ×8, "d'S1" ×2)
VOWEL_LETTERS = set("AEIOU")
# the renderers set the article a model's name begins with (model.wording.ARTICLES) as text, so the
# contractions of a preposition with it apply (de el portador -> del portador)
CONTRACTIONS = {
    "ca": [(re.compile(r"\b([Dd])e el(s?) "), r"\1el\2 "), (re.compile(r"\b([Aa]) el(s?) "), r"\1l\2 "),
           (re.compile(r"\b([Pp])er el(s?) "), r"\1el\2 ")],
    "es": [(re.compile(r"\b([Dd])e el "), r"\1el "), (re.compile(r"\b([Aa]) el "), r"\1l ")],
}


def fluent_id(key: str) -> str:
    """The Fluent identifier of a code key: dots become dashes."""
    return key.replace(".", "-")


def elision(value: Any) -> str:
    """`vowel` when a name is read with an initial vowel sound (Catalan elides before it).

    Symbols (a capital letter, maybe with digits or primes: A, O4, AB) elide when their
    first letter is a vowel (`VOWEL_LETTERS`: the notes' "de R", "de P", "d'O"); words elide
    before a vowel or an h.
    """
    text = str(getattr(value, "plain", value)).strip()
    if not text or ARTICLES["ca"].match(text):
        return "other"          # a name with its article (el portador, l’engranatge): no elision
    first = text[0]
    symbol = first.isupper() and (len(text) == 1 or not text[1].islower())
    if symbol:
        return "vowel" if first in VOWEL_LETTERS else "other"
    return "vowel" if first.lower() in "aeiouàèéíòóúh" else "other"


PLURAL_NAME = re.compile(r"(?i)^(els|les|los|las) |\s(i|y|and|eta)\s")


def count(value: Any) -> str:
    """`many` when a name stands for several things and a verb after it is plural: a list of
    names, a name with a plural article (els pedals, les rodes, los dientes) or two names
    joined by "and" (el plat i els pedals), or one the renderer found plural (`many`: an
    English name, which has no article to tell, `Renderer.plural`); else `one`."""
    if getattr(value, "n_names", 1) > 1 or getattr(value, "many", False):
        return "many"
    text = str(getattr(value, "plain", value)).strip()
    return "many" if PLURAL_NAME.search(text) else "one"


# the word "fixed" in a name, in the four languages (the fixed cylinder, el cilindro fijo,
# la politja fixa, zilindro finkoa)
FIXED_WORD = re.compile(r"(?i)\b(fixed|fij[oa]s?|fix[ae]?s?|finko\w*)\b")


def says_fixed(value: Any) -> str:
    """`yes` when a body's name already says it is fixed (C5-1.8's *fixed cylinder*): a
    sentence then does not add "which is fixed" after it; else `no`."""
    return "yes" if FIXED_WORD.search(str(getattr(value, "plain", value))) else "no"


FEMININE_ARTICLE = re.compile(r"(?i)^(la|las|una|unas) ")


def gender(value: Any) -> str:
    """`f` when a Spanish name is feminine by its article (la polea, las ruedas) and is one
    name, for a participle that agrees with it (fijada, fijadas); else `m` (a list takes the
    masculine, as Spanish does when any of its names is masculine, and most lists here are)."""
    if getattr(value, "n_names", 1) > 1:
        return "m"
    return "f" if FEMININE_ARTICLE.match(str(getattr(value, "plain", value)).strip()) else "m"


def word(value: Any) -> str:
    """The word a select expression matches when a variable is a word, not a name (the
    quantity a sentence is about: `{ WORD($kind) -> [accel] … *[speed] … }`): the renderer
    hands every non-number to Fluent as a token, which no key matches, so the select reads
    the token's plain text."""
    return str(getattr(value, "plain", value))


# a leading article in the four languages, which a name's comparison with another leaves out
LEADING_ARTICLE = re.compile(r"(?i)^(the|el|la|els|les|los|las|l[’'])\s*")


def same(first: Any, second: Any) -> str:
    """`yes` when the name `first` already says the ground's word `second`, once their articles
    are left out: the same word (a frame the model calls *el suelo* and the ground's word the
    text uses for the reference, el *suelo*) or one word of it (C5-1.8's Catalan *terra
    cilíndric*, a *cylindrical ground*). The frame's row then needs no tie to the ground's word,
    "(fixed: the *ground*)" or "*terra cilíndric* (*terra*)", which would only repeat it
    (twenty-second round b, decided per language: C5-1.4 calls its frame *bastidor* in Spanish
    only; twenty-fourth round a: the word inside the name); else `no`."""
    def bare(value: Any) -> str:
        return LEADING_ARTICLE.sub("", str(getattr(value, "plain", value)).strip()).casefold()
    name, word = bare(first), bare(second)
    held = bool(word) and re.search(rf"(?<![\w·-]){re.escape(word)}(?![\w·-])", name) is not None
    return "yes" if name == word or held else "no"


# fluent.runtime (0.4) annotates a function as returning a FluentType, but its resolver takes a plain
# str too (resolver.match compares a select's key with ==, resolve() passes a str through): ours
# return the word a select expression matches, so the cast only states what the resolver accepts.
FUNCTIONS = cast(dict[str, Callable[[Any], FluentType]], {"ELISION": elision, "COUNT": count,
                                                          "FIXED": says_fixed, "WORD": word,
                                                          "GENDER": gender, "SAME": same})


class Catalogue:
    """The messages of one language."""

    def __init__(self, lang: str, source: str) -> None:
        self.lang = lang
        self.source = source
        self.bundle = FluentBundle([lang], functions=FUNCTIONS, use_isolating=False)
        self.bundle.add_resource(FluentResource(source))

    def keys(self) -> list[str]:
        """The Fluent ids of the catalogue's messages, in file order."""
        return re.findall(r"^([A-Za-z][\w-]*)\s*=", self.source, re.M)

    def has(self, key: str) -> bool:
        """Whether the catalogue has message `key` (a dotted key, as the document writes it)."""
        return self.bundle.has_message(fluent_id(key))

    def format(self, key: str, args: dict[str, Any] | None = None) -> str:
        """The message `key` with its variables filled (strings or numbers)."""
        if not self.has(key):
            raise KinematikaError("schema", "catalogue-no-message", "explain", key=key, lang=self.lang)
        message = self.bundle.get_message(fluent_id(key))
        assert message.value is not None, f"{self.lang}: {key} has attributes only"     # none in the catalogues
        text, errors = self.bundle.format_pattern(message.value, args or {})
        if errors:
            raise KinematikaError("schema", "catalogue-message-error", "explain", key=key, lang=self.lang,
                                  problem=str(errors[0]))
        assert isinstance(text, str), f"{self.lang}: {key}"      # FluentNone comes with an error, raised above
        return text

    def get(self, key: str) -> str:
        """A message without variables (a word such as a subscript)."""
        return self.format(key)


@lru_cache(maxsize=None)
def catalogue(lang: str) -> Catalogue:
    """The catalogue of `lang` (one of LANGS), read once."""
    return Catalogue(known(lang), (LOCALES / f"{lang}.ftl").read_text(encoding="utf-8"))
