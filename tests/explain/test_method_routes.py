"""Issue 30, third round: the method of the notes, by rule (docs/explain.md, "Method (third
round)").

- A wheel rolling on a profile is explained through its centre, which keeps its distance from
  the profile — never through the geometric contact point in the steps (the slides' rolling
  pair, 4.4; C5-1.7): on a fixed profile the centre's path, and the route goes on from the
  centre (C5-1.3: a_Q = a_SJ^t + a_QS^n + a_QS^t + a_rel + a_Cor, six terms, not eight); on
  a moving edge the slides' axes at the wheel's centre turning with the edge (v_A = v_B +
  v_AB + v_rel ∥ tangent, then a_A = … + a_rel + a_Cor), and the wheel's α from equal
  tangential components at the contact (the normal difference one of the two unknowns).
- The order of solution names dyads only where a step is one, and never how the mechanism
  "does not decompose".
- A body whose ω the explanation works out has its α too: no "—" in the rates' table.
"""
from __future__ import annotations

import math

import pytest

from kinematika.explain.document import GEOM_MARK
from kinematika.explain.document import Equation, Section
from kinematika.explain.needs import LEVELS

from .helpers import LANGS, explained, rendered


def _step_equations(name: str, level: str) -> list[Equation]:
    _, doc = explained(name)
    out: list[Equation] = []

    def walk(blocks):
        for b in blocks:
            if isinstance(b, Section):
                walk(b.blocks)
            elif isinstance(b, Equation) and b.level == level:
                out.append(b)
    for sec in doc.sections:
        if sec.title.key in LEVELS:
            walk(sec.blocks)
    return out


def _syms(eq: Equation) -> list:
    return [eq.target.sym] + [t.sym for side in eq.sides for t in side]


@pytest.mark.parametrize("name", ["seed_001_rolling_pair", "seed_c5_1_3_bar_in_sleeve"])
def test_steps_do_not_go_through_the_geometric_point(name):
    for level in ("v", "a"):
        for eq in _step_equations(name, level):
            assert all(GEOM_MARK not in str(s.sub) for s in _syms(eq)), (name, level, eq.target.sym)
            assert all(t.how is None or repr(GEOM_MARK)[1:-1] not in repr(t.how) for side in eq.sides for t in side)


def test_bar_in_sleeve_acceleration_has_six_terms():
    """a_Q = a_SJ^t + a_QS^n + a_QS^t + a_Q∈bar/support + a_Cor (the old road: eight, with
    a_J∈ground and the contact's term through J^geom)."""
    eqs = [eq for eq in _step_equations("seed_c5_1_3_bar_in_sleeve", "a") if eq.target.sym.sub == "Q"
           and any(t.kind == "coriolis" for side in eq.sides for t in side)]
    assert len(eqs) == 1
    terms = [t for side in eqs[0].sides for t in side]
    assert len(terms) == 5
    assert [t.kind for t in terms] == ["tangential", "normal", "tangential", "slide", "coriolis"]


def test_rolling_pair_lever_by_axes_at_the_wheel_centre():
    """The slides' first slide of 4.4: a_A = a_B + a_AB^n + a_AB^t + a_rel + a_Cor finds α_N
    alone. By hand (B origin, A = (ρ/sin β, 0), the edge along e = (cos β, sin β), v = 0.5,
    a_A = 0): seen from N the centre runs along e at u, so (v, 0) = ω k × BA + u e, and
    0 = −ω² BA + α k × BA + s e + 2 ω k × u e, two scalar equations each."""
    sol, _ = explained("seed_001_rolling_pair")
    rho, beta, v = 0.1, math.radians(30), 0.5
    ba = rho / math.sin(beta)
    e = (math.cos(beta), math.sin(beta))
    # velocities: (v, 0) = ω k × (ba, 0) + u e  →  v = u cos β, 0 = ω ba + u sin β
    u = v / e[0]
    w = -u * e[1] / ba
    # accelerations: 0 = −ω² (ba, 0) + α k × (ba, 0) + s e + 2 ω k × (u e)
    cor = (-2 * w * u * e[1], 2 * w * u * e[0])
    # x: −ω² ba + s cos β + cor_x = 0 ; y: α ba + s sin β + cor_y = 0
    s = (w * w * ba - cor[0]) / e[0]
    alpha = -(s * e[1] + cor[1]) / ba
    eqs = [eq for eq in _step_equations("seed_001_rolling_pair", "a")
           if any(t.kind == "coriolis" for side in eq.sides for t in side)]
    assert len(eqs) == 1
    assert math.isclose(float(sol.alpha("N")), alpha, rel_tol=1e-9)
    tangential = [t for side in eqs[0].sides for t in side if t.kind == "tangential"]
    assert len(tangential) == 1 and math.isclose(tangential[0].value[1], alpha * ba, rel_tol=1e-9)
    # the roller: the contact's term is an unknown along the normal (equal tangential parts)
    contact = [t for eq in _step_equations("seed_001_rolling_pair", "a") for side in eq.sides for t in side
               if t.kind == "contact"]
    assert contact and all(t.unknown for t in contact)


@pytest.mark.parametrize("lang", LANGS)
def test_order_names_dyads_only_where_there_are(lang):
    # the slides write no word for a dyad (4.2: "R loturak dituzten mekanismoak", two
    # elements N and P): the Basque pages say it in theirs (fifth round)
    dyad = {"en": "dyad", "es": "díada", "ca": "díade", "eu": "loturak dituen bi elementuko taldea"}[lang]
    one_wheel = rendered("seed_c5_1_7_semicylinder", lang, "md", False).lower()
    assert dyad not in one_wheel and "assur" not in one_wheel
    assert dyad in rendered("seed_001_r_pairs", lang, "md", False).lower()
    for name in ("seed_c5_1_4_epicyclic", "seed_c5_e2_gear_change"):
        text = rendered(name, lang, "md", False)
        assert "Assur" not in text and dyad not in text.lower()


@pytest.mark.parametrize("name", ["seed_c5_e4_upper_wheel", "seed_c5_e6_bicycle"])
def test_rates_table_has_no_holes(name):
    text = rendered(name, "en", "md", False)
    table = text.split("## Angular velocities and accelerations")[1].split("\n\n\n")[0]
    rows = [r for r in table.splitlines() if r.startswith("| *")]
    assert rows and all("—" not in r for r in rows), table


def test_basque_pages_use_the_slides_words_for_a_dyad():
    """The Basque slides (4.2, 4.3) name no dyad: they solve "R loturak dituzten mekanismoak"
    by their two elements N and P. "diada" is a word they do not use, on no Basque page."""
    for name in ("seed_001_r_pairs", "seed_001_p_pair_coriolis"):
        text = rendered(name, "eu", "md", False)
        assert "diada" not in text.lower(), name
    assert "RRR loturak dituen bi elementuko taldea: *N elementua* eta *P elementua*" in \
        rendered("seed_001_r_pairs", "eu", "md", False)
