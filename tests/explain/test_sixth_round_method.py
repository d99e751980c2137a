"""Issue 30, sixth round (method): the fourth audit's method items, each a rule of the
builder checked where the notes' solution shows it. Values are derived by hand in each
docstring. (C5-1.3's shared rate is checked with the bookkeeping, in test_bookkeeping.py.)"""
from __future__ import annotations

import math
import re

import sympy

from kinematika.explain.document import Equation, Msg, Section

from .helpers import LANGS, explained, num, rendered, over


def _blocks(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        out += _blocks(b) if isinstance(b, Section) else [b]
    return out


def _section(doc, key: str) -> Section:
    return next(s for s in doc.sections if s.title.key == key)


def _sym(expr, name: str):
    return next(s for s in expr.free_symbols if str(s) == name)


# -- a rolling wheel's centre: a_C = α × JC, never a_C = a_CJ^t -------------------------------------------------------
ROLLING_CENTRES = ("seed_c5_e4_upper_wheel", "seed_c5_e5_unequal_wheels", "seed_c5_e6_bicycle")


@over(name=ROLLING_CENTRES)
def test_a_rolling_centre_alone_is_alpha_times_its_radius(name):
    """A wheel's centre found alone on its straight path is its own tangential acceleration,
    a_C = a_C^t, of magnitude α·JC (round 29 c: term by term, as C5-1.7 writes a_C = a_C^t + a_C^n;
    this round had written the product α × JC as the term), never a_C = a_CJ^t, which reads as
    if the contact's acceleration were zero (it is not: only v_J = 0)."""
    _, doc = explained(name)
    alone = [e for e in _blocks(_section(doc, "sec.accelerations")) if isinstance(e, Equation)
             and len(e.sides) == 1 and len(e.sides[0]) == 1 and e.sides[0][0].kind == "tangential"]
    assert alone, name
    for e in alone:
        t = e.sides[0][0]
        assert not t.spelt and t.how[0].base == "α" and (t.sym.sub, t.sym.sup) == (e.target.sym.sub, "t"), e.target.sym
    for lang in LANGS:
        page = rendered(name, lang, drawings=False)
        for m in re.finditer(r"^a_(\S+)\s+=\s+a_\{?([^ }^]+)\}?\^[tT]\s*$", page, re.M):
            assert m.group(1) == m.group(2), (name, lang, m.group(0))


def test_the_bicycle_rear_hub_by_hand():
    """C5-E.6: H at height R_roda over the contact G, a_H = (v̇; 0) (the datum). a_H = α × GH
    with GH = (0; R_roda): α k × (0, R_roda) = (−α·R_roda; 0) = (v̇; 0), so α_rear = −v̇/R_roda;
    the page writes "a_H = α_{atzeko gurpila} × G…H" and α from its x component (twenty-fifth
    round d): "x norabidean: a_H = −α·GH ⇒ α = −v̇/R_gurpila"."""
    _, doc = explained("seed_c5_e6_bicycle")
    eq = next(e for e in _blocks(_section(doc, "sec.accelerations"))
              if isinstance(e, Equation) and e.target.sym.sub == "H" and len(e.sides[0]) == 1)
    t = eq.sides[0][0]
    x, y = t.value
    vd = _sym(sympy.sympify(x), "vd")
    assert sympy.simplify(x - vd) == 0 and sympy.simplify(y) == 0
    alpha = next(d for d in doc.derived() if d.body == "rear" and d.kind == "alpha").value.value
    r = _sym(sympy.sympify(alpha), "R_roda")
    assert sympy.simplify(alpha + vd / r) == 0
    page = rendered("seed_c5_e6_bicycle", "eu", drawings=False)
    assert re.search(r"^a_H\s+=\s+a_H\^T\s*$", page, re.M)       # round 29 c: term by term
    assert "a_H^T = α_gurpila1 × GH = (v̇; 0)" in page            # gurpila1: 27th round (g)
    assert re.search(r"G-?H = \(0; R_gurpila\); x norabidean: a_H\^T = −α_gurpila1·R_gurpila ⇒ α_gurpila1 = −v̇/R_gurpila", page)


# -- 001's rolling pair: the contact section refers to what step 3 wrote ----------------------------------------------
def test_the_contact_section_refers_to_the_steps():
    """001's rolling pair: step 3 writes v_F∈N = v_B + ω_N × BF and a_F∈N likewise; the
    contact section says their values and the step, it does not write the equations again.
    By hand: BA = ρ/sin β = 0.2, ω_N = −v·tan β / BA = −1.443 rad/s, F the foot of A on the
    edge, BF = BA·cos β = 0.1732 along (cos 30°, sin 30°); v_F∈N = ω_N k × BF =
    ω_N·(−0.0866; 0.15) = (0.125; −0.2165) m/s."""
    sol, doc = explained("seed_001_rolling_pair")
    sec = _section(doc, "sec.contact")
    blocks = _blocks(sec)
    assert not [b for b in blocks if isinstance(b, Equation) and b.target.sym.sub == "F∈N"]
    said = {b.args["sym"].base: b for b in blocks if isinstance(b, Msg) and b.key == "contact.written"}
    assert set(said) == {"v", "a"} and all(b.args["step"] == 3 for b in said.values())
    beta, rho, v = math.radians(30), 0.1, 0.5
    ba = rho / math.sin(beta)
    w = -v * math.tan(beta) / ba
    bf = ba * math.cos(beta)
    hand = (-w * bf * math.sin(beta), w * bf * math.cos(beta))
    got = num(sol, said["v"].args["value"].value)
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(got, hand)), (got, hand)
    assert math.isclose(hand[0], 0.125) and math.isclose(hand[1], -0.2165, abs_tol=1e-4)
    for lang in LANGS:
        page = rendered("seed_001_rolling_pair", lang, drawings=False)
        contact = next(s for s in page.split("\n## ") if "v_{F^{geom}}  =" in s)    # the geometric point: the contact section
        assert "v_{F∈N}  =" not in contact and "a_{F∈N}  =" not in contact, lang


# -- C5-1.5: three degrees of freedom under two data, one given whole ------------------------------------------------------------------
def test_the_count_is_the_datas_where_a_whole_velocity_makes_up_the_data():
    """C5-1.5 by hand: 8 moving bodies besides the welded strand 1, 24 unknowns; two pins
    (2 conditions each), the block's guide (2) and eight rolling contacts (2 each), 22
    conditions, one of them dependent (vertical strands tangent to pulleys side by side):
    rank 21, 24 − 21 = 3 degrees of freedom. The statement gives two data, v_C1 (down, along
    the vertical: one condition) and v_C3 = (0; −2v) whole (two): the data fix the motion and
    the notes say nothing of the count. The page said no mobility sentence (the fourth audit
    read "3 degrees of freedom" under two data as a datum missing; the fifth and sixth read the
    sentence explaining it as bookkeeping to delete); it now says two, one a datum."""
    _, doc = explained("seed_c5_1_5_pulley_block")
    said = [b for b in _section(doc, "sec.structure").blocks if isinstance(b, Msg) and b.key.startswith("structure.dof")]
    # twenty-seventh round (e): two teachers missed the count, the only page without one; it is
    # the mobility the statement leaves, one degree a datum, with the direction it gives
    assert [b.key for b in said] == ["structure.dof_data"] and said[0].args["dof"] == 2
    ca = rendered("seed_c5_1_5_pulley_block", "ca", drawings=False)
    assert "tres graus de llibertat" not in ca and "dos graus de llibertat" in ca


def test_a_mechanism_with_as_many_data_as_freedoms_says_the_mobility_alone():
    """Where every datum is one condition (the rolling pair: the slider's speed, one degree of
    freedom) the sentence is the plain one."""
    _, doc = explained("seed_001_rolling_pair")
    said = [b for b in _section(doc, "sec.structure").blocks if isinstance(b, Msg) and b.key.startswith("structure.dof")]
    assert [b.key for b in said] == ["structure.dof"]


# -- C5-2.1: the notes' precession ψ̇ tied to the chassis' rate --------------------------------------------------------
def test_the_precession_is_tied_to_the_chassis_rate():
    """C5-2.1 by hand: the chassis turns about I = (0; L) (the rear axle's line meets the
    normal to v_F at F = (L; 0), v_F at 45°); |v_F| = v₀, IF = √2·L, so ψ̇ = v₀/(√2·L) =
    √2·v₀/(2·L). The notes call the chassis' rate the precession ψ̇: the page finds it as
    "x norabidean: v_{F,I_txasisa} = ψ̇·L ⇒ ψ̇ = ω_txasisa = √2·v₀/(2·L)" (from the term's x
    component, twenty-fifth round (d): I_txasisa F = (L; −L)) and writes ψ̇ after; a datum's rate (the
    fan's ω₁) is not written twice."""
    sol, doc = explained("seed_c5_2_1_tricycle")
    w = next(d for d in doc.derived() if d.body == "chassis" and d.kind == "omega").value.value
    v0, big_l = _sym(sympy.sympify(w), "v0"), _sym(sympy.sympify(w), "L")
    assert sympy.simplify(w - sympy.sqrt(2) * v0 / (2 * big_l)) == 0
    for lang, name in (("eu", "txasisa"), ("ca", "xassís")):
        page = rendered("seed_c5_2_1_tricycle", lang, drawings=False)
        # the centre in full in the subscript (seventeenth round (a)), as the segment FI_{b}
        # to it, the centre braced as everywhere on the page (twenty-seventh round (g))
        assert re.search(rf": v_\{{FI_\{{{name}\}}\}} = ψ̇·L ⇒ ψ̇ = ω_{name} = √2·v₀/\(2·L\)$", page, re.M), lang
        assert f"ω_{name} ×" not in page
    fan = rendered("fan_absolute", "eu", drawings=False)
    assert "ω_1 = ω_" not in fan
