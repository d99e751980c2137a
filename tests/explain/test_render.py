"""Every worked example of the notes explained in the four languages and three formats;
the pages are self-contained and carry the solver's final numbers; the command works."""
from __future__ import annotations

import re
import shutil
import subprocess
import sys

import pytest

from kinematika.explain import LANGS, render
from kinematika.explain.catalogue import catalogue
from kinematika.questions import answer
from kinematika.report.values import plain

from tests.conftest import KINDS, sampled

from .helpers import EXAMPLES, WORKED, explained

# the notes' examples of each kind (every one in a deep run)
NOTES = sampled(WORKED, KINDS)


@pytest.mark.parametrize("name", NOTES)
def test_explained_in_four_languages(name):
    sol, doc = explained(name)
    for lang in LANGS:
        cat = catalogue(lang)
        for fmt in ("md", "html", "tex"):
            text = render(doc, lang, fmt, drawings=False)
            title = cat.get("sec.velocities" if sol.space.dim == 2 else "sec.rates")
            if fmt != "tex":
                assert title in text, (name, lang, fmt)
            assert cat.get("sec.answers") in text or fmt == "tex"


@pytest.mark.parametrize("name", sampled([n for n in WORKED if not n.endswith("symbolic")][:8] + ["four_bar", "quick_return"],
                                         KINDS | {"seed_c5_1_1_pulley_on_cable"}))
def test_html_is_self_contained_and_has_the_final_numbers(name):
    sol, doc = explained(name)
    page = render(doc, "eu", "html")
    assert "<script" not in page and "<link" not in page and "@import" not in page
    assert re.findall(r"(?:src|href)=\"https?:", page) == []
    assert page.count("<svg") == page.count("</svg>")
    if sol.symbolic:
        return
    for q in sol.model.questions:
        if q.kind not in ("velocity", "acceleration", "omega", "alpha"):
            continue
        value = plain(answer(sol, q), False)
        for x in (value if isinstance(value, list) else [value]):
            if abs(x) > 1e-9:
                assert f"{x:.4g}".replace("-", "−").replace(".", ",") in page, (name, q.echo, x)


def test_symbolic_formulas_are_written_exactly():
    sol, doc = explained("seed_c5_e2_gear_change")
    page = render(doc, "ca", "html")
    assert "4·<i>Ω</i>/3" in page and "Omega" not in page          # the parameter Omega as the letter, in italics


def test_command_line(tmp_path):
    """The page written by the command (in this process, by click's runner); a language it
    does not know is one line and exit status 2 from the command itself (a child process)."""
    from typer.testing import CliRunner

    from kinematika.cli import app

    out = tmp_path / "fb.html"
    run = CliRunner().invoke(app, ["explain", str(EXAMPLES / "four_bar.yaml"), "--lang", "ca", "--format", "html",
                                   "-o", str(out)])
    assert run.exit_code == 0 and run.exception is None, run.output
    assert "Velocitats" in out.read_text(encoding="utf-8")
    bad = subprocess.run([sys.executable, "-m", "kinematika", "explain", str(EXAMPLES / "four_bar.yaml"),
                          "--lang", "fr"], capture_output=True, text=True)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and "fr" in bad.stderr
    assert len(bad.stderr.strip().splitlines()) == 1


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="no TeX engine here")
def test_latex_compiles(tmp_path):
    _, doc = explained("seed_001_p_pair_coriolis")
    (tmp_path / "p.tex").write_text(render(doc, "eu", "tex"), encoding="utf-8")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", "p.tex"],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    assert (tmp_path / "p.pdf").stat().st_size > 10000


@pytest.mark.parametrize("name, drawings", [("quick_return", 1), ("fan_composition", 1), ("seed_c5_2_1_tricycle", 2)])   # centres only when asked
def test_figures_are_the_draw_figures(name, drawings):
    """The mechanism (3D too) and its instant centres as `kinematika draw` draws them, bare
    (captions in the page's language), ids unique across the page; a symbolic model's
    caption gives the numbers it is drawn at."""
    sol, doc = explained(name)
    page = render(doc, "es", "html")
    assert page.count('<figure class="drawing">') == drawings
    ids = re.findall(r'\bid="([^"]+)"', page)
    assert len(ids) == len(set(ids)), "ids repeated across the inline figures"
    refs = set(re.findall(r'url\(#([^)]+)\)|href="#([^"]+)"', page))
    assert {r for pair in refs for r in pair if r} <= set(ids)
    assert "<!-- velocity -->" not in page                     # no English legend
    if sol.symbolic:
        assert ("Dibujado con" in page and "1,2" in page) or "1.2" in page


def test_numbers_as_each_language_writes_them():
    """A decimal comma in Spanish, Catalan and Basque (Babel's), so a vector's components
    are parted by semicolons; English keeps the point and the comma."""
    _, doc = explained("four_bar")
    en, es = render(doc, "en", "md", drawings=False), render(doc, "es", "md", drawings=False)
    assert "(−9.117, −1.576) m/s" in en and "(−9,117; −1,576) m/s" in es
    # pairs run together as the slides write them (v_BA, AB), O2 and O4 beside them
    assert "ω_3 = −|v_BA| / AB = −0,4516 rad/s" in render(doc, "ca", "md", drawings=False)
    assert "0,4516" in render(doc, "eu", "html", drawings=False)


def test_a_bar_is_turned_in_a_tables_cell_only():
    """Markdown as plain text: |v_A| reads as written in a sentence; inside a pipe table's cell
    a bar would end the cell, so a table holding one is written as a list of its rows, the
    bar as it is (sixteenth round: one bar character a page), never a backslash the reader
    sees; ">" and "<" between words are not escaped."""
    from kinematika.explain.render.markdown import MarkdownRenderer

    r = MarkdownRenderer.__new__(MarkdownRenderer)
    assert r.esc("AI = |v_A| / |ω|") == "AI = |v_A| / |ω|"
    table = r.table(["what", "value"], [["|v_A|", "3"]])
    assert table.splitlines() == ["- |v_A|: 3"]
    assert r.table(["what", "x", "y"], [["|v_A|", "3", "4"]]).splitlines() == ["- |v_A|: x: 3; y: 4"]
    assert r.table(["what", "value"], [["v_A", "3"]]).splitlines()[2] == "| v_A | 3 |"
    assert r.esc("(r₂ − r₁)² > r₁² and r < R") == "(r₂ − r₁)² > r₁² and r < R"
    assert r.esc("> quoted") == "\\> quoted" and r.esc("<b>") == "\\<b>"
