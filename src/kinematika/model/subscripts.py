"""A body's subscript in the symbols (ω_roda, v_B∈plat, α_M) when the model's notation gives
it no index: read off the body's name in the page's language, as the course notes write
their symbols (the slides' ω_N for "N elementua", the C5 chapter's Ω^roda, Ω^plat,
Ω^{roda sup}, Ω^{roda1}), never the body's number in the file (ω_6 for pulley 3).

The rule, for each body of a model that names its bodies in the language:

1. a code in the name (a capital and up to three capitals or digits: the N of "element N",
   the S1 of "xassís S1", the OQ of "barra OQ") that no other body's name holds is the
   subscript: ω_N, ω_S1, ω_OQ;
2. else the word the name is about (past its article and the language's small words; the
   first thing of "el plat i els pedals"): the first word in Catalan and Spanish, the last
   in English, the first not ending in -ko in Basque), when no other body's is that word:
   ω_braç, ω_plat, ω_koroa, ω_wheel, ω_gurpila; but on a page where wheels mesh with
   wheels (wheels in mesh: `wording.meshed`), the word "wheel" (roda, rueda, gurpil) does
   not tell a meshing wheel from the others, so the name's other word is taken when it
   has one: the sun wheel beside the planets is ω_sun (ca roda central: ω_central), E.2's
   fixed central wheel ω_central, never ω_wheel;
3. else that word with the name's number or its code (politja 1 -> politja1, "1. polea" ->
   polea1, "roda de radi R" -> rodaR as the notes' Ω^{rodaR}, where the code R alone is a
   parameter's name: `named_labels`' `parameters`);
4. else (a name of several words whose word clashes with another body's, and that holds no
   number or code of its own) that word with the body's rank among the bodies named by the
   same word, in the notes' numbering: *left wheel* and *right wheel* are ω_wheel1 and
   ω_wheel2, *ezkerreko gurpila* and *eskuineko gurpila* ω_gurpila1 and ω_gurpila2, *la
   politja fixa* and *la politja mòbil* ω_politja1 and ω_politja2 (a rank another body's
   subscript holds is skipped). A teacher writes a short index on the board and declares it
   once (the page's notation line under the structure: `render.base.Renderer.subscripts`),
   never "v_{J∈ezkerreko kable-zatia}" or "ω_{ezkerreko gurpila rel txasisa}", a subscript of
   words with spaces (issue 30, twenty-seventh round (g), a Basque teacher); ω_gurpila1 is
   the style of the pages whose names hold a number (*1. gurpila*).

A body the language does not name is written by the model's own name when that is a plain
word (ground, carrier), else by its number; so is any body whose subscript would still be
another's. A model that names no body in the language keeps the numbers (ω_3, as its
figures' numbering).
"""
from __future__ import annotations

import re
from typing import Optional

# the small words a subscript leaves out, per language (the article is stripped first), and
# the words that join two things in one name (el plat i els pedals): the subscript is the first's
SMALL_WORDS = {"ca": {"de", "del", "dels", "d", "el", "la", "els", "les", "l", "a"},
               "es": {"de", "del", "el", "la", "los", "las", "a"},
               "en": {"of", "the", "a", "an"},
               "eu": set()}
# the word for a wheel, per language: no subscript among meshing wheels (rule 2)
WHEEL_WORDS = {"en": {"wheel"}, "ca": {"roda"}, "es": {"rueda"}, "eu": {"gurpil", "gurpila"}}
JOINING = {"ca": {"i", "amb"}, "es": {"y", "con"}, "en": {"and", "with", "of"}, "eu": {"eta"}}
CODE = re.compile(r"^[A-Z][A-Z0-9]{0,3}$")           # N, S1, OQ, O1A
NUMBER = re.compile(r"^\d+\.?$")                      # 1 (satèl·lit 1), 1. (1. satelitea)
PLAIN_ID = re.compile(r"^[A-Za-z][A-Za-z0-9]{0,11}$")  # a model's own name fit for a subscript
ARTICLE = re.compile(r"(?i)^(?:(?:els|les|el|la|los|las)\s+|l['’]\s*)")


def _words(name: str) -> list[str]:
    """The name's words past its article."""
    text = ARTICLE.sub("", name.strip(), count=1)
    return [w.strip(",;:()") for w in re.split(r"\s+", text) if w.strip(",;:()")]


def read_off(label: str, name: str, lang: Optional[str]) -> bool:
    """Whether subscript `label` is body `name` run together, every word of it, so a student
    reads it off the name and a legend saying so is a line a teacher deletes (fifteenth
    round): each word of the name (past its article and the language's small words, de, of)
    once, in any order, a number without the Basque ordinal's dot (politja1 for *politja 1*,
    polea1 for *1. polea*, ω_{roda esquerra}), in Basque a word with its article too
    (platera for *plater pedalduna*'s *plater*... only when every word is there). A subscript
    that keeps only some of the name's words is shortened (sixteenth round: central for *roda
    central*, plat for *plat amb els pedals*, rodaR for *roda de radi R*): the reader cannot
    tell which body it is until the page says so. An abbreviation or a symbol from the notes
    (ψ̇) is not read off either."""
    small = SMALL_WORDS.get(lang or "", set())
    words = [w.rstrip(".") for w in _words(name)]
    words = [w for w in words if w and w.lower().replace("’", "'").split("'")[-1] not in small]
    text = label.replace(" ", "")
    if not text or not words or len(words) > 6:
        return False

    def forms(w: str) -> set[str]:
        return {w, w + "a"} if lang == "eu" else {w}

    def match(rest: str, left: tuple[str, ...]) -> bool:
        if not left:
            return not rest
        return any(rest.startswith(f) and match(rest[len(f):], left[:k] + left[k + 1:])
                   for k, w in enumerate(left) for f in forms(w))
    return match(text, tuple(words))


def _head(content: list[str], lang: str) -> str:
    """The word a name is about: the first in Catalan and Spanish (roda esquerra), the last
    in English (left wheel), the first not ending in -ko in Basque (ezkerreko gurpila,
    polea finkoa), a Basque stem before the declined last word with its article (gurpil
    zentrala -> gurpila)."""
    if lang == "en":
        return content[-1]
    if lang == "eu":
        head = next((w for w in content if not w.endswith("ko")), content[-1])
        return head if head is content[-1] or head.endswith("a") else head + "a"
    return content[0]


def _candidates(name: str, lang: str) -> tuple[list[str], list[str]]:
    """(codes, subscripts in the rule's order) of one name."""
    small, joining = SMALL_WORDS.get(lang, set()), JOINING.get(lang, set())
    words = _words(name)
    cut = next((k for k, w in enumerate(words) if w.lower() in joining), len(words))
    codes = [w for w in words if CODE.match(w)]
    first = words[:cut]
    numbers = [w.rstrip(".") for w in first if NUMBER.match(w)]
    content = [w for w in first if not NUMBER.match(w) and not CODE.match(w)
               and w.lower().replace("’", "'").split("'")[-1] not in small]
    if not content:
        return codes, []
    head = _head(content, lang)
    number = numbers[0] if len(numbers) == 1 else ""
    out = [head]
    if number:
        out.append(head + number)
    elif len(codes) == 1:              # roda de radi R -> rodaR, the notes' Ω^{rodaR}
        out.append(head + codes[0])
    return codes, out


def _modifier(name: str, lang: str) -> str:
    """The word a wheel's name is about once its word for a wheel is left out (sun wheel ->
    sun, roda central -> central, gurpil zentrala -> zentrala), '' when it has no other."""
    small, joining, wheel = SMALL_WORDS.get(lang, set()), JOINING.get(lang, set()), WHEEL_WORDS.get(lang, set())
    words = _words(name)
    words = words[:next((k for k, w in enumerate(words) if w.lower() in joining), len(words))]
    content = [w for w in words if not NUMBER.match(w) and not CODE.match(w)
               and w.lower().replace("’", "'").split("'")[-1] not in small]
    if not any(w.lower() in wheel for w in content):
        return ""
    rest = [w for w in content if w.lower() not in wheel]
    return _head(rest, lang) if rest else ""


def _ranked(free: list[str], found: dict, out: dict[str, str], taken: set,
            spelt: dict[str, str]) -> dict[str, str]:
    """Rule 4: each body of `free` (in the notes' numbering) left without a subscript whose
    name has a word (`found[b][1][0]`, the word rule 2 took and another body's name shares)
    gets that word with its rank among such bodies of the same word: wheel1, wheel2. A
    subscript already given (`out`), reserved (`taken`) or that another body's rule 3 reads
    off its own name (gurpila1 for *1. gurpila*) is skipped: the next rank is taken. Two
    bodies called alike (*la roda* twice) keep their numbers: no name tells them apart, so
    no legend could say which is roda1."""
    used = set(taken) | set(out.values())
    held = {w for b in free for w in found[b][1][1:]}
    rank: dict[str, int] = {}
    ranked: dict[str, str] = {}
    for b in free:
        if b in out or not found[b][1] or any(o != b and spelt[o] == spelt[b] for o in free):
            continue
        head = found[b][1][0]
        k = rank.get(head, 1)
        while f"{head}{k}" in used or (f"{head}{k}" in held and f"{head}{k}" not in found[b][1]):
            k += 1
        ranked[b] = f"{head}{k}"
        used.add(ranked[b])
        rank[head] = k + 1
    return ranked


def named_labels(order: list[str], names: dict[str, str], lang: Optional[str],
                 given: dict[str, str], parameters: Optional[set] = None,
                 wheels: frozenset = frozenset()) -> dict[str, str]:
    """Each body's subscript by the rule above: `order` the bodies in the notes' numbering
    (the frame first), `names` body -> its name in `lang` (empty: numbers), `given` the
    bodies the model's notation indexes (kept, and never reused), `parameters` names a
    body's subscript must not take: a body's symbol never equals a length's (ω_R beside the
    radius R reads as the radius' rate), so its name's next word is taken (ω_roda); `wheels`
    the bodies that mesh with wheels, whose word for a wheel is no subscript (rule 2)."""
    numbers = {b: str(k) for k, b in enumerate(order, start=1)}
    if not names:
        return {b: given.get(b, numbers[b]) for b in order}
    lang = lang or "en"
    free = [b for b in order if b not in given]
    spelt = {b: names.get(b, "") for b in free}
    found = {b: _candidates(spelt[b], lang) if spelt[b] else ([], []) for b in free}
    taken = set(given.values()) | set(parameters or ())
    out: dict[str, str] = {}
    code_count: dict[str, int] = {}
    for codes, _ in found.values():
        for c in set(codes):
            code_count[c] = code_count.get(c, 0) + 1
    for b in free:
        codes, words = found[b]
        unique_codes = [c for c in codes if code_count[c] == 1 and c not in taken]
        if unique_codes:
            out[b] = unique_codes[0]
            continue
        others = [w for o in free if o != b for w in found[o][1][:1]]
        for level, w in enumerate(words):
            clash = w in others if level == 0 else any(w in found[o][1] for o in free if o != b)
            if not clash and w not in taken:
                other = _modifier(spelt[b], lang) if level == 0 and b in wheels else ""
                out[b] = other if other and other not in taken and other not in others else w
                break
        else:
            if not spelt[b] and PLAIN_ID.match(b):
                out[b] = b
    out.update(_ranked(free, found, out, taken, spelt))
    labels = {**{b: given[b] for b in given if b in numbers}, **out}
    written: dict[str, list[str]] = {}
    for b, t in labels.items():
        written.setdefault(t, []).append(b)
    return {b: labels[b] if b in labels and len(written[labels[b]]) == 1 else numbers[b] for b in order}
