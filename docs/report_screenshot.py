"""Make docs/figures/report.png: a report as Chromium shows it, for the README.

Run from the repository root (needs the ``report`` extra and Debian's ``chromium``)::

    python docs/report_screenshot.py

It writes the report of the swinging sieve (problem 3.7) with the command line,
``python -m kinematics report fixtures/ch3_3_7_sieve.edges -o report.html`` (in a
temporary directory), opens it in headless Chromium driven by playwright, moves
the animation's slider to 60°, and puts two views side by side: the top of the
page (the mechanism with its Assur groups) and the whole-cycle section (the
animation and the plots over the cycle).
"""

from __future__ import annotations

import io
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from PIL import Image
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parent.parent
FIXTURE = "fixtures/ch3_3_7_sieve.edges"
OUT = ROOT / "docs" / "figures" / "report.png"
WIDTH, HEIGHT = 1000, 1250  # each view, CSS pixels


def main() -> int:
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        sys.stderr.write("no chromium on the PATH: apt-get install chromium\n")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        page_file = Path(tmp) / "report.html"
        command = [sys.executable, "-m", "kinematics", "report", FIXTURE, "-o", str(page_file)]
        subprocess.run(command, cwd=ROOT, check=True)
        with sync_playwright() as driver:
            browser = driver.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": WIDTH, "height": HEIGHT})
            page.goto(page_file.as_uri())
            page.evaluate(
                """() => { const s = document.getElementById("cycle-slider");
                           s.value = "20"; s.dispatchEvent(new Event("input")); }"""
            )
            top = page.screenshot()
            page.evaluate("document.getElementById('cycle').scrollIntoView()")
            cycle = page.screenshot()
            browser.close()
    views = [Image.open(io.BytesIO(png)).convert("RGB") for png in (top, cycle)]
    sheet = Image.new("RGB", (2 * WIDTH + 24, HEIGHT), "#d5dbe2")
    for k, view in enumerate(views):
        sheet.paste(view, (k * (WIDTH + 24), 0))
    sheet = sheet.resize((sheet.width * 3 // 4, sheet.height * 3 // 4), Image.LANCZOS)
    sheet.save(OUT, optimize=True)
    print(f"wrote {OUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
