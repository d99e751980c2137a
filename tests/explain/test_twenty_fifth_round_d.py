"""Issue 30, twenty-fifth round (d): signs and captions, from the readers' reports.

1. On a symbolic page a rate is read off one component of its term, "along x: a_H =
   −α_{rear wheel}·GH ⇒ α_{rear wheel} = −v̇/R_wheel", never off a magnitude, "α = −|a_H| /
   GH", which holds only for the sense the figure shows when the data are symbols of any value
   (ca reader: E.1, E.4, E.5, E.6). Numeric pages keep "−|v_BA| / AB = −5.5 rad/s".
2. A polygon caption that says which images are at the pole names them all, an instant
   centre's too (C5-E.3's v_{I_rod} = 0), and where another body's point at O has its own
   image (C5-E.1's o′∈wheels, which moves) it says which O o′ is: the fixed point O of the arm.
"""

from __future__ import annotations

import re

import sympy

from kinematika.explain.document import Figure, Msg, Value

from .helpers import LANGS, SEEDS, explained, over, rendered

ALONG = {"en": "along", "es": "según", "ca": "segons", "eu": "norabidean"}
IMAGE_OF_O = {"en": "o′, the image of O,", "es": "o′, la imagen de O,", "ca": "o′, la imatge d’O,",
              "eu": "o′, O-ren irudia,"}


def _symbolic(name: str) -> bool:
    sol, _ = explained(name)
    return bool(sol.symbolic)


def _rates(name: str) -> list:
    """The rates the page reads off a rotation term (ω, α of a body; not a wheel's spin φ̇)."""
    _, doc = explained(name)
    return [d for d in doc.derived() if d.kind in ("omega", "alpha") and d.body]


@over(name=SEEDS, lang=LANGS)
def test_d_a_symbolic_rate_is_never_read_off_a_magnitude(name: str, lang: str) -> None:
    """Symbolic page: no "ω = −|v_HG| / GH" (a magnitude with the sense as a sign) for a
    body's rate, in the document or on the page (a wheel's spin about its axle, ω′ = |v_C4| /
    r, is a magnitude by definition); numeric page: that form stays."""
    _, doc = explained(name)
    spins = tuple(d.sym.base + " = " for d in doc.derived() if d.kind == "spin")   # a wheel's own spin, |v| / r
    page = rendered(name, lang, drawings=False)
    lines = [m.group(0) for m in re.finditer(r"^[ωαψ]\S*( = \S+)? = −?\|[va]_.*\| / .*$", page, re.M)]
    lines = [ln for ln in lines if not ln.startswith(spins)]
    read = [d for d in _rates(name) if any(i == "| / " for i in d.how)]
    if _symbolic(name):
        assert not read, [d.sym for d in read]
        assert not lines, lines
    elif read:
        assert lines, name


@over(name=SEEDS, lang=LANGS)
def test_d_the_component_written_holds(name: str, lang: str) -> None:
    """Every "along x: T = ±rate·L ⇒ rate = value" is true of the solver's own vectors: the
    term's component along that axis equals ± the rate's value times L, L the arm's length
    (a segment) or the arm's component written (an oblique arm: "(R/2)")."""
    if not _symbolic(name):
        return
    sol, _ = explained(name)
    for d in (d for d in _rates(name) if d.lead and d.source is not None and d.arm is not None):
        at = next(k for k, i in enumerate(d.lead) if hasattr(i, "key"))
        axis = d.lead[at].key[-1]
        assert d.lead[at].key in ("readoff.along_x", "readoff.along_y"), d.lead
        sign = -1 if "−" in d.lead[at:] else 1
        factor = next((i.value for i in d.lead[at:] if isinstance(i, Value)), None)
        if factor is not None:      # an oblique arm: its components written first (KS = (√3·r, r); …)
            assert at == 4 and [sympy.sympify(c) for c in d.lead[2].value] == [sympy.sympify(c) for c in d.arm], d.lead
        arm = [sympy.sympify(c) for c in d.arm]
        length = sympy.sqrt(arm[0] ** 2 + arm[1] ** 2) if factor is None else sympy.sympify(factor)
        comp = sympy.sympify(d.source.value[0 if axis == "x" else 1])
        assert sympy.simplify(comp - sign * sympy.sympify(d.value.value) * length) == 0, (d.sym, d.lead)
        page = rendered(name, lang, drawings=False)
        assert ALONG[lang] in page, lang


def test_d_the_bicycle_rear_wheel_by_hand() -> None:
    """C5-E.6: GH = (0, R_wheel), a_H = (v̇, 0) and α k × GH = (−α·R_wheel, 0), so along x
    v̇ = −α·R_wheel and α = −v̇/R_wheel; v_H = (v, 0): ω = −v/R_wheel. The front wheel alike:
    its centre F moves as H, R_wheel above its contact."""
    pages = {lang: rendered("seed_c5_e6_bicycle", lang, drawings=False) for lang in LANGS}
    # the rear wheel is wheel 1 and the front wheel 2 of the page's notation line (27th round (g))
    assert "GH = (0, R_wheel); along x: a_H^t = −α_wheel1·R_wheel ⇒ α_wheel1 = −v̇/R_wheel" in pages["en"]
    assert "GH = (0, R_wheel); along x: v_HG = −ω_wheel1·R_wheel ⇒ ω_wheel1 = −v/R_wheel" in pages["en"]
    assert "JF = (0, R_wheel); along x: a_F^t = −α_wheel2·R_wheel ⇒ α_wheel2 = −v̇/R_wheel" in pages["en"]    # its own equation (round 27b)
    assert "GH = (0; R_roda); segons x: a_H^t = −α_roda1·R_roda ⇒ α_roda1 = −v̇/R_roda" in pages["ca"]
    assert "GH = (0; R_rueda); según x: a_H^t = −α_rueda1·R_rueda ⇒ α_rueda1 = −v̇/R_rueda" in pages["es"]
    assert "GH = (0; R_gurpila); x norabidean: a_H^T = −α_gurpila1·R_gurpila ⇒ α_gurpila1 = −v̇/R_gurpila" in pages["eu"]
    for page in pages.values():
        assert "|a_H|" not in page and "|v_HG|" not in page


def test_d_the_cavity_and_an_oblique_arm_by_hand() -> None:
    """C5-E.1: the wheels' centre C is R below the contact J (JC = (0, −R)) and a_C^t =
    (−2·R·θ̈, 0): α k × (0, −R) = (α·R, 0), so along x a_C^t = α·JC, α = −2·θ̈. An oblique
    arm (C5-E.4's PN before round 27b, whose upper wheel is now composed from the chassis):
    C5-1.4's second planet, its centre 2r/5 from A2 along 30°, so I₂S = (3r/5)(cos 30°, sin 30°)
    = (3√3·r/10, 3r/10); v_S = 3rω at −60°: (3rω/2, −3√3·rω/2); along x 3rω/2 = −ω₂·(3r/10),
    ω₂ = −5ω, written "−ω·(3·r/10)"."""
    e1 = rendered("seed_c5_e1_cavity", "en", drawings=False)
    assert "JC = (0, −R); along x: a_C^t = α_wheels·R ⇒ α_wheels = −2·θ̈" in e1
    assert "JC = (0, −R); along x: v_CJ = ω_wheels·R ⇒ ω_wheels = −2·θ̇" in e1
    planets = rendered("seed_c5_1_4_epicyclic", "en", drawings=False)
    assert ("I_{planet2}S = (3·√3·r/10, 3·r/10); along x: v_{SI_{planet2}} = −ω_planet2·(3·r/10) "
            "⇒ ω_planet2 = −5·ω") in planets


def test_d_numeric_pages_keep_the_magnitude() -> None:
    """001 r_pairs (numbers): ω_N = −|v_BA| / AB = −5.5 rad/s (clockwise), unchanged."""
    page = rendered("seed_001_r_pairs", "en", drawings=False)
    assert "ω_N = −|v_BA| / AB = −5.5 rad/s (clockwise)" in page
    assert "along x:" not in page and "along y:" not in page


def _captions(page: str) -> list[tuple[str, str]]:
    """Each figure's caption (the italic line after a figure) with the text written before it
    since the previous one."""
    out, start = [], 0
    for m in re.finditer(r"^!\[[^\]]*\]\[[^\]]*\]\n\n\*(.*)\*$", page, re.M):
        out.append((m.group(1), page[start:m.start()]))
        start = m.end()
    return out


@over(name=SEEDS, lang=LANGS)
def test_d_a_caption_names_every_centre_at_the_pole(name: str, lang: str) -> None:
    """An instant centre whose velocity the polygon's equations write as zero ("- v_{I_rod} =
    (0, 0)") is named in the caption's at-pole sentence (C5-E.3: "j∈left wheel, k∈right
    wheel, and the image of the instant centre I_rod are at the pole o")."""
    page = rendered(name, lang, drawings=False)
    for caption, before in _captions(page):
        if not re.search(r"pol[oe]? o|poloan", caption):
            continue
        for centre in set(re.findall(r"^- v_\{(I_[^}]+)\} = \(0[,;] 0\)$", before, re.M)):
            assert centre in caption and f"v_{{{centre}}}" in caption, (centre, caption)


def test_d_the_rod_centre_by_hand() -> None:
    """C5-E.3: the rod turns about I_rod (its velocity zero); the velocity polygon's caption
    names it with the wheels' contacts, and v_{I_rod} = 0 with theirs."""
    en = rendered("seed_c5_e3_wheels_with_rod", "en", drawings=False)
    assert ("j∈wheel1, k∈wheel2, and the image of the instant centre I_{rod} are at the pole o, "
            "since v_{J∈wheel1} = v_{K∈wheel2} = v_{I_{rod}} = 0.") in en
    ca = rendered("seed_c5_e3_wheels_with_rod", "ca", drawings=False)
    assert "j∈roda1, k∈roda2 i la imatge del CIR I_{biela} són al pol o" in ca


@over(name=SEEDS, lang=LANGS)
def test_d_o_prime_says_which_o(name: str, lang: str) -> None:
    """Where a polygon letters another body's point at O (o∈wheels, twenty-eighth round (f); o′∈wheels before), the caption does not
    call o′ just "the image of O": it names the fixed point O of its body."""
    _, doc = explained(name)
    page = rendered(name, lang, drawings=False)
    for fig in (b for b in doc.blocks() if isinstance(b, Figure)):
        if not any(label.startswith("o∈") for label, _, _ in fig.points):
            continue
        keys = [m.key for n in fig.notes for m in _msgs(n)]
        assert "fig.o_prime_named" not in keys, keys
    if name == "seed_c5_e1_cavity":
        assert IMAGE_OF_O[lang] not in page


def _msgs(m: object) -> list:
    """A message and the messages inside its arguments."""
    if isinstance(m, Msg):
        out = [m]
        for a in m.args.values():
            out += _msgs(a)
        return out
    items = getattr(m, "items", None)
    if isinstance(items, list):
        return [x for i in items for x in _msgs(i)]
    return _msgs(m.item) if hasattr(m, "item") else []


def test_d_the_cavity_caption_by_hand() -> None:
    """C5-E.1: O is the arm's pivot on the ground; the wheels' point at O moves (its image
    o′∈wheels is drawn apart): the caption's o′ is the fixed O of the arm OC."""
    en = rendered("seed_c5_e1_cavity", "en", drawings=False)
    assert "o′, the image of the fixed point O of the arm OC, is at the pole o, since a_O = 0." in en
    ca = rendered("seed_c5_e1_cavity", "ca", drawings=False)
    assert "j∈rodes i o′, la imatge del punt fix O del braç OC, són al pol o" in ca
    es = rendered("seed_c5_e1_cavity", "es", drawings=False)
    assert "o′, la imagen del punto fijo O del brazo OC, está en el polo o" in es
