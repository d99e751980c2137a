"""The page's exercise mode in Chromium: a link of `kinematika exercise`'s links.txt opens a
variant as the whole page — no model editor, no answers, no control that solves, and no
response carrying a value of the key before Check — typed answers are checked (a right one,
the Coriolis term left out) and the worked solution shown after the check."""
from __future__ import annotations

import pytest

from tests.conftest import BROWSER_WAIT, DEEP
from tests.exercise.conftest import P_PAIR, P_PAIR_VARY, make

pytestmark = pytest.mark.browser


def test_the_page_opens_a_link_checks_the_answers_and_shows_the_solution(browser, server, tmp_path):
    """On the web tests' page server and browser (tests/web/conftest.py: one of each for a
    test process); the link holds the model, whatever model the server opened with."""
    from kinematika.exercise import write_exercise

    ex = make(P_PAIR, P_PAIR_VARY, 1, 7, "eu")            # one variant: the page opens one link
    write_exercise(ex, tmp_path, solutions=False, pdf=False)
    fragment = (tmp_path / "links.txt").read_text().splitlines()[0].split("\t")[1]
    v = ex.variants[0]
    mistakes = {m.kind: m for m in v.mistaken}
    context = browser.new_context(viewport={"width": 1000, "height": 1400})
    try:
        _drive(context.new_page(), server.url, fragment, v, mistakes, tmp_path)
    finally:
        context.close()


def _drive(page, url, fragment, v, mistakes, tmp_path):
    """The browser's part: the link opened, the answers typed and checked, the solution shown."""
    page.set_default_timeout(BROWSER_WAIT)      # a hang detector: the page's own requests run too
    seen = []
    page.on("response", lambda r: seen.append(r))  # noqa: PLW0108 - Playwright wraps a Python function
    page.goto(url + fragment)
    page.get_by_test_id("exercise-input-q1").wait_for()         # drawn from the statement's answer
    # the page is the exercise alone: nothing of the builder, nothing that solves
    ids = page.eval_on_selector_all("[data-testid]", "els => els.map(e => e.dataset.testid)")
    assert "model-editor" not in ids and "answers" not in ids
    assert all(i == "exercise" or i.startswith("exercise-") for i in ids), ids
    assert page.locator("textarea, select").count() == 0
    buttons = page.eval_on_selector_all("button", "els => els.map(e => e.dataset.testid)")
    assert sorted(buttons) == ["exercise-check", "exercise-show"] and not page.get_by_test_id("exercise-show").is_visible()
    # before Check: only the exercise's statement was asked for, and no response holds a key value
    api = [r for r in seen if "/api/" in r.url]
    assert [r.url.rsplit("/", 1)[1] for r in api] == ["exercise"]
    text = api[0].text()
    for r in v.rows:
        for written in (f"{r.value:.4g}", f"{r.value:.4g}".replace(".", ","), repr(r.value)):
            assert written not in text, (r.question, written)
    page.get_by_test_id("exercise-input-q1").fill(repr(v.rows[0].value).replace(".", ","))
    page.get_by_test_id("exercise-input-q2").fill(repr(mistakes["coriolis-omitted"].rows["q2"].value))
    page.get_by_test_id("exercise-check").click()
    page.get_by_test_id("exercise-score").filter(has_text="10").wait_for()
    assert page.get_by_test_id("exercise-mark-q1").text_content().startswith("✔")
    assert page.get_by_test_id("exercise-mark-q2").get_attribute("data-diagnosis") == "coriolis-omitted"
    assert _opened(page.get_by_test_id("exercise-link").get_attribute("href")) == _opened(fragment)
    if DEEP:                                  # a picture to look at, not a check
        page.screenshot(path=str(tmp_path / "exercise-page.png"), full_page=True)
    page.get_by_test_id("exercise-show").click()
    page.locator("[data-testid=exercise-solution] iframe").wait_for()
    page.wait_for_function("document.querySelector('[data-testid=exercise-solution] iframe').style.height !== ''")


def _opened(fragment):
    """What a link holds: its parameters, the model's text inflated (browsers and zlib
    deflate the same text to different bytes)."""
    import base64
    import zlib
    from urllib.parse import parse_qs

    params = parse_qs(fragment.lstrip("#"))
    packed = params.pop("model")[0]
    text = zlib.decompress(base64.urlsafe_b64decode(packed + "=" * (-len(packed) % 4)), -15).decode()
    return params, text
