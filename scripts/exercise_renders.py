"""The renders docs/exercises.md shows: a Basque sheet of the quick-return with a student's
name, the start of the Catalan key of the notes' epicyclic train (its contents and a
variant), the statement figures of the quick-return, the epicyclic train and the four-bar,
one quiz question as Moodle shows it with three answers (right, the Coriolis term left out,
degrees taken as radians), and the page's exercise mode with two answers checked. Needs
Chromium.

    .venv/bin/python scripts/exercise_renders.py [OUT]       (default docs/exercises)
"""
from __future__ import annotations

import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from kinematika.exercise import make_exercise, write_exercise  # noqa: E402
from kinematika.exercise.printing import screenshots  # noqa: E402
from kinematika.model.files import load_model  # noqa: E402
from tests.exercise.moodle_view import question_page  # noqa: E402

P_PAIR = ROOT / "examples" / "exercises" / "p_pair_coriolis.yaml"
FOUR_BAR = ROOT / "examples" / "exercises" / "four_bar.yaml"
QUICK_RETURN = ROOT / "examples" / "exercises" / "quick_return.yaml"
EPICYCLIC = ROOT / "examples" / "exercises" / "epicyclic.yaml"
CLASS = ("ID zenbakia;Izena;Abizenak;Helbide elektronikoa\n"
         "7001;Ane;Etxeberria Lasa;ane.etxeberria@ikasle.eus\n7002;Iñaki;Ibáñez Goñi;inaki.ibanez@ikasle.eus\n")
WIDTH = 794                       # an A4 page's width at 96 px per inch


def crop(png: Path, height: int) -> None:
    from PIL import Image

    with Image.open(png) as im:
        im.crop((0, 0, im.width, min(height, im.height))).save(png, optimize=True)


def page_render(work: Path, png: Path) -> None:
    """The page's exercise mode opened by a link of links.txt, two answers checked."""
    from playwright.sync_api import sync_playwright

    from kinematika.exercise.printing import FLAGS, chromium
    from kinematika.web.server import Start
    from tests.web.page_server import PageServer

    ex = make_exercise(load_model(P_PAIR), ["s=300:500:10", "beta=20:40:1", "w=2:6:0.5"], 1, 7, "eu",
                       source=P_PAIR)
    write_exercise(ex, work / "page", solutions=False, pdf=False)
    fragment = (work / "page" / "links.txt").read_text().split("\t")[1].strip()
    v = ex.variants[0]
    wrong = {m.kind: m for m in v.mistaken}["coriolis-omitted"].rows["q2"].value
    server = PageServer(Start())
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path=chromium(), args=FLAGS)
            page = browser.new_page(viewport={"width": 900, "height": 1130})
            page.goto(server.url + fragment)
            page.get_by_test_id("exercise-input-q1").fill(f"{v.rows[0].value:.4g}".replace(".", ","))
            page.get_by_test_id("exercise-input-q2").fill(f"{wrong:.4g}".replace(".", ","))
            page.get_by_test_id("exercise-check").click()
            page.get_by_test_id("exercise-score").filter(has_text="10").wait_for()
            page.screenshot(path=str(png), full_page=True)
            browser.close()
    finally:
        server.stop()


def main(out: Path) -> None:
    from kinematika.exercise.roster import read_class

    out.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp())
    shots = []
    roster = work / "class.csv"
    roster.write_bytes(CLASS.encode("cp1252"))                    # as Excel saves it in Basque
    qr = make_exercise(load_model(QUICK_RETURN), ["th=20:160:5", "w=5:15:1"], 2, 11, "eu", source=QUICK_RETURN,
                       students=read_class(roster))
    write_exercise(qr, work / "qr", pdf=False)
    shots.append((work / "qr" / "sheets.html", out / "sheet-eu.png", 1122))
    shutil.copy(work / "qr" / "figures" / "variant-001.png", out / "figure-quick-return-eu.png")
    ep = make_exercise(load_model(EPICYCLIC), ["r=30:80:5", "w=2:20:1"], 2, 11, "ca", source=EPICYCLIC)
    write_exercise(ep, work / "ep", pdf=False)
    shots.append((work / "ep" / "key.html", out / "key-ca.png", 2000))
    shutil.copy(work / "ep" / "figures" / "variant-001.png", out / "figure-epicyclic-ca.png")
    ex = make_exercise(load_model(P_PAIR), ["s=300:500:10", "beta=20:40:1", "w=2:6:0.5"], 2, 7, "eu",
                       source=P_PAIR)
    write_exercise(ex, work / "pp", pdf=False)
    quiz = (work / "pp" / "quiz.xml").read_text(encoding="utf-8")
    v = ex.variants[0]
    mistakes = {m.kind: m for m in v.mistaken}
    rows = [r.question for r in v.rows]
    answers = {1: repr(v.rows[0].value),
               2: repr(mistakes["coriolis-omitted"].rows["q2"].value),
               rows.index("q5.x") + 1: repr(mistakes["degrees-as-radians"].rows["q5.x"].value)}
    page = work / "moodle.html"
    page.write_text(question_page(quiz, 1, answers), encoding="utf-8")
    shots.append((page, out / "moodle-question-eu.png", 1500))
    fb = make_exercise(load_model(FOUR_BAR), ["a=25:35:1", "theta2=0:355:5"], 1, 3, "ca", source=FOUR_BAR)
    write_exercise(fb, work / "four_bar", solutions=False, pdf=False)
    shutil.copy(work / "four_bar" / "figures" / "variant-001.png", out / "figure-four-bar-ca.png")
    screenshots([(html, png) for html, png, _ in shots], width=WIDTH)
    for _, png, height in shots:
        crop(png, height)
    page_render(work, out / "page-exercise-eu.png")
    crop(out / "page-exercise-eu.png", 1130)
    print("\n".join(str(png) for _, png, _ in shots))


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "docs" / "exercises")
