"""Screenshots of the page (docs/app.md), through headless Debian Chromium.

    .venv/bin/python docs/app/make_screenshots.py

Starts `kinematika app --no-browser` on a free port of 127.0.0.1 and photographs the page
at a few moments of its use. Needs Chromium (`bash scripts/browser.sh`).
"""
from __future__ import annotations

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


def main() -> None:
    proc, url = serve()
    try:
        with sync_playwright() as p:
            browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
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
