"""Issue 30, twenty-seventh round (b): one kind of body, one method (docs/explain.md,
"Twenty-seventh round (b)").

Teachers reading `kinematika explain` in Catalan, Spanish and Basque found:

- C5-1.4: the three planets solved three ways (the first from its centre between its axle
  and its contact with the ring, the second read off the sun, the third "by symmetry");
- C5-E.4: the upper wheel turned about P at velocities and composed from the chassis at
  accelerations;
- C5-E.6: the front wheel's step had no vector equation where the rear wheel's has one
  (C5-1.2's wheels likewise);
- C5-2.1: ψ̇ written in step 1's equation before the line "⇒ ψ̇ = ω_xassís = …";
- C5-1.6, E.6: "ω_corretja = ω_braç (es trasllada …)": the belt's straight run translates,
  not the belt; C5-1.5: "I_politja3: respecte del terra, T4 es mou amb (0; 2·v)" named
  neither whose points move nor their velocities.

Each rule is checked over the notes' seeds in the four languages where it applies, and by
hand on the page the reader read, against values derived here from the data.
"""
from __future__ import annotations

import re

from kinematika.explain.context import Ctx
from kinematika.explain.drives import drives
from kinematika.explain.group import path_centre
from kinematika.explain.kin import kin
from kinematika.explain.kinds import rolls
from kinematika.model.wording import ARTICLES

from .helpers import LANGS, SEEDS, explained, over, rendered

VELOCITIES = {"en": "Velocities", "es": "Velocidades", "ca": "Velocitats", "eu": "Abiadurak"}
ACCELERATIONS = {"en": "Accelerations", "es": "Aceleraciones", "ca": "Acceleracions", "eu": "Azelerazioak"}
# the straight run of a belt or chain, as each language's teacher names it
RUN = {"en": "straight run", "es": "tramo recto", "ca": "tram recte", "eu": "zati zuzena"}
# the definition on the notation line: "ψ̇ is the angular velocity of the *chassis*"
DEFINES = {"en": "is the angular velocity of", "es": "es la velocidad angular de", "ca": "és la velocitat angular",
           "eu": "abiadura angeluarra da"}
# the proportional construction's second sentence (two parallel velocities)
LINEAR = {"en": "varies linearly", "es": "varía linealmente", "ca": "varia linealment", "eu": "linealki aldatzen"}


def _ctx(name: str) -> Ctx:
    sol, _ = explained(name)
    return Ctx(sol)


def _called(name: str, body: str, lang: str) -> str:
    """The body's name as the page stars it (*planet 1*, *rodeta 1*), its article dropped."""
    sol, _ = explained(name)
    spelt = sol.model.wording.bodies.get(lang, {}).get(body, body)
    article = ARTICLES.get(lang)
    return article.sub("", spelt, count=1) if article is not None and article.match(spelt) else spelt


def _section(page: str, title: str) -> str:
    """The text of the page's section `## title`, up to the next section."""
    parts = re.split(r"^## ", page, flags=re.M)
    return next((p for p in parts if p.startswith(title + "\n")), "")


def _steps(section: str) -> list[tuple[str, str]]:
    """(heading, text) of each numbered step of a section."""
    parts = re.split(r"^### ", section, flags=re.M)[1:]
    return [(p.split("\n", 1)[0], p.split("\n", 1)[1] if "\n" in p else "") for p in parts]


def _shape(text: str) -> list[str]:
    """What a step writes, paragraph by paragraph: an equation (a fenced block), a term of its
    list, a line of text; figures and their captions left out."""
    out, fenced = [], False
    for line in text.splitlines():
        if line.startswith("```"):
            if not fenced:
                out.append("equation")
            fenced = not fenced
        elif fenced or not line.strip() or line.startswith("![") or re.fullmatch(r"\*.*\*", line.strip()):
            continue
        else:
            out.append("term" if line.startswith("- ") else "line")
    return out


def _own_step(page: str, title: str, name: str) -> str | None:
    """The text of the step of `title`'s section whose heading names the body `name` alone."""
    for heading, text in _steps(_section(page, title)):
        if re.findall(r"\*([^*]+)\*", heading) == [name]:
            return text
    return None


@over(name=SEEDS, lang=LANGS)
def test_bodies_of_one_kind_are_written_one_way(name, lang):
    """Bodies of one kind (the same round shapes, the same joints with the same bodies:
    `kin.kin`) that the page works out in steps of their own are written alike, at each level:
    the same equations, terms and lines (C5-1.4's planets; C5-E.4's lower wheels)."""
    ctx = _ctx(name)
    page = rendered(name, lang, drawings=False)
    listed = [b for b in ctx.model.moving_bodies if not ctx.fixed(b)]
    for b in listed:
        for k in (k for k in kin(ctx, b) if k in listed and listed.index(k) > listed.index(b)):
            for title in (VELOCITIES[lang], ACCELERATIONS[lang]):
                mine, theirs = (_own_step(page, title, _called(name, x, lang)) for x in (b, k))
                if mine is not None and theirs is not None:     # (C5-1.1's strands share steps)
                    assert _shape(mine) == _shape(theirs), (title, b, k, _shape(mine), _shape(theirs))


@over(name=SEEDS, lang=LANGS)
def test_a_wheel_on_a_fixed_body_is_found_by_its_vector_equation(name, lang):
    """A wheel rolling without slipping on a fixed body, listed in the structure, gets its ω
    from the vector equation about its contact (v_C = v_{J∈wheel} + v_CJ), as every step of
    the page does — never a line "its contact point is its instant centre, so ω = …" alone
    (C5-E.6's front wheel, C5-1.2's wheels)."""
    ctx = _ctx(name)
    page = rendered(name, lang, drawings=False)
    velocities = _section(page, VELOCITIES[lang])
    for j in ctx.model.joints:
        if not rolls(j) or ctx.sol.geometry(j.id).contact is None:
            continue
        for fixed, wheel in ((j.a, j.b), (j.b, j.a)):
            if not ctx.fixed(fixed) or ctx.fixed(wheel) or wheel not in ctx.model.moving_bodies \
                    or path_centre(ctx, j, wheel) is None:
                continue            # a wheel with its centre (not a belt on a fixed pulley)
            called = _called(name, wheel, lang)
            steps = [text for heading, text in _steps(velocities) if f"*{called}*" in heading]
            assert steps, (wheel, "no step names it")
            contact = ctx.contact(j)
            fences = [block for text in steps for block in re.findall(r"```\n(.*?)```", text, flags=re.S)]
            assert any(f"v_{{{contact}∈" in block for block in fences), (wheel, contact, "no equation about the contact")


@over(name=SEEDS, lang=LANGS)
def test_a_body_composed_at_accelerations_is_composed_at_velocities(name, lang):
    """A rate found at accelerations by composing from a carrier (α_{b rel K} = …, then
    α_b = α_{b rel K} + α_K) is found the same way at velocities (ω_{b rel K} = …): one body,
    one method at both levels (C5-E.4's upper wheel turned about P at velocities)."""
    page = rendered(name, lang, drawings=False)
    velocities, accelerations = _section(page, VELOCITIES[lang]), _section(page, ACCELERATIONS[lang])
    for line in accelerations.splitlines():
        found = re.match(r"α_\{([^}]+ rel [^}]+)\} = ", line)
        if found:
            assert re.search(r"^ω_\{" + re.escape(found.group(1)) + r"\} = ", velocities, flags=re.M), found.group(1)


@over(name=SEEDS, lang=LANGS)
def test_a_noted_rate_is_defined_before_it_is_written(name, lang):
    """A body's rate the model's notation writes otherwise (C5-2.1's precession ψ̇ for
    ω_xassís), tied to its body where it is found ("ψ̇ = ω_xassís = …"), is defined before
    the page first writes it: on the notation line under the structure."""
    page = rendered(name, lang, drawings=False)
    for noted in dict.fromkeys(re.findall(r"(?:⇒ |^)(?!ω_|α_)(\S+) = ω_\S+ = ", page, flags=re.M)):
        first = page.index(noted)
        line = page[page.rindex("\n", 0, first) + 1:page.index("\n", first)]
        assert DEFINES[lang] in line and line.index(noted) < line.index(DEFINES[lang]), (noted, line)


@over(name=SEEDS, lang=LANGS)
def test_the_straight_run_is_what_translates(name, lang):
    """A belt or chain drive says that the run between the wheels translates (the notes'
    "trams de cable que no estan en contacte amb les politges"), never the belt: in the
    relation seen from the carrier (C5-1.6, C5-E.6; the run's own ω line is gone since round 29 c)."""
    ctx = _ctx(name)
    page = rendered(name, lang, drawings=False)
    for d in drives(ctx):
        called = _called(name, d.line, lang)
        said = [line for line in page.splitlines() if line.startswith("ω_") and RUN[lang] in line]
        assert not said, (d.line, "round 29 c: the run gets no ω line")
        relation = [line for line in page.splitlines() if RUN[lang] in line and not line.startswith(("ω_", "α_"))]
        assert relation and all(called.split()[0] in line for line in relation), (d.line, relation)


@over(name=SEEDS, lang=LANGS)
def test_two_parallel_velocities_name_whose_points_move(name, lang):
    """A centre found from two parallel velocities says whose points they are and writes
    their velocities as the steps do (C5-1.5: "the points T4 and C3 of *pulley 3* move,
    relative to the *ceiling*, at v_{T4∈pulley3} = (0, 2·v) and v_C3 = (0, −2·v)")."""
    _, doc = explained(name)
    from kinematika.explain.document import CentreNote

    notes = [b for b in doc.blocks() if isinstance(b, CentreNote) and b.how == "parallel"]
    page = rendered(name, lang, drawings=False)
    lines = [line for line in page.splitlines() if LINEAR[lang] in line]
    assert len(lines) >= len(notes) > 0 or not notes
    for note, line in zip(notes, lines):
        a, b = note.pair
        head = line[:line.index(LINEAR[lang])]
        assert f"*{_called(name, b, lang)}" in head, (b, head)      # Basque declines it: *3. polearen*
        for p, _ in note.witnesses:         # v_C3, v_{T4∈politja3}: its velocity as the steps write it
            assert re.search(r"v_\{?" + re.escape(p) + r"(∈[^}]*)?\}? = \(", head), (p, head)


# by hand, on the pages the readers read --------------------------------------------------------

def test_the_epicyclic_planets_by_hand():
    """C5-1.4: each planet's axle moves with the carrier, 2r from O: |v_A| = 2rω; its contact
    with the ring moves with the ring, 3r from O: |v| = 3rω the other way. The speed falls
    linearly to zero between them: d / (r − d) = 2 / 3, d = 2r/5 from the axle (the notes'
    (2/5)r), and ω_planet = −(2rω) / (2r/5) = −5ω. Planet 2's axle is at 30°: A2 = (√3 r, r),
    its centre 2r/5 further out along 30°: (6√3 r/5, 6r/5); planet 3's at 150°: (−6√3 r/5, 6r/5).
    All three are found from the ring and the carrier, each through its centre."""
    page = rendered("seed_c5_1_4_epicyclic", "en", drawings=False)
    assert "5. *Planet 2*, from the *ring* and the *carrier*." in page
    assert "6. *Planet 3*, from the *ring* and the *carrier*." in page
    for n, where in ((1, "(0, −12·r/5)"), (2, "(6·√3·r/5, 6·r/5)"), (3, "(−6·√3·r/5, 6·r/5)")):
        assert f"at 2·r/5 from A{n}: at {where}." in page, n
        assert f"⇒ ω_planet{n} = −5·ω" in page, n
    assert "by symmetry" not in page
    answers = _section(page, "Answers")
    assert "planet 2* relative" not in answers and "planet 3*" not in answers      # only what is asked


def test_the_catalan_epicyclic_planets_read_alike():
    """The Catalan reader's page: the three planet steps each place the planet's centre and
    read ω off it, none from the sun."""
    page = rendered("seed_c5_1_4_epicyclic", "ca", drawings=False)
    for n in (1, 2, 3):
        step = _own_step(page, "Velocitats", f"rodeta {n}")
        assert step is not None and step.startswith(f"\nI_{{rodeta{n}}}: "), n
        assert f"v_{{I_{{rodeta{n}}}}} = (0; 0)" in step and "v_{K∈roda central}" not in step, n


def test_the_upper_wheel_by_hand():
    """C5-E.4 (ca): seen from the chassis both axles are fixed and the wheels of equal radius R
    roll on each other, so ω_{sup rel xassís} = −ω_{esq rel xassís} = −v/R (the left wheel's v/R,
    the chassis not turning); then v_P = v_U + ω × UP = (−v, 0) + (−v/R) k × (0, R)
    = (−v, 0) + (v, 0) = 0: P is the centre (the notes' "(→v) + (←v) = 0"). The accelerations
    differentiate the same relation: α = −v̇/R."""
    page = rendered("seed_c5_e4_upper_wheel", "ca", drawings=False)
    velocities, accelerations = _section(page, "Velocitats"), _section(page, "Acceleracions")
    assert "ω_{roda3 rel xassís} = −ω_{roda1 rel xassís} = −v/R" in velocities
    assert "- v_PU = ω_roda3 × UP = (v; 0)" in velocities and "- v_P = (0; 0)" in velocities
    assert "v_NP" not in velocities and "trobat a «Centres instantanis de rotació (CIR)»: v_P = 0" not in velocities
    assert "α_{roda3 rel xassís} = −α_{roda1 rel xassís} = −v̇/R" in accelerations


def test_the_bicycle_front_wheel_by_hand():
    """C5-E.6 (es): the front wheel rolls on the road with its hub F moving with the frame at
    v: v_F = v_{J∈wheel} + ω × JF with v_J = 0 and JF = (0, R_rueda): v = −ω R_rueda, ω = −v/R_rueda,
    written as the rear wheel's step writes it."""
    page = rendered("seed_c5_e6_bicycle", "es", drawings=False)
    step = _own_step(page, "Velocidades", "rueda delantera")
    assert step is not None
    assert "v_F  =  v_{J∈rueda2}  +  v_FJ" in step
    assert "⇒ ω_rueda2 = −v/R_rueda" in step
    rear = next(text for heading, text in _steps(_section(page, "Velocidades")) if "*rueda trasera*" in heading)
    assert "v_H  =  v_{G∈rueda1}  +  v_HG" in rear


def test_the_tricycle_precession_by_hand():
    """C5-2.1 (ca): the notes' ψ̇ is the chassis' angular velocity (C5.2: Ω_xassís = ψ̇); the
    notation line says it before step 1 writes v_{F,I_xassís} = ψ̇ × I_xassís F."""
    page = rendered("seed_c5_2_1_tricycle", "ca", drawings=False)
    told = page.index("Notació: ψ̇ (la precessió) és la velocitat angular del *xassís*")     # round 29a
    assert told == page.index("ψ̇") - len("Notació: ")
    assert told < page.index("v_{FI_{xassís}} = ψ̇ × I_{xassís}F")


def test_the_belt_and_the_pulleys_by_hand():
    """C5-1.6 (ca): "el tram recte de la corretja es trasllada"; C5-1.5 (ca): the third pulley's
    contact T4 with strand 4 rises at 2v and its centre C3 falls at 2v (the notes' ↑2v, ↓2v),
    so its centre is midway, r/2 from C3."""
    belt = rendered("seed_c5_1_6_belt", "ca", drawings=False)
    assert "els eixos són fixos i el tram recte de la *corretja* es trasllada" in belt
    assert "ω_corretja" not in belt          # round 29 c: the notes give the belt no rate
    pulleys = rendered("seed_c5_1_5_pulley_block", "ca", drawings=False)
    assert ("I_{politja3}: els punts T4 i C3 de la *politja 3* es mouen, respecte del *sostre*, amb "
            "v_{T4∈politja3} = (0; 2·v) i v_C3 = (0; −2·v)") in pulleys
    assert "a r/2 de C3" in pulleys
