"""How a model's things are called and written, per language: what the explanations and
figures say, and nothing else reads (the answers keep the model's own names).

    names:                                # per language (en, es, ca, eu)
      ca:
        title: Transmissió epicicloidal
        bodies: {carrier: el portador, sun: la roda central, ring: la corona}
        points: {A1: centre de la primera rodeta}
        joints: {hub: boixa}               # a joint's id, as the text names it
        parameters: {r: radi de la roda central}   # what a parameter is (the Data section)
        data: ["Aquí es pren aquesta geometria: …"]   # statements of the Data section
        notes: ["Els apunts donen …; el correcte és … perquè …"]
    notation:                             # how a quantity is written (sympy's spelling)
      w0: omega_0                         # a parameter: ω₀
      vd: vdot                            # v̇
      omega(block): omega_1               # ω of a body (relative to the frame): ω₁
      omega(blades/block): omega_2        # relative to another body: ω₂
      omega(blades): {eu: omega_aspak, ca: omega_aspes}   # per language
      index(wheel1): "1"                  # a body's index in every symbol (ω_1, v_B∈1, I_12)
      spin(j3): {symbol: phidot, radius: r}   # a knife-edge wheel's spin: φ̇ = v·e / r

A written symbol is a name as sympy reads one (`omega_0` ω₀, `vdot` v̇, `R_roda`), so every
format (HTML, Markdown, LaTeX, the figures' mathtext) sets it as it sets the model's own
names. Checked here, once, with the place named.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Optional

from ..errors import KinematikaError, Names
from ..languages import known             # the explanations' languages (each has a catalogue)

# the articles a name may begin with in Catalan and Spanish (`names.ca.bodies: {carrier: el
# portador}`): texts contract them with a preposition (del portador), figures leave them out.
# English names are written without one (`wheel`): the explanation's text supplies "the"
# (render.base.SUPPLIED_ARTICLE), as a Catalan or Spanish model's name carries its own
ARTICLES = {"ca": re.compile(r"(?i)(els|les|el|la) |l['’]"), "es": re.compile(r"(?i)(los|las|el|la) "),
            "en": re.compile(r"(?i)the ")}
NO_ARTICLE = re.compile(r"(?!)")
# the subscripts of a motion's parts as each language writes them (v_rel, v_arr,B, a_Cor):
# the explanations' symbols and the figures' labels read them here (one place for both)
# sub.rel names the relative motion's term (the notes' v_REL, Ω_REL: REL is the moving frame);
# sub.rel_to joins a body to the one it is seen from (ω_{politja fixa rel. braç}). In Catalan
# they differ: the notes keep REL (upper case) for the moving frame's name, so REL never joins
# two names, where it would read as a third body; the join is "rel" (relatiu a), the notes'
# word in lower case — not "resp.", which a reader takes for "respectivament", and never a
# slash, which reads as a division. Without a full stop, as the slides (seed 001: v_{B∈N rel
# M}) and the other languages write it: "rel" on one page and "rel." on the next read as two
# notations (twenty-fourth round (c)).
# Basque writes rel, as its slides (seed 001: v_rel, a_rel, 2 ω × v_rel), not erl.
PART_SUBSCRIPTS = {"sub.rel": {"en": "rel", "es": "rel", "ca": "REL", "eu": "rel"},
                   "sub.rel_to": {"en": "rel", "es": "rel", "ca": "rel", "eu": "rel"},
                   "sub.drag": {"en": "drag", "es": "arr", "ca": "ar", "eu": "arr"},
                   "sub.cor": {"en": "Cor", "es": "Cor", "ca": "Cor", "eu": "cor"}}
# the Basque slides (4.2) write the composition a_B = a_arr + a_rel + a_cor: their word, lower case

# the superscripts of an acceleration's normal and tangential components (a_BA^n, a_BA^t), as
# each course writes them: the Basque slides (seed 001, 4.2) write a_BA^N and a_BA^T, and keep
# D for a known direction so that N is free for the normal ("Norabidea adierazteko D erabiliko
# da, N hizkia normala adierazi behar denean erabili ahal izateko"); the Catalan notes write
# a_T^n (seed 002), as English and Spanish texts do. One place for the equations, the lists of
# terms and the polygons' labels (`Renderer.noted`; issue 30, twenty-seventh round (g))
COMPONENT_SUPERSCRIPTS = {"n": {"eu": "N"}, "t": {"eu": "T"}}


def component_superscript(sup: str, lang: Optional[str]) -> str:
    """A symbol's superscript as `lang` writes it: a normal or tangential component's (n, t)
    in the course's letter (Basque N, T), any other (geom, a model's own) as it is."""
    return COMPONENT_SUPERSCRIPTS.get(sup, {}).get(lang or "en", sup)


# a screw axis as a figure labels it, in each course's words (the Catalan notes' EIRL, eix
# instantani de rotació i lliscament; the Spanish EIR; the Basque ardatz instantaneoa)
SCREW_AXIS = {"en": "ISA", "es": "EIR", "ca": "EIRL", "eu": "ardatz instantaneoa"}


def part_subscript(key: str, lang: Optional[str]) -> str:
    """The subscript `key` (sub.rel, sub.drag, sub.cor) in `lang` (English when None)."""
    words = PART_SUBSCRIPTS[key]
    return words.get(lang or "en", words["en"])


# patterns compiled where first used (`re`'s cache): most models have no `names:` or `notation:`
RATE = r"^(omega|alpha)\((.+)\)$"
SPELLING = r"^[A-Za-z][A-Za-z0-9_]*$"      # a name sympy writes as a symbol
INDEX_KEY = r"^index\((.+)\)$"                # notation: index(BODY): N
SPIN_KEY = r"^spin\((.+)\)$"                  # notation: spin(JOINT): {symbol, radius}
CONTACT_KEY = r"^contact\((.+)\)$"            # notation: contact(JOINT): NAME
INDEX = r"^[A-Za-z0-9]{1,4}$"                 # a body's index as the notes write it
RELATIVE_WORD = r"^[A-Za-z]{1,6}\.?$"          # notation: relative: rel


@dataclass
class Wording:
    """Titles, body names, point descriptions and notes per language, and the notation."""

    titles: dict[str, str] = field(default_factory=dict)
    bodies: dict[str, dict[str, str]] = field(default_factory=dict)     # lang -> body -> name
    points: dict[str, dict[str, str]] = field(default_factory=dict)     # lang -> point -> text
    joints: dict[str, dict[str, str]] = field(default_factory=dict)     # lang -> joint id -> name
    parameters: dict[str, dict[str, str]] = field(default_factory=dict)  # lang -> parameter -> what it is
    data: dict[str, list[str]] = field(default_factory=dict)            # lang -> statements of the data
    notes: dict[str, list[str]] = field(default_factory=dict)           # lang -> notes
    indices: dict[str, dict[str, str]] = field(default_factory=dict)    # body -> lang|"*" -> its index
    spins: dict[str, tuple[str, str]] = field(default_factory=dict)     # wheel joint -> (symbol, radius)
    contacts: dict[str, str] = field(default_factory=dict)              # rolling joint -> its contact's name
    symbols: dict[str, dict[str, str]] = field(default_factory=dict)    # key -> lang|"*" -> name
    wheels: frozenset = frozenset()                                     # bodies that mesh with a wheel (`meshed`)
    relative: dict[str, str] = field(default_factory=dict)              # lang|"*" -> the word of v_{P∈b rel a}

    def relative_word(self, lang: Optional[str]) -> str:
        """The word joining a body to the one it is seen from, v_{B∈N rel M}, ω_{b rel a}: the
        model's `notation: {relative: WORD}` (the notes' own, rel or REL), else the
        language's (`PART_SUBSCRIPTS['sub.rel_to']`). One word a page, so that the step, the
        composition of motions and the answers write one relative vector alike."""
        return self.relative.get(lang or "", self.relative.get("*", part_subscript("sub.rel_to", lang)))

    def title(self, lang: str, default: str) -> str:
        """The model's title in `lang`, else `default` (its `name`)."""
        return self.titles.get(lang, default)

    def body(self, name: str, lang: Optional[str]) -> str:
        """The body's name in `lang` (the model's own when the model gives none)."""
        return self.bodies.get(lang or "", {}).get(name, name)

    def joint(self, name: str, lang: Optional[str]) -> str:
        """A joint's name in `lang` (its id when the model gives none)."""
        return self.joints.get(lang or "", {}).get(name, name)

    def point(self, name: str, lang: Optional[str]) -> str:
        """What the point is, in `lang` ('' when the model does not say)."""
        return self.points.get(lang or "", {}).get(name, "")

    def parameter(self, name: str, lang: Optional[str]) -> str:
        """What the parameter is, in `lang` ('' when the model does not say)."""
        return self.parameters.get(lang or "", {}).get(name, "")

    def index(self, body: str, lang: Optional[str]) -> Optional[str]:
        """The body's index as the notes write it (`notation: index(BODY)`), None when the
        model gives none (the body is numbered)."""
        spelt = self.indices.get(body)
        return None if spelt is None else spelt.get(lang or "", spelt.get("*"))

    def labels(self, order: list[str], lang: Optional[str], reserved: tuple = ()) -> dict[str, str]:
        """Each body of `order` (the notes' numbering, the frame first) as the symbols write it
        in `lang`: its index (`index`), else a subscript read off its name in `lang`
        (`subscripts.named_labels`: ω_roda, ω_{roda sup}), else its number. A name read off
        never equals a parameter's (`reserved`, and those the wording describes): C5-E.5's
        "roda de radi R" is not ω_R beside the radius R (ω_R = −v/R), it is ω_roda."""
        from .subscripts import named_labels

        given = {b: i for b in order if (i := self.index(b, lang)) is not None}
        params = set(reserved) | {k for described in self.parameters.values() for k in described}
        return named_labels(order, self.bodies.get(lang or "", {}), lang, given, params, self.wheels)

    def symbol(self, key: str, lang: Optional[str]) -> Optional[str]:
        """How `key` is written in `lang`: a parameter's name, or `omega(body)`,
        `omega(body/other)`, `alpha(…)`; None when the model does not say."""
        spelt = self.symbols.get(key)
        if spelt is None:
            return None
        return spelt.get(lang or "", spelt.get("*"))

    def parameter_symbols(self, lang: Optional[str]) -> dict[str, str]:
        """parameter name -> its written name, for the parameters the notation spells."""
        out = {}
        for key in self.symbols:
            if not re.match(RATE, key):
                spelt = self.symbol(key, lang)
                if spelt:
                    out[key] = spelt
        return out


def noun(name: str, lang: Optional[str] = None) -> str:
    """A name without its article (el portador -> portador), for a figure's label or a table."""
    for code, pattern in ARTICLES.items():
        m = pattern.match(name)
        if m and m.end() < len(name) and lang in (None, code):
            return name[m.end():]
    return name


def read_wording(names: Any, notation: Any, bodies: dict, points: dict, parameters: dict,
                 default_title: str, joints: Optional[dict] = None, frame: str = "ground") -> Wording:
    """The checked `names:` and `notation:` sections (either may be None)."""
    out = Wording(wheels=meshed(joints or {}, bodies))
    for lang, spec in (names or {}).items():
        where = f"names.{lang}"
        _language(lang, where)
        if spec.title is not None:
            out.titles[lang] = _text(spec.title, f"{where}.title")
        out.bodies[lang] = {_known(b, bodies, "body", f"{where}.bodies"): _text(t, f"{where}.bodies.{b}")
                            for b, t in (spec.bodies or {}).items()}
        out.points[lang] = {_known(p, points, "point", f"{where}.points"): _text(t, f"{where}.points.{p}")
                            for p, t in (spec.points or {}).items()}
        out.joints[lang] = {_known(j, joints or {}, "joint", f"{where}.joints"): _text(t, f"{where}.joints.{j}")
                            for j, t in (spec.joints or {}).items()}
        out.parameters[lang] = {_known(p, parameters, "parameter", f"{where}.parameters"):
                                _text(t, f"{where}.parameters.{p}") for p, t in (spec.parameters or {}).items()}
        out.data[lang] = [_text(t, f"{where}.data[{i}]") for i, t in enumerate(spec.data or [])]
        out.notes[lang] = [_text(t, f"{where}.notes[{i}]") for i, t in enumerate(spec.notes or [])]
    for raw, spelt in (notation or {}).items():
        where = f"notation.{raw}"
        spin = re.match(SPIN_KEY, raw.strip())
        if spin is not None:
            out.spins[_spin_joint(spin.group(1).strip(), joints or {}, where)] = _spin(spelt, parameters, where)
            continue
        contact = re.match(CONTACT_KEY, raw.strip())
        if contact is not None:
            out.contacts[_contact_joint(contact.group(1).strip(), joints or {}, where)] = _index(spelt, where,
                                                                                                "contact-name-shape")
            continue
        index = re.match(INDEX_KEY, raw.strip())
        if index is not None:
            b = _known(index.group(1).strip(), bodies, "body", where)
            given = {"*": spelt} if isinstance(spelt, str) else dict(spelt)
            for lang in given:
                if lang != "*":
                    _language(lang, f"{where}.{lang}")
            out.indices[b] = {lang: _index(i, f"{where}.{lang}" if lang != "*" else where) for lang, i in given.items()}
            continue
        if raw.strip() == "relative":
            given = {"*": spelt} if isinstance(spelt, str) else dict(spelt)
            for lang in given:
                if lang != "*":
                    _language(lang, f"{where}.{lang}")
            out.relative = {lang: _relative_word(w, f"{where}.{lang}" if lang != "*" else where)
                            for lang, w in given.items()}
            continue
        key = _notation_key(raw, bodies, parameters, where)
        if isinstance(spelt, str):
            out.symbols[key] = {"*": _spelling(spelt, where)}
        else:
            for lang in spelt:
                _language(lang, f"{where}.{lang}")
            out.symbols[key] = {lang: _spelling(s, f"{where}.{lang}") for lang, s in spelt.items()}
    _distinct_indices(out, [frame] + [b for b in bodies if b != frame])
    return out


def _distinct_indices(out: Wording, order: list) -> None:
    """No two bodies share an index, in any language (a given index against the numbers of
    the others, too: a body left numbered keeps its place in the file)."""
    if not out.indices:
        return
    from ..languages import LANGS

    for lang in LANGS:
        seen: dict[str, str] = {}
        for k, b in enumerate(order, start=1):
            spelt = out.indices.get(b)
            text = str(k) if spelt is None else spelt.get(lang, spelt.get("*", str(k)))
            if text in seen:
                raise KinematikaError("schema", "index-twice", f"notation.index({b})", first=seen[text], second=b,
                                      index=text)
            seen[text] = b


def _spin_joint(name: str, joints: dict, where: str) -> str:
    """A knife-edge wheel's joint (`spin(j3)`): its spin is the speed of its point along its
    plane over its radius."""
    _known(name, joints, "joint", where)
    if not getattr(joints[name].kind, "knife_edge", False):
        raise KinematikaError("schema", "spin-not-wheel", where, joint=name)
    return name


def meshed(joints: dict, bodies: dict) -> frozenset:
    """The bodies that are wheels among wheels: the two bodies of a joint whose kind rolls on
    pitch circles, and of one that rolls where both bodies are circles (C5-1.4's sun wheel and
    its planets, E.2's fixed central wheel and its planets). On such a page "wheel" does not
    tell one body from the others (`subscripts.named_labels`: ω_sun, not ω_wheel, beside the
    planets). The kinds are asked (`rolls`, `pitch`), never named (`tests/joints/test_registry`);
    the shapes are read only for a rolling joint, so a model without one imports no shapes."""
    def round_(body: str) -> bool:
        from .body_shapes import Circle

        return any(isinstance(s, Circle) for s in getattr(bodies.get(body), "shapes", ()) or ())

    out: set = set()
    for j in joints.values():
        kind = j.kind
        if getattr(kind, "rolls", False) and (getattr(kind, "pitch", False) or (round_(j.a) and round_(j.b))):
            out |= {j.a, j.b}
    return frozenset(out)


def _contact_joint(name: str, joints: dict, where: str) -> str:
    """A rolling or gear joint (`contact(j4)`): its contact point is written as the notes
    write it (the slides' F) in the explanation and its figures."""
    from ..joints import KINDS

    if name not in joints or not getattr(joints[name].kind, "touches", False):
        touching = [j for j, joint in joints.items() if joint.kind.touches]
        kinds = Names(sorted(k.name for k in KINDS.values() if k.touches), joined="or")
        raise KinematikaError("schema", "contact-not-touching", where, text=name, kinds=kinds, joints=touching)
    return name


def _spin(spelt: Any, parameters: dict, where: str) -> tuple[str, str]:
    """{symbol: NAME, radius: PARAMETER}: how the spin is written and the wheel's radius."""
    if not isinstance(spelt, dict) or set(spelt) != {"symbol", "radius"}:
        raise KinematikaError("schema", "spin-shape", where)
    radius = spelt["radius"]
    if radius not in parameters:
        raise KinematikaError("schema", "spin-radius-unknown", f"{where}.radius", radius=radius,
                              parameters=Names(parameters))
    return _spelling(spelt["symbol"], f"{where}.symbol"), radius


def _relative_word(text: Any, where: str) -> str:
    """The word of a relative motion (`notation: {relative: rel}`): one to six letters, with
    an abbreviation's full stop (rel, REL, rel.)."""
    if not isinstance(text, str) or not re.match(RELATIVE_WORD, text):
        raise KinematikaError("schema", "index-shape", where, index=str(text))
    return text


def _index(text: str, where: str, key: str = "index-shape") -> str:
    if not isinstance(text, str) or not re.match(INDEX, text):
        raise KinematikaError("schema", key, where, index=str(text))
    return text


def _language(lang: str, where: str) -> None:
    known(lang, where)


def _text(text: str, where: str) -> str:
    if not text.strip():
        raise KinematikaError("schema", "name-or-note-empty", where)
    return text.strip()


def _known(name: str, known: dict, kind: str, where: str) -> str:
    if name not in known:
        raise KinematikaError("schema", f"unknown-{kind}", where, **{kind: name, f"{kind}s": list(known)})
    return name


def _notation_key(key: str, bodies: dict, parameters: dict, where: str) -> str:
    """A parameter's name, or omega(body), omega(body/other), alpha(…) of known bodies;
    returned as looked up (a rate without spaces: omega(blades/block))."""
    rate = re.match(RATE, key.strip())
    if rate is None:
        if key not in parameters:
            raise KinematikaError("schema", "notation-key-unknown", where, key=key, parameters=list(parameters))
        return key
    parts = [b.strip() for b in rate.group(2).split("/")]
    if len(parts) > 2:
        raise KinematikaError("schema", "notation-rate-bodies", where, key=key)
    for b in parts:
        _known(b, bodies, "body", where)
    return f"{rate.group(1)}({'/'.join(parts)})"


def rate_key(kind: str, body: str, relative_to: Optional[str] = None) -> str:
    """The notation's key of ω (kind 'omega') or α ('alpha') of `body`, relative to another."""
    return f"{kind}({body}{'/' + relative_to if relative_to else ''})"


def _spelling(name: str, where: str) -> str:
    if not re.match(SPELLING, name):
        raise KinematikaError("schema", "notation-spelling", where, name=name)
    return name
