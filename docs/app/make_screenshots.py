"""Screenshots of the page (docs/app.md), through headless Debian Chromium.

    .venv/bin/python docs/app/make_screenshots.py

Starts `kinematika app --no-browser` on a free port of 127.0.0.1 and photographs the page
at a few moments of its use. Needs Chromium (`bash scripts/browser.sh`).
"""
from __future__ import annotations

import math
import re
import subprocess
import sys
import time
from pathlib import Path

import httpx
from playwright.sync_api import sync_playwright

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run"]


def serve() -> tuple[subprocess.Popen, str]:
    proc = subprocess.Popen([sys.executable, "-m", "kinematika", "app", "examples/four_bar.yaml",
                             "--no-browser", "--port", "0"], cwd=ROOT, text=True,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    url = re.search(r"http://127\.0\.0\.1:\d+/", proc.stdout.readline()).group(0)
    for _ in range(100):
        try:
            if httpx.get(url + "api/start").status_code == 200:
                break
        except httpx.HTTPError:
            time.sleep(0.1)
    return proc, url


def ready(page) -> None:
    page.wait_for_function("() => window.kinematika && window.kinematika.state.solution"
                           " && document.getElementById('busy').hidden")
    page.wait_for_timeout(700)


def slide(page, k: int) -> None:
    page.evaluate("""(k) => { const s = document.querySelector('[data-testid=input-slider]');
        s.value = String(k); s.dispatchEvent(new Event('input', {bubbles: true})); }""", k)
    page.wait_for_timeout(900)


def example(page, name: str) -> None:
    gen = page.evaluate("window.kinematika.state.gen")
    page.get_by_test_id("example").select_option(name)
    page.wait_for_function(f"() => window.kinematika.state.gen > {gen}")
    ready(page)


def building(page) -> None:
    """The offset slider-crank of tests/web/test_build.py built by hand from a blank model."""
    sys.path.insert(0, str(ROOT))
    from tests.web import test_build as tb

    tb.blank(page)
    tb.tool(page, "pivot", lambda: tb.click_at(page, (0, 0)))
    tb.tool(page, "link", lambda: tb.click_point(page, "O1"), lambda: tb.click_at(page, (0.04, 0.02)))
    tb.typed(page, "prop-length", "50 mm")
    tb.typed(page, "prop-angle", "30")
    tb.tool(page, "link", lambda: tb.click_point(page, "A"), lambda: tb.click_at(page, (0.18, 0.0)))
    tb.typed(page, "prop-length", "150 mm")
    page.screenshot(path=HERE / "build-links.png", clip={"x": 0, "y": 0, "width": 1440, "height": 800})
    tb.tool(page, "slider", lambda: tb.click_point(page, "B"))
    tb.typed(page, "prop-line-y", "-20 mm")
    page.get_by_test_id("tool-select").click()
    tb.selected(page, lambda: tb.click_body(page, "O1", "A"), "link1")
    page.get_by_test_id("properties").get_by_test_id("input-omega").fill("10")
    tb.step(page, lambda: page.get_by_test_id("set-input").click())
    tb.selected(page, lambda: tb.click_point(page, "B"), "B")
    tb.step(page, lambda: page.get_by_test_id("ask-velocity").click())
    page.frame_locator("[data-testid=explanation]").locator("h1").first.wait_for(timeout=60000)
    page.set_viewport_size({"width": 1440, "height": 1500})   # (a full-page shot leaves the frame blank)
    page.wait_for_timeout(1200)
    page.screenshot(path=HERE / "build-slider-crank.png")
    page.set_viewport_size({"width": 1440, "height": 1000})


def languages(page) -> None:
    for lang in ("es", "ca", "eu"):
        gen = page.evaluate("window.kinematika.state.gen")
        page.get_by_test_id("ui-language").select_option(lang)
        page.wait_for_function(f"() => window.kinematika.state.gen > {gen}")
        ready(page)
        page.wait_for_timeout(1500)
        page.screenshot(path=HERE / f"four_bar.{lang}.png", clip={"x": 0, "y": 0, "width": 1440, "height": 1000})
    page.get_by_test_id("ui-language").select_option("en")
    ready(page)


def phone_shot(browser, url: str) -> None:
    phone = browser.new_page(viewport={"width": 390, "height": 844}, bypass_csp=True)
    phone.goto(url)
    ready(phone)
    slide(phone, 125)
    phone.screenshot(path=HERE / "phone.png", full_page=True)
    phone.close()


def as_a_student(browser, url: str) -> None:
    """The page as a student meets it (issue 35), at 1400 × 900 and 390 × 844, in Basque and
    Catalan: building with a hint (not an error) of what is missing, a renamed rod, one word
    for its length; the crank turned by hand; on a phone, the properties by the figure and
    every answer in the panel."""
    sys.path.insert(0, str(ROOT))
    from tests.web import test_build as tb

    page = browser.new_page(viewport={"width": 1400, "height": 900}, bypass_csp=True)
    page.goto(url)
    ready(page)
    page.get_by_test_id("ui-language").select_option("eu")
    ready(page)
    tb.step(page, lambda: page.get_by_test_id("new-model").click())
    tb.tool(page, "pivot", lambda: tb.click_at(page, (0, 0)))
    tb.tool(page, "link", lambda: tb.click_point(page, "O1"), lambda: tb.click_at(page, (0.04, 0.02)))
    tb.typed(page, "prop-length", "50 mm")
    tb.typed(page, "prop-angle", "30")
    tb.tool(page, "link", lambda: tb.click_point(page, "A"), lambda: tb.click_at(page, (0.18, 0.0)))
    tb.typed(page, "prop-length", "150 mm")
    tb.tool(page, "slider", lambda: tb.click_point(page, "B"))
    page.get_by_test_id("tool-select").click()
    page.wait_for_timeout(500)
    page.screenshot(path=HERE / "building.eu.png")
    tb.selected(page, lambda: tb.click_body(page, "O1", "A"), "barra1")
    page.get_by_test_id("properties").get_by_test_id("input-omega").fill("10")
    tb.step(page, lambda: page.get_by_test_id("set-input").click())
    tb.selected(page, lambda: tb.click_body(page, "A", "B"), "barra2")
    field = page.get_by_test_id("properties").locator("input[data-testid=rename]")
    tb.step(page, lambda: (field.fill("biela"), field.press("Enter")))
    tb.selected(page, lambda: tb.click_point(page, "B"), "B")
    tb.step(page, lambda: page.get_by_test_id("ask-velocity").click())
    page.wait_for_timeout(1500)
    page.screenshot(path=HERE / "student.eu.png")
    page.close()

    page = browser.new_page(viewport={"width": 1400, "height": 900}, bypass_csp=True)
    page.goto(url)
    ready(page)
    page.get_by_test_id("ui-language").select_option("ca")
    ready(page)
    page.locator("#new-menu summary").click()
    tb.step(page, lambda: page.get_by_test_id("new-slider-crank").click())
    page.get_by_test_id("by-hand").click()
    box = page.locator('#figure [data-handle="A"]').bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, 13):                        # the crank (50 mm at 30°) turned by hand, 120°
        t = math.radians(30 + 10 * i)
        page.mouse.move(*page.evaluate(f"window.kinematika.toScreen([{0.05 * math.cos(t)}, {0.05 * math.sin(t)}])"))
    page.mouse.up()
    page.wait_for_timeout(1500)
    page.screenshot(path=HERE / "by-hand.ca.png")
    page.close()

    for lang in ("eu", "ca"):
        phone = browser.new_page(viewport={"width": 390, "height": 844}, bypass_csp=True)
        phone.goto(url)
        ready(phone)
        phone.get_by_test_id("ui-language").select_option(lang)
        ready(phone)
        phone.wait_for_timeout(800)
        handle = phone.locator('#figure [data-handle="B"]').bounding_box()
        phone.mouse.click(handle["x"] + handle["width"] / 2, handle["y"] + handle["height"] / 2)
        phone.wait_for_timeout(1200)
        phone.screenshot(path=HERE / f"phone-properties.{lang}.png")
        phone.get_by_test_id("close-properties").click()
        phone.locator("#answers").scroll_into_view_if_needed()
        phone.evaluate("document.querySelector('.answers-panel').scrollIntoView({block: 'start'})")
        phone.wait_for_timeout(500)
        phone.screenshot(path=HERE / f"phone-answers.{lang}.png")
        phone.close()


def main() -> None:
    proc, url = serve()
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
            if "--student" in sys.argv:          # only the page as a student meets it
                as_a_student(browser, url)
                return
            page = browser.new_page(viewport={"width": 1440, "height": 1000}, bypass_csp=True)
            page.goto(url)
            ready(page)
            page.screenshot(path=HERE / "four_bar.png")
            languages(page)
            building(page)
            phone_shot(browser, url)
            if "--only-new" in sys.argv:      # the building, the languages, the phone
                return
            page.goto(url)
            ready(page)
            slide(page, 125)
            page.get_by_test_id("language").select_option("eu")
            page.set_viewport_size({"width": 1440, "height": 1620})
            page.wait_for_timeout(1200)
            page.screenshot(path=HERE / "four_bar-moved.png")
            page.set_viewport_size({"width": 1440, "height": 1000})
            editor = page.get_by_test_id("model-editor")
            editor.fill(editor.input_value().replace("at: O4}", "at: Q4}"))
            page.get_by_test_id("error").wait_for(state="visible")
            page.wait_for_timeout(300)
            page.screenshot(path=HERE / "error.png", clip={"x": 0, "y": 0, "width": 1440, "height": 720})
            page.get_by_test_id("ui-language").select_option("en")
            for name, k in (("quick_return.yaml", 60), ("planetary_gears.yaml", 0),
                            ("jansen_leg.yaml", 200), ("robot_arm_3d.yaml", 60),
                            ("spherical_four_bar.yaml", 24)):
                example(page, name)
                if k:
                    slide(page, k)
                page.screenshot(path=HERE / name.replace(".yaml", ".png"),
                                clip={"x": 0, "y": 0, "width": 1440, "height": 1000})
            browser.close()
    finally:
        proc.terminate()
        proc.wait(10)
    print("wrote", *sorted(p.name for p in HERE.glob("*.png")))


if __name__ == "__main__":
    main()
