"""Issue 30, twenty-eighth round (c): four small items an English teacher marked
(docs/explain.md, "Twenty-eighth round (c)").

- C5-1.3, accelerations, Step 2: "α_support·SJ" and "α_support·QS" stood in the marks row
  above a_S and a_QS^t, where the notes' marks (M, D, ?, ⊥ …, ∥ …) go; α_support is the
  step's unknown, and the notes mark an unknown magnitude "?";
- C5-1.4: the instant centres omitted the sun wheel, which turns about the fixed axle O and
  whose ω the question asks, while the carrier's and the ring's centres at O were listed;
- "∥ normal" under a rolling contact's term: which normal? The line is now named, as the
  slides name it (∥_BF: the contact and a centre on it), or "the normal at J";
- C5-1.6: a velocity "polygon" of a single arrow; a figure of one vector is not drawn.

Each rule is checked over the notes' seeds in the four languages where it applies, and by
hand on the page the teacher read, against values derived here from the data.
"""
from __future__ import annotations

import math
import re

from kinematika.explain.document import CentreNote, Figure

from .helpers import LANGS, SEEDS, explained, over, rendered

VELOCITIES = {"en": "Velocities", "es": "Velocidades", "ca": "Velocitats", "eu": "Abiadurak"}
CENTRES = {"en": "Instant centres", "es": "Centros instantáneos de rotación (CIR)",
           "ca": "Centres instantanis de rotació (CIR)", "eu": "Biraketa-zentro instantaneoak"}
# the pages with a rolling contact's relative acceleration term (seed 001's rolling pair) and
# two that are not seeds: a belt on pulleys, and planets on a sun
CONTACTS = ("seed_001_rolling_pair", "pulley_train", "planetary_gears")


def _section(page: str, title: str) -> str:
    """The text of the page's section `## title`, up to the next section."""
    parts = re.split(r"^## ", page, flags=re.M)
    return next((p for p in parts if p.startswith(title + "\n")), "")


def _blocks(text: str) -> list[list[str]]:
    """The equations' code blocks of `text`: each a list of its lines (marks row above,
    the equation, marks row below)."""
    return [b.strip("\n").split("\n") for b in re.findall(r"```\n(.*?)```", text, flags=re.S)]


def _steps(page: str) -> list[str]:
    """The page's steps (`### Step n` … up to the next heading of any level)."""
    return re.findall(r"^### [^\n]*\n(.*?)(?=^##)", page + "\n##", flags=re.M | re.S)


# 1. the marks row -------------------------------------------------------------------------

@over(name=SEEDS + ["planetary_gears", "triad_six_bar"], lang=LANGS)
def test_no_rate_a_step_solves_stands_in_its_marks_row(name, lang):
    """A rate the step finds (the line "α_support = |a_S| / JS = …" after its equation) is
    an unknown of the equation: its marks row above writes "?" where that rate's term is,
    never "α_support·SJ", which reads as a known magnitude. Any model: every step of every
    page, velocities and accelerations."""
    page = rendered(name, lang, drawings=False)
    for step in _steps(page):
        for m in re.finditer(r"```\n(.*?)```", step, flags=re.S):
            block = m.group(1).strip("\n").split("\n")
            if len(block) < 3:
                continue
            before = set(re.findall(r"^((?:ω|α)_\S+) = ", step[:m.start()], flags=re.M))
            after = set(re.findall(r"^((?:ω|α)_\S+) = ", step[m.end():], flags=re.M))
            for rate in after - before:          # found by this equation (or a later one)
                assert not re.search(re.escape(rate) + r"(²)?·", block[0]), (rate, block[0])


@over(lang=LANGS)
def test_c5_1_3_marks_the_support_terms_unknown(lang):
    """C5-1.3 by hand: S, the support's centre, moves on a straight line parallel to the
    ground at the support's radius, so a_S = α_support × JS (J the contact) and a_QS^t =
    α_support × SQ, both of unknown magnitude until α_support is found from this very
    equation (with |a_rel|): the marks above a_S and a_QS^t are "?" and "?", the row holds
    only marks, the known magnitudes' formulas (ω_support²·QS, the Coriolis 2·ω·v) and no
    α; the sentence before the equation says the two ? are one unknown, α_support."""
    page = rendered("seed_c5_1_3_bar_in_sleeve", lang, drawings=False)
    block = next(b for b in _blocks(page) if len(b) == 3 and re.search(r"a_S\s+\+", b[1]))
    above, equation = block[0], block[1]
    for term in (r"a_S", r"a_QS\^[tT]"):          # Basque writes a^T
        found = re.search(term + r"(?=\s)", equation)
        at, width = found.start(), len(found.group())
        mark = above[max(0, at - 3):at + width + 3].strip()
        assert mark == "?", (term, mark, above)
    assert "α" not in above, above
    sentence = next(line for line in page.split("\n") if "α_support·SJ" in line or "α_euskarria·SJ" in line
                    or re.search(r"α_\S+·SJ", line))
    assert "?" in sentence and not sentence.startswith(" "), sentence


# 2. the sun wheel's centre ----------------------------------------------------------------

@over(lang=LANGS)
def test_c5_1_4_names_the_sun_wheels_centre(lang):
    """C5-1.4: the carrier, the sun wheel and the ring are each hinged to the ground at O
    (the model's three revolute joints at O), so their three centres relative to the ground
    are O = (0, 0) — the notes: "Els CIRs respecte al terra del portador, de la corona i de
    la roda central coincideixen amb el punt central". The sun's ω is asked; its centre is
    listed with the other two."""
    sol, _ = explained("seed_c5_1_4_epicyclic")
    pinned = [j for j in sol.model.joints if j.kind.name == "revolute" and "ground" in (j.a, j.b) and j.at == "O"]
    assert {j.b if j.a == "ground" else j.a for j in pinned} == {"carrier", "sun", "ring"}
    section = _section(rendered("seed_c5_1_4_epicyclic", lang, drawings=False), CENTRES[lang])
    at_o = re.findall(r"^I_\{[^}]+\}: [^(\n]*\(0[,;] 0\)[^(\n]*$", section, flags=re.M)
    assert len(at_o) == 3, at_o


def test_a_centre_of_a_body_on_a_fixed_axle_asked_for_its_rate_is_written():
    """Any model: on a page that writes centres relative to the frame, every body pinned to
    the frame whose ω (or α) relative to the frame is asked has its centre written, at its
    pin. Checked on the documents of the seeds: the centre notes written name each such body."""
    for name in SEEDS:
        sol, doc = explained(name)
        model = sol.model
        frame = model.frame
        notes = [b for b in doc.blocks() if isinstance(b, CentreNote)]
        if not any(frame in n.pair for n in notes):
            continue
        asked = {q.target for q in model.questions if q.kind in ("omega", "alpha")
                 and q.relative_to in (None, frame) and isinstance(q.target, str)}
        pinned = {j.b if j.a == frame else j.a for j in model.joints
                  if j.kind.name == "revolute" and frame in (j.a, j.b)}
        written = {b for n in notes for b in n.pair if frame in n.pair and b != frame}
        assert (asked & pinned) <= written, (name, (asked & pinned) - written)


# 3. the contact normal named --------------------------------------------------------------

@over(name=CONTACTS, lang=LANGS)
def test_a_contacts_normal_is_named(name, lang):
    """The relative acceleration of the two points of a rolling contact lies along the
    common normal; the marks row says which normal: a segment (∥ FA) or the normal at the
    contact, never "∥ normal" alone."""
    page = rendered(name, lang, drawings=False)
    rows = [b[-1] for b in _blocks(page) if len(b) >= 3]
    assert rows
    for row in rows:
        assert not re.search(r"∥ normala?(\s|$)", row), row


def test_seed_001_rolling_pairs_normal_is_fa():
    """Seed 001's rolling pair: the lever N (a straight line through B) and the roller R
    (a circle of radius ρ about A) touch at F; the normal to the lever at F passes through
    the roller's centre A, so a_{F∈N rel R} ∥ FA. By hand: F is the foot of the
    perpendicular from A to the lever, AF ⊥ the lever; the term's value is along it."""
    sol, doc = explained("seed_001_rolling_pair")
    pts = sol.inst.points
    beta = math.radians(30)
    rho = 0.1
    a = (rho / math.sin(beta), 0.0)
    assert math.isclose(pts["A"][0], a[0]) and abs(pts["A"][1]) < 1e-12
    u = (math.cos(beta), math.sin(beta))                       # the lever's direction
    along = a[0] * u[0] + a[1] * u[1]
    f = (along * u[0], along * u[1])                           # the foot of the perpendicular
    assert math.isclose(math.hypot(a[0] - f[0], a[1] - f[1]), rho)
    terms = [t for eq in doc.equations() for t in eq.terms if t.kind == "contact"]
    assert terms
    for t in terms:
        assert t.dir.code == "para" and t.dir.ref == "FA", t.dir
        v = [float(x) for x in t.value]
        fa = (a[0] - f[0], a[1] - f[1])
        assert abs(v[0] * fa[1] - v[1] * fa[0]) <= 1e-9 * math.hypot(*v) * rho + 1e-12


# 4. no polygon of one arrow ---------------------------------------------------------------

@over(name=SEEDS, lang=("en",))
def test_no_polygon_of_one_arrow(name, lang):
    """Any model: a velocity or acceleration polygon draws at least two arrows; a "polygon"
    of one vector closes nothing, and the equation alone says it (the notes draw none)."""
    _, doc = explained(name)
    for fig in (b for b in doc.blocks() if isinstance(b, Figure)):
        if fig.caption is not None and str(getattr(fig.caption, "key", "")).startswith(("fig.level_", "fig.step_", "fig.polygon_")):
            assert len(fig.arrows) >= 2, (fig.caption.key, len(fig.arrows))


@over(lang=LANGS)
def test_c5_1_6_has_no_velocity_figure(lang):
    """C5-1.6 by hand: the only velocity equation is v_A = v_O + v_AO, with O the arm's
    fixed pivot (v_O = 0): its polygon would be the single arrow oa (|v_AO| = ω·OA). The
    velocities section writes the equation and draws no figure; the notes draw none there."""
    page = rendered("seed_c5_1_6_belt", lang, drawings=False)
    section = _section(page, VELOCITIES[lang])
    assert section
    assert "![" not in section, "a figure in the velocities"
    assert any(re.search(r"v_A\s+=\s+v_O\s+\+\s+v_AO", line) for b in _blocks(section) for line in b)
