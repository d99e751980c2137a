"""HTML printed by Chromium: the sheets and the key to PDF (`page.pdf`), and any page to PNG
(to look at it), through Playwright driving the system's Chromium (`/usr/bin/chromium`, or
`chromium` on the path; never a browser Playwright downloads).

Printing is optional: without Playwright or Chromium the HTML files are written all the
same and `missing()` says in one line what to install.
"""
from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any, Callable, Optional

from ..errors import Said
from ..limits import PRINT_SECONDS

CHROMIUM = "/usr/bin/chromium"
FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run"]


def chromium() -> Optional[str]:
    """The Chromium executable, or None."""
    return CHROMIUM if Path(CHROMIUM).exists() else shutil.which("chromium")


def missing() -> Optional[Said]:
    """Why pages cannot be printed here (one line), or None when they can."""
    from ..extras import available, install_hint

    if not available("playwright.sync_api"):
        return Said("pdf-skipped", program="Playwright", hint=install_hint("exercise"))
    if chromium() is None:
        return Said("pdf-skipped", program="Chromium", hint="apt-get install chromium")
    return None


def in_own_thread(work: Callable[[], Any]) -> Any:
    """`work()` in a thread of its own: Playwright's synchronous API refuses a thread that
    runs an asyncio loop (Jupyter's, a server's) or already drives a Playwright."""
    from concurrent.futures import ThreadPoolExecutor

    with ThreadPoolExecutor(1) as pool:
        return pool.submit(work).result()


def print_pdfs(pages: list[tuple[Path, Path]]) -> None:
    """Print each HTML file to its PDF (A4, backgrounds kept), with one browser."""
    with Printer() as printer:
        for html, pdf in pages:
            printer.submit(html, pdf)


class Printer:
    """One browser, in a thread of its own, printing the HTML files handed to it (`submit`)
    one after the other while the caller goes on: started early, Chromium starts while the
    figures are drawn, and the sheets print while the worked solutions are made. Leaving the
    `with` block waits for every file and raises the printing's error, if any.

    Start it after forking worker processes: a fork copies no other thread."""

    def __init__(self) -> None:
        import queue
        import threading

        self._jobs: "queue.Queue[Optional[tuple[Path, Path]]]" = queue.Queue()
        self._thread = threading.Thread(target=self._run, name="kinematika-printer", daemon=True)
        self._error: Optional[BaseException] = None

    def __enter__(self) -> "Printer":
        self._thread.start()
        return self

    def submit(self, html: Path, pdf: Path) -> None:
        """Print `html` to `pdf` after the files handed before it."""
        self._jobs.put((html, pdf))

    def __exit__(self, kind: Any, *rest: Any) -> None:
        self._jobs.put(None)
        self._thread.join()
        if self._error is not None and kind is None:
            raise self._error

    def _run(self) -> None:
        try:
            _print_jobs(self._jobs)
        except BaseException as err:          # told to the caller when it leaves the block
            self._error = err


def bookmarks(page: Any) -> list[tuple[str, str]]:
    """The bookmarks a page asks for: each link `<a href="#ID" data-bookmark="TITLE">`, in
    the page's order, as (TITLE, ID). Chromium writes a named destination for each id a link
    points to, and `outline.add_outline` adds the bookmarks to it (Chromium's own outline
    needs a tagged PDF, about twice the size)."""
    found = page.eval_on_selector_all(
        'a[data-bookmark][href^="#"]', "els => els.map(e => [e.dataset.bookmark, e.getAttribute('href').slice(1)])")
    return [(str(title), str(dest)) for title, dest in found]


def _print_jobs(jobs: Any) -> None:
    from playwright.sync_api import sync_playwright

    from .outline import add_outline

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium(), args=FLAGS)
        try:
            page = browser.new_page()
            page.set_default_timeout(PRINT_SECONDS * 1000)
            while (job := jobs.get()) is not None:
                html, pdf = job
                page.goto(html.resolve().as_uri(), wait_until="load")
                page.pdf(path=str(pdf), format="A4", print_background=True, prefer_css_page_size=True)
                add_outline(pdf, bookmarks(page))
        finally:
            browser.close()


def screenshots(pages: list[tuple[Path, Path]], width: int = 900, full_page: bool = True,
                print_media: bool = True) -> None:
    """Each HTML file as a PNG (as printed: `print` media), to look at."""
    in_own_thread(lambda: _screenshots(pages, width, full_page, print_media))


def _screenshots(pages: list[tuple[Path, Path]], width: int, full_page: bool, print_media: bool) -> None:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium(), args=FLAGS)
        try:
            page = browser.new_page(viewport={"width": width, "height": 1200})
            page.set_default_timeout(PRINT_SECONDS * 1000)
            if print_media:
                page.emulate_media(media="print")
            for html, png in pages:
                page.goto(html.resolve().as_uri(), wait_until="load")
                page.screenshot(path=str(png), full_page=full_page)
        finally:
            browser.close()
