"""Issue 30, twenty-fourth round (d): two readers' items on main's pages.

- every body, and every point velocity, is derived in a numbered step that the order of
  solution lists, in the velocities and in the accelerations; the summary of rates after
  the steps only collects (C5-E.6's front wheel, "v_F = v_H = (v, 0)" and its ω and α, and
  C5-1.2's "v_Q = ω_OQ × I_{OQ}Q" and both wheels' ω were worked out under "Angular
  velocities", and the order never named the *front wheel*);
- the answers are a table of the asked quantities on every page: the working of an answer
  (the intrinsic split's |v_P|, t = v_P/|v_P|, a_P^t · t, |a_P^n|) is derived in a section
  before them (C5-1.7's answers were the only bullet list, their row carried that working).
"""

from __future__ import annotations

import re

from kinematika.explain.document import Derived, Equation, Msg

from .helpers import LANGS, SEEDS, explained, over, rendered

SUMMARY = ("sec.rates_summary", "sec.rates_summary_v")
LEVELS = ("sec.velocities", "sec.accelerations")


def _parts(name: str, lang: str) -> dict[str, str]:
    """The page's level-2 sections' Markdown, by their key in the document (one `## ` heading a
    section, in the document's order)."""
    _, doc = explained(name)
    md = rendered(name, lang, drawings=False)
    chunks = re.split(r"^## ", md, flags=re.M)[1:]
    assert len(chunks) == len(doc.sections), (len(chunks), len(doc.sections))
    return {s.title.key: c for s, c in zip(doc.sections, chunks)}


@over(name=SEEDS, lang=LANGS)
def test_d_the_rates_summary_only_collects(name: str, lang: str) -> None:
    """The summary of rates holds its table and derives nothing (no rate or velocity read off,
    no rolling or symmetry reason); every body of its table has a numbered step titled by it
    in the velocities (and the accelerations when written) and an item in the order."""
    _, doc = explained(name)
    parts = _parts(name, lang)
    # the ground a drive wraps is listed with its 0 (round 29 c: C5-1.6's fixed pulley): no step of its own
    for sec in (s for s in doc.sections if s.title.key in SUMMARY):
        derived = [b for b in sec.leaves() if isinstance(b, (Derived, Equation))
                   or (isinstance(b, Msg) and b.key.startswith(("idle.rolling", "idle.symmetry")))]
        assert not derived, derived
        summary = parts[sec.title.key]
        said = [ln for ln in summary.splitlines()[1:] if ln and not ln.startswith(("|", "*", "!", "["))]
        assert not [ln for ln in said if " = " in ln], said
        bodies = [ln.split(" | ")[0].strip("| ") for ln in summary.splitlines() if ln.startswith("| *")
                  and not all(c.strip() == "0" for c in ln.strip("|").split("|")[1:])]
        order = re.search(r"^### .*\n(?:(?!^##).*\n)*", parts["sec.structure"], flags=re.M)
        assert order is not None
        listed = "\n".join(ln for ln in order.group(0).splitlines() if re.match(r"\d+\. ", ln))
        for level in (k for k in LEVELS if k in parts):
            titles = "\n".join(ln for ln in parts[level].splitlines() if ln.startswith("### "))
            missing = [b for b in bodies if b.lower() not in titles.lower()]
            assert not missing, (level, missing)
        unlisted = [b for b in bodies if b.lower() not in listed.lower()]
        assert not unlisted, ("order", unlisted)


@over(name=SEEDS, lang=LANGS)
def test_d_the_answers_are_a_table_of_asked_quantities(name: str, lang: str) -> None:
    """Every page's answers are a table (no list of rows), and no answer carries a magnitude
    |…| or the unit tangent: the working is derived before, in the page's sections."""
    parts = _parts(name, lang)
    answers = parts["sec.answers"]
    rows = [ln for ln in answers.splitlines() if ln.startswith("| ")]
    assert len(rows) >= 3, answers[:300]
    assert not [ln for ln in answers.splitlines() if ln.startswith("- ")], answers[:300]
    for row in rows[2:]:
        answer = row.rsplit(" | ", 1)[-1]
        assert "|" not in answer.rstrip(" |") and " t = " not in answer, row


def test_d_the_intrinsic_working_comes_before_the_answers() -> None:
    """C5-1.7: |v_P|, t = v_P/|v_P|, a_P^t · t and |a_P^n| are derived in the curvature section
    (ω, ω̇ and r the notes' symbols), and the answer row gives a_P^t and a_P^n alone."""
    want = {"en": "(2·r·ω̇, 0); a_P^n = (0, −4·r·ω²/3) |", "es": "(2·r·ω̇; 0); a_P^n = (0; −4·r·ω²/3) |",
            "ca": "(2·r·ω̇; 0); a_P^n = (0; −4·r·ω²/3) |", "eu": "(2·r·ω̇; 0); a_P^N = (0; −4·r·ω²/3) |"}
    for lang in LANGS:
        n, t = ("N", "T") if lang == "eu" else ("n", "t")       # the Basque slides' a^N (27th round (g))
        parts = _parts("seed_c5_1_7_semicylinder", lang)
        working = parts["sec.curvature"]
        for said in ("|v_P| = 2·r·ω", "t = v_P/|v_P| = (1", "a_P · t = 2·r·ω̇", f"|a_P^{n}| = 4·r·ω²/3"):
            assert said in working, (lang, said)
        row = next(ln for ln in parts["sec.answers"].splitlines() if f"a_P^{t}" in ln)
        assert row.endswith(want[lang]) and row.count(" = ") == 2, (lang, row)


def test_d_the_wheels_are_steps_of_their_own() -> None:
    """C5-E.6 and C5-1.2, the readers' words: "3. The *front wheel*, from the *ground* and
    the *frame*." in the order, a step for it in the velocities and the accelerations (Step 3
    since round 27b: the step the solution finds it in, with the vector equations the rear
    wheel's step writes), v_F and a_F written in the frame's step; v_Q = v_{I_{OQ}} + v_{QI_{OQ}}
    in Step 1 of C5-1.2, the right wheel's ω read off v_Q = v_{K2∈wheel} + v_QK2 right after."""
    parts = _parts("seed_c5_e6_bicycle", "en")
    assert "3. The *front wheel*, from the *ground* and the *frame*." in parts["sec.structure"]
    for level, line in (("sec.velocities", "JF = (0, R_wheel); along x: v_FJ = −ω_wheel2·R_wheel ⇒ ω_wheel2 = −v/R_wheel"),
                        ("sec.accelerations", "JF = (0, R_wheel); along x: a_F^t = −α_wheel2·R_wheel ⇒ α_wheel2 = −v̇/R_wheel")):
        step = parts[level].split("### Step 3: the *front wheel*\n")[1].split("### Step 4")[0]
        assert line in step, level
        assert ("v_F = v_H" if level == "sec.velocities" else "a_F = a_H") in parts[level].split("### Step 2")[0]
    es = _parts("seed_c5_e6_bicycle", "es")["sec.structure"]
    assert re.search(r"^3\. La \*rueda delantera\*, a partir del \*suelo\* y del \*cuadro\*\.$", es, flags=re.M), es
    bar = _parts("seed_c5_1_2_bar_on_inclined_wheels", "en")["sec.velocities"]
    step1 = bar.split("### Step 2")[0]
    assert "v_Q  =  v_{I_{OQ}}  +  v_{QI_{OQ}}" in step1
    assert step1.index("v_Q  =  v_{I_{OQ}}") < step1.index("ω_wheel2 = −|v_QK2| / K2Q = −2.91 rad/s")
