"""Issue 30, twenty-fourth round (e): four readers' items on main's pages (docs/explain.md,
"Twenty-fourth round (e)").

- the M/D legend lists "M: magnitude known; D: direction known" plainly on every page; where
  the page has a point named M or D, one short sentence after it says that letter is the mark
  and not the point, naming the letter (the old aside "(under a term these letters are always
  these marks, never the point D)" read oddly; the Basque one hung M's note on D);
"""
from __future__ import annotations

import re


from .helpers import LANGS, SEEDS, explained, over, rendered, model_tree

# the legend, the same on every page (the notes' marks, seed 001)
LEGEND = {"en": "M: magnitude known; D: direction known; ?: unknown;",
          "es": "M: módulo conocido; D: dirección conocida; ?: desconocido;",
          "ca": "M: mòdul conegut; D: direcció coneguda; ?: desconegut;",
          "eu": "M: modulua ezaguna; D: norabidea ezaguna; ?: ezezaguna (norabidea edo modulua);"}
# the sentence after the legend for one letter that is also a point of the page
ONE = {"en": {"M": "Here M marks a known magnitude; it is not the point M.",
              "D": "Here D marks a known direction; it is not the point D."},
       "es": {"M": "Aquí M indica un módulo conocido; no es el punto M.",
              "D": "Aquí D indica una dirección conocida; no es el punto D."},
       "ca": {"M": "Aquí M indica un mòdul conegut; no és el punt M.",
              "D": "Aquí D indica una direcció coneguda; no és el punt D."},
       "eu": {"M": "Hemen M letrak modulu ezaguna adierazten du; ez da M puntua.",
              "D": "Hemen D letrak norabide ezaguna adierazten du; ez da D puntua."}}
# the old asides, gone
OLD = ("never the point", "nunca el punto", "mai el punt", "marka gisa", "under a term",
       "bajo un término", "sota un terme")


def _clash(name: str, md: str) -> list[str]:
    """The notes' letters that are a point of the page (model point, contact, points table)."""
    sol, doc = explained(name)
    points = set(sol.model.points) | set(doc.joints.values())
    points |= set(re.findall(r"^\| ([A-Z][A-Za-z0-9]*) \|", md, flags=re.M))
    return [m for m in ("M", "D") if m in points]


@over(name=SEEDS, lang=LANGS)
def test_the_marks_legend_is_plain_and_a_clash_is_its_own_sentence(name, lang):
    """Every page with equations lists the legend plainly; a letter that is also a point is
    said in one sentence of its own right after the legend, naming that letter (C5-1.1 and
    C5-E.5: D; C5-2.1: M, until the twenty-eighth round (b) renamed them; 001's guide M is a
    body: nothing). A user's model keeps the sentence: test_twenty_eighth_round_b.py."""
    md = rendered(name, lang, drawings=False)
    line = next((ln for ln in md.splitlines() if LEGEND[lang] in ln), None)
    if line is None:
        assert not explained(name)[1].equations(), "no legend"
        return
    assert not any(old in md for old in OLD)
    clash = _clash(name, md)
    for letter in ("M", "D"):
        said = ONE[lang][letter] in line
        assert said == (clash == [letter]), (letter, clash)
    # the sentence follows the legend's last clause at once (the ⊥/∥ clause)
    if len(clash) == 1:
        after = line.split("∥", 1)[1]
        assert re.match(r"[^.]*\. " + re.escape(ONE[lang][clash[0]]), after), after


# ---- a point's body after ∈ is read on the page -------------------------------------------
NOTATION = {"en": "Notation: ", "es": "Notación: ", "ca": "Notació: ", "eu": "Notazioa: "}
ARTICLE = re.compile(r"(?i)^(?:(?:els|les|el|la|los|las|the)\s+|l['’]\s*)")
SMALL = {"de", "del", "d", "of", "the", "a"}


def _readable(label: str, name: str, lang: str) -> bool:
    """Whether subscript `label` is body `name` as written or its words run together, or the
    code the name holds (OJ of *barra OJ*, M of *guia M*): a student reads it off the name."""
    words = [w.rstrip(".") for w in ARTICLE.sub("", name.strip()).split()]
    words = [w for w in words if w.lower().replace("’", "'").split("'")[-1] not in SMALL]
    joined = "".join(words)
    plain = label.replace(" ", "")
    if label in words and re.fullmatch(r"[A-Z][A-Z0-9]{0,3}", label):
        return True
    return plain == joined or (lang == "eu" and plain in {joined + "a", "".join(w + "a" for w in words)}) \
        or sorted(re.findall(r"\d+|\D+", plain)) == sorted(words)


@over(name=SEEDS, lang=LANGS)
def test_every_body_after_in_is_read_off_or_defined(name, lang):
    """v_{J∈zilindroa} on C5-1.8 (the body is *zilindro finkoa*; es v_{J∈cilindro} of the
    *cilindro fijo*, ca v_{J∈terra} of the *terra cilíndric*): a body written after ∈ whose
    subscript is not its name as written is defined once on the Notation line."""
    md = rendered(name, lang, drawings=False)
    names = (model_tree(name).get("names") or {}).get(lang, {})
    bodies = list((names.get("bodies") or {}).values())
    if not bodies:
        return
    notation = next((ln for ln in md.splitlines() if ln.startswith(NOTATION[lang])), "")
    prose = "\n".join(ln for ln in md.splitlines() if not ln.startswith(NOTATION[lang]))
    labels = {m for m in re.findall(r"[va]_\{[A-Za-z0-9′]+∈([^}]+)\}", prose) if " rel" not in m}
    for label in sorted(labels):
        if any(_readable(label, b, lang) for b in bodies):
            continue
        assert f"∈{label}}}" in notation or f"ω_{label} " in notation or f"ω_{{{label}}} " in notation, \
            (label, notation)


# ---- the models' own texts --------------------------------------------------------------------
def _model_texts(name: str, lang: str) -> list[str]:
    """The model's data and notes sentences in `lang` (its own words, `names.LANG`)."""
    names = (model_tree(name).get("names") or {}).get(lang, {})
    return [t for key in ("data", "notes") for t in (names.get(key) or []) if isinstance(t, str)]


@over(name=SEEDS, lang=LANGS)
def test_a_typed_rate_is_italic_and_a_power_no_subscript(name, lang):
    """C5-2.1's "val la seva resposta φ̇ = v₀ …": upright, the dot sat on the φ's stem and a
    reader read φ; a letter with a dot is a rate, set in italics as the answer table sets
    it. E.6's "ℜ_P = v_P²/aⁿ": the square is not part of the subscript."""
    page = rendered(name, lang, "html", drawings=False)
    upright = re.findall(r'(?<!<i>)(?<!<b class="v">)<span class="mk(?:">.[\u0307\u0308]+| d[td][^"]*">.)</span>', page)
    assert not upright, upright
    assert not re.search(r"<sub>[^<]*[²³¹\u2070-\u207f]</sub>", page)


@over(name=SEEDS, lang=LANGS)
def test_the_model_texts_write_the_pages_notation(name, lang):
    """A model's note writes a point's velocity v_P as the page does, never the notes' v(P)
    (C5-E.6), and a segment XY it sets equal to something joins two points of the page
    (C5-E.5's "CP = r₂" where the wheel's centre is B: BP)."""
    sol, doc = explained(name)
    points = set(sol.model.points) | set(doc.joints.values())
    for text in _model_texts(name, lang):
        assert not re.search(r"(?<![\w(])[va]\([A-Z]\w*\)", text), text
        for a, b in re.findall(r"(?<![\w′])([A-Z])([A-Z])(?= =)", text):
            assert {a, b} <= points, (a + b, text)


def test_the_basque_small_wheel_is_said_whole():
    """C5-E.1 (eu): the radius of the small wheel read "*gurpil* txikiaren erradioa", half
    the name in italics; the model now says "gurpilen erradio txikia"."""
    md = rendered("seed_c5_e1_cavity", "eu", drawings=False)
    assert "*gurpil* txikiaren" not in md
    assert "*gurpilen* erradio txikia" in md


# ---- a primed point is defined where it is first written ------------------------------------
# the definition of the foot J′ beside its first mention, per language
FOOT = {"en": r"at (\w)′, the foot of the perpendicular from \1 to the guide",
        "es": r"en (\w)′, el pie de la perpendicular desde \1 a la guía",
        "ca": r"a (\w)′, el peu de la perpendicular des de \1 a la guia",
        "eu": r"(\w)′ da \1 puntutik gidara doan perpendikularraren oina"}      # two sentences since 29 (b)


@over(name=SEEDS, lang=LANGS)
def test_a_primed_point_is_defined_where_first_written(name, lang):
    """C5-1.3's "(al seu peu J′ sobre la guia, …)": J′ was never defined. A point written
    X′ that is no point of the model is defined at its first mention as the foot of the
    perpendicular from X to the guide."""
    sol, doc = explained(name)
    md = rendered(name, lang, drawings=False)
    points = set(sol.model.points) | set(doc.joints.values())
    first = re.search(r"(?<![\w′])([A-Z])′", md)
    if first is None or f"{first[1]}′" in points:
        return
    said = re.search(FOOT[lang], md)
    assert said and said[1] == first[1], md[first.start() - 80:first.end() + 80]
    assert said.start() <= first.start() < said.end(), "defined after its first mention"


# ---- a point the page lists is a point it uses ---------------------------------------------
# the points table's row of a point the model says nothing of: "a point of the *ground*"
GENERIC = {"en": r"a point of (?:the )?\*[^*]+\*", "es": r"un punto de(?:l| la| los| las)? \*[^*]+\*",
           "ca": r"un punt (?:del|de la|de l’|dels|de les) ?\*[^*]+\*", "eu": r"\*[^*]+\* puntua"}
STRUCTURE = {"en": "## Structure", "es": "## Estructura", "ca": "## Estructura", "eu": "## Egitura"}


@over(name=SEEDS, lang=LANGS)
def test_a_listed_point_of_no_words_is_used(name, lang):
    """C5-E.4's "| G | un punto del *suelo* | (0; 0) |": G only anchored the ground's line
    and the page used it nowhere. A point the model gives no words is listed only when the
    page writes it after its structure (the model now draws the line through (0, 0))."""
    md = rendered(name, lang, drawings=False)
    start = md.find("\n## ", md.find(STRUCTURE[lang]) + 5)
    rest = md[start:]
    for point, what in re.findall(r"^\| ([A-Z][A-Z0-9]*) \| ([^|]+) \|", md, flags=re.M):
        if re.fullmatch(GENERIC[lang], what.strip()):
            assert re.search(rf"(?<![\w′]){point}(?![\w′])", rest), (point, what)
