"""Take the README's screenshots of the example workspace's report (headless Chromium).

    .venv/bin/python scripts/screenshots.py   # writes docs/report-*.png

Needs what `scripts/setup` installs (D3 from npm, playwright) and Debian's chromium.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

from playwright.sync_api import sync_playwright

from haros_arch.viz.browser import CHROMIUM_ARGS, chromium_path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"

# (file, configuration, finding rule to pick or None, vertex id to click or None)
SHOTS = [
    ("report-finding.png", "robot", "topic-type-mismatch", None),
    ("report-qos.png", "rover", "qos-incompatible", None),
    ("report-unresolved.png", "robot", None, "topic:/?/status"),
]


def main() -> int:
    with tempfile.TemporaryDirectory() as tmp:
        report = Path(tmp) / "report.html"
        subprocess.run([sys.executable, "-m", "haros_arch.cli", "report",
                        str(ROOT / "examples/project.yaml"), "-o", str(report)], check=True)
        with sync_playwright() as driver:
            browser = driver.chromium.launch(executable_path=chromium_path(),
                                             args=CHROMIUM_ARGS)
            for name, config, rule, vertex in SHOTS:
                page = browser.new_page(viewport={"width": 1500, "height": 820})
                page.goto(report.as_uri())
                page.wait_for_function("window.harosReport && window.harosReport.ready")
                page.select_option("#config", label=config)
                if rule:
                    page.click(f'#findings .item[data-rule="{rule}"]')
                if vertex:
                    page.click(f'#graph .vertex[data-id="{vertex}"]')
                page.wait_for_timeout(400)
                page.screenshot(path=str(DOCS / name))
                page.close()
                print(f"wrote docs/{name}")
            browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
