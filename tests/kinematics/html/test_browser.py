"""The report in a real browser: headless Chromium, driven by playwright, one browser a session.

Chromium is Debian's ``chromium`` package (or ``$ASSUR_CHROMIUM``); playwright
drives that executable (``executable_path``), it never downloads its own. The
tests skip, saying why, when either is missing, unless ``ASSUR_REQUIRE_BROWSER``
is set (``.ci/run`` sets it after installing both): then they fail instead.

Each fixture's page is opened from disk and checked: no console error, no
request outside the file, not blank, every MathML formula laid out with a
size, every number equal to the command line's JSON, and the slider moving
the drawn pose.
"""

from __future__ import annotations

import io
import os
import re
import shutil
from pathlib import Path

import pytest
from PIL import Image

from kinematics.html.markup import format_number

from .conftest import STEMS, cli_json, json_at

try:
    from playwright.sync_api import sync_playwright
except ImportError:  # the tests say so and skip (or fail under ASSUR_REQUIRE_BROWSER)
    sync_playwright = None

#: a browser start and a page per fixture: left out of the default run, run by CI (-m slow)
pytestmark = pytest.mark.slow

#: set (to anything but 0) where the browser tests must run: a missing browser fails them
REQUIRED = os.environ.get("ASSUR_REQUIRE_BROWSER", "0") not in ("", "0")
_CANDIDATES = ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable")


def chromium_executable() -> str | None:
    """``$ASSUR_CHROMIUM``, else the first Chromium on the PATH (Debian's is /usr/bin/chromium)."""
    for name in (os.environ.get("ASSUR_CHROMIUM"), *_CANDIDATES):
        found = shutil.which(name) if name else None
        if found:
            return found
    return None


def _unavailable(reason: str) -> None:
    if REQUIRED:
        pytest.fail(f"{reason}; ASSUR_REQUIRE_BROWSER is set, so the browser tests must run")
    pytest.skip(reason)


class Tab:
    """A browser page that records console errors, uncaught exceptions and requests."""

    def __init__(self, page) -> None:
        self.page = page
        self.errors: list[str] = []
        self.requests: list[str] = []
        page.on("console", lambda m: self.errors.append(m.text) if m.type == "error" else None)
        page.on("pageerror", lambda exc: self.errors.append(f"uncaught: {exc}"))
        page.on("request", lambda request: self.requests.append(request.url))

    def open(self, path: Path) -> None:
        """Load the page from disk afresh, with empty records."""
        self.errors.clear()
        self.requests.clear()
        self.page.goto(path.resolve().as_uri(), wait_until="load")

    def frame(self) -> str:
        return self.page.get_attribute("#cycle-svg", "data-frame")

    def scrub(self, frame: int) -> None:
        """Move the slider to ``frame`` as a user does: its value, then an input event."""
        self.page.evaluate(
            """frame => {
                const slider = document.getElementById("cycle-slider");
                slider.value = String(frame);
                slider.dispatchEvent(new Event("input", {bubbles: true}));
            }""",
            frame,
        )


@pytest.fixture(scope="session")
def browser():
    """One headless Chromium for the session."""
    executable = chromium_executable()
    if sync_playwright is None:
        _unavailable("playwright is not installed (pip install -e '.[test]')")
    if executable is None:
        _unavailable("no Chromium found (apt-get install chromium, or set ASSUR_CHROMIUM)")
    with sync_playwright() as driver:
        chromium = driver.chromium.launch(
            executable_path=executable, args=["--no-sandbox", "--disable-gpu"]
        )
        yield chromium
        chromium.close()


@pytest.fixture(scope="session")
def tab(browser):
    """One page of the session's browser, reused by every test that loads a report."""
    page = browser.new_page(viewport={"width": 1100, "height": 900})
    yield Tab(page)
    page.close()


def _distinct_colours(png: bytes) -> int:
    image = Image.open(io.BytesIO(png)).convert("RGB")
    colours = image.getcolors(maxcolors=1 << 16)
    return len(colours) if colours is not None else 1 << 16


_MATH_SIZES = """() => Array.from(document.querySelectorAll("math")).map(m => {
    const box = m.getBoundingClientRect();
    return [box.width, box.height, m instanceof MathMLElement];
})"""

_TIED = """() => Array.from(document.querySelectorAll("[data-source]")).map(e => ({
    source: e.dataset.source, path: e.dataset.path, value: e.dataset.value ?? null,
    text: e.innerText, cell: e.tagName === "TD"
}))"""

#: what the script moves: the links' outlines, the sliders, the pins, the guides
_POSE = """() => Array.from(document.getElementById("cycle-svg").querySelectorAll(
        "[data-link], [data-slider], [data-pin], [data-guide]"
    )).map(e => ["points", "transform", "cx", "cy", "x1", "y1", "x2", "y2"]
        .map(name => e.getAttribute(name)).join(" "))"""


def _check_numbers(tab: Tab, stem: str) -> None:
    """Every number the page ties to a JSON path shows that value (as the page rounds it)."""
    tied = tab.page.evaluate(_TIED)
    assert tied, "no number tied to the command line's JSON"
    for item in tied:
        expected = json_at(cli_json(item["source"], stem), item["path"])
        if isinstance(expected, float):
            assert float(item["value"]) == expected, item["path"]
            if item["cell"]:
                assert item["text"].strip() == format_number(expected), item["path"]
        elif item["value"] is not None:
            assert item["value"] == str(expected), item["path"]
            assert str(expected) in item["text"] or item["cell"], item["path"]


def _check_slider(tab: Tab, picture: bool = False) -> None:
    """Scrubbing to another pose moves the drawn pose and the readout (and the picture)."""
    count = int(tab.page.get_attribute("#cycle-slider", "max")) + 1
    sketch = int(tab.frame())
    assert count >= 2, "an animation of one pose"
    other = (sketch + max(1, count // 3)) % count
    before = tab.page.evaluate(_POSE)
    shot = tab.page.locator("#cycle-svg").screenshot() if picture else b""
    readout = tab.page.inner_text("#cycle-readout")
    tab.scrub(other)
    assert tab.frame() == str(other)
    assert tab.page.evaluate(_POSE) != before, "the drawn pose did not move"
    if picture:
        assert tab.page.locator("#cycle-svg").screenshot() != shot, "the picture did not change"
    assert tab.page.inner_text("#cycle-readout") != readout
    tab.scrub(sketch)
    assert tab.page.evaluate(_POSE) == before, "back at the sketch, the drawing is not"


@pytest.mark.parametrize("stem", STEMS)
def test_the_report_renders_in_chromium(tab, all_reports, stem):
    """The page loads without error or request, is not blank, lays out its formulas and numbers."""
    tab.open(all_reports.path(stem))
    assert tab.errors == []
    outside = [url for url in tab.requests if not url.startswith(("file:", "data:"))]
    assert outside == [], "requests outside the page"
    assert _distinct_colours(tab.page.screenshot(type="jpeg")) > 16, "the page looks blank"
    sizes = tab.page.evaluate(_MATH_SIZES)
    assert sizes, "no MathML formula"
    assert all(mathml for _, _, mathml in sizes), "a <math> not parsed as MathML"
    assert all(w > 0 and h > 0 for w, h, _ in sizes), "a formula without a rendered size"
    _check_numbers(tab, stem)
    if tab.page.query_selector("#cycle-slider") is not None:
        _check_slider(tab)
    assert tab.errors == []


@pytest.mark.parametrize("stem", ["jansen", "ch3_3_1_slider_power", "gear_pair", "ch2_2_3_tangent"])
def test_the_slider_changes_the_picture(tab, all_reports, stem):
    """Screenshots of the animation at two poses differ (turning, sliding, gears, a stretch)."""
    tab.open(all_reports.path(stem))
    _check_slider(tab, picture=True)


def test_the_play_button_runs_and_stops_the_animation(tab, all_reports):
    tab.open(all_reports.path("jansen"))
    button = tab.page.locator("#cycle-play")
    assert button.inner_text() == "Play"
    button.click()
    assert button.inner_text() == "Pause"
    tab.page.wait_for_function("document.getElementById('cycle-svg').dataset.frame !== '0'")
    button.click()
    assert button.inner_text() == "Play"
    stopped = tab.frame()
    tab.page.wait_for_timeout(300)
    assert tab.frame() == stopped
    assert tab.errors == []


def test_a_stretch_plays_to_and_fro(tab, all_reports):
    """Short of a whole turn, play turns back at each end instead of jumping across."""
    tab.open(all_reports.path("ch2_2_3_tangent"))
    count = int(tab.page.get_attribute("#cycle-slider", "max")) + 1
    tab.scrub(count - 2)
    tab.page.click("#cycle-play")
    tab.page.wait_for_function(
        f"Number(document.getElementById('cycle-svg').dataset.frame) < {count - 2}"
    )
    tab.page.click("#cycle-play")
    assert int(tab.frame()) > 0
    assert tab.errors == []


def test_fractions_are_laid_out_as_fractions(tab, all_reports):
    """The Willis relations' fractions stand taller than one line: MathML is rendered natively."""
    tab.open(all_reports.path("exam_2_planetary"))
    heights = tab.page.evaluate(
        """() => Array.from(document.querySelectorAll("#gears mfrac")).map(f => [
            f.getBoundingClientRect().height, f.firstElementChild.getBoundingClientRect().height
        ])"""
    )
    assert heights
    assert all(whole > 1.6 * numerator > 0 for whole, numerator in heights)


def test_the_vietnamese_report_renders(tab, reports):
    tab.open(reports.path("ch3_3_4_fourbar", "vi"))
    assert tab.errors == []
    assert tab.page.get_attribute("html", "lang") == "vi"
    assert tab.page.inner_text("#cycle-play") == "Chạy"
    assert "Họa đồ vận tốc" in tab.page.inner_text("#kinematics")
    sizes = tab.page.evaluate(_MATH_SIZES)
    assert sizes and all(w > 0 and h > 0 for w, h, _ in sizes)


def test_printing_on_a4_hides_the_controls(browser, all_reports):
    """The print stylesheet: no contents box or controls, one main section per page, A4 pages."""
    page = browser.new_page()
    try:
        page.goto(all_reports.path("ch3_3_4_fourbar").resolve().as_uri())
        page.emulate_media(media="print")
        assert not page.is_visible("nav.contents")
        assert not page.is_visible("#cycle-play")
        assert page.is_visible("#cycle-svg")
        breaks = page.evaluate(
            """() => Array.from(document.querySelectorAll("section.part + section.part"))
                .map(s => getComputedStyle(s).breakBefore)"""
        )
        assert breaks and set(breaks) == {"page"}
        pdf = page.pdf(format="A4")
        assert pdf.startswith(b"%PDF")
        assert len(re.findall(rb"/Type\s*/Page(?!s)", pdf)) > 1, "one A4 page only"
    finally:
        page.close()
