"""The renders docs/exercises.md shows: a sheet and a page of the key in eu and ca, the
four-bar's statement figure, one quiz question as Moodle shows it with three answers
(right, the Coriolis term left out, degrees taken as radians), and the page's exercise mode
with two answers checked. Needs Chromium.

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
    wrong = {m.kind: m for m in ex.mistakes(v)}["coriolis-omitted"].rows["q2"].value
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
            page.screenshot(path=str(png))
            browser.close()
    finally:
        server.stop()


def main(out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp())
    shots = []
    for lang in ("eu", "ca"):
        ex = make_exercise(load_model(P_PAIR), ["s=300:500:10", "beta=20:40:1", "w=2:6:0.5"], 2, 7, lang,
                           source=P_PAIR)
        folder = work / lang
        write_exercise(ex, folder, pdf=False)
        shots += [(folder / "sheets.html", out / f"sheet-{lang}.png", 1122),
                  (folder / "key.html", out / f"key-{lang}.png", 2200)]
        if lang == "eu":
            quiz = (folder / "quiz.xml").read_text(encoding="utf-8")
            v = ex.variants[0]
            mistakes = {m.kind: m for m in ex.mistakes(v)}
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
