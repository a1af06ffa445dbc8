"""Take the README's screenshots of the example workspace's report (headless Chromium).

    PYTHONPATH=. .venv/bin/python scripts/screenshots.py   # writes docs/report-*.png

The first two are of the example workspace (examples/project.yaml); the third, of a name
not known statically, of fixtures/report_unresolved (the example's robot started with the
monitor's robot named only at start: /?/status).

The last two are from bench/report_scale.py's fleets: the first view of 300 nodes, and
six robots of the nested shape (/robot1/sensors/, base/, arm/) with /robot1/base/ opened.
With ``--husky DIR`` (a checkout of husky/husky, ROS 1 noetic branch, under DIR/src) it
also takes docs/report-launch.png, the Launch view of husky_gazebo/husky_playpen. With
``--nav2 DIR`` (nav2_bringup and nav2_common of ros-navigation/navigation2 under DIR/src)
it takes docs/report-launch-ros2.png, the Launch view of nav2_bringup's bringup_launch.py
scrolled to navigation_launch.py's nodes (a remap drawn from the name in code to the name
it resolves to).

Needs what `scripts/setup` installs (D3 from npm, playwright) and Debian's chromium.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

from playwright.sync_api import sync_playwright

from haros_arch.viz import write_report
from haros_arch.viz.browser import CHROMIUM_ARGS, chromium_path

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"

# (file, project, configuration, finding rule to pick or None, vertex id to click or
# None); the example decides every name, so the unresolved one is from a fixture that
# starts the example's robot with the monitor's robot named only when it starts
EXAMPLE = ROOT / "examples/project.yaml"
UNRESOLVED = ROOT / "fixtures/report_unresolved/project.yaml"
SHOTS = [
    ("report-finding.png", EXAMPLE, "robot", "topic-type-mismatch", None),
    ("report-qos.png", EXAMPLE, "rover", "qos-incompatible", None),
    ("report-unresolved.png", UNRESOLVED, "robot_named_at_start", None, "topic:/?/status"),
]


def scale_model(shape: str = "robots", nodes: int = 300, topics: int = 1000) -> dict:
    spec = importlib.util.spec_from_file_location("report_scale", ROOT / "bench/report_scale.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.scale_model(nodes, topics, shape=shape)  # type: ignore[no-any-return]


def launch_shot(browser: Any, husky: str, tmp: str) -> None:
    report = Path(tmp) / "husky.html"
    subprocess.run([sys.executable, "-m", "haros_arch.cli", "report", husky, "-o", str(report),
                    "--jobs", "1"], check=True, stdout=subprocess.DEVNULL)
    page = browser.new_page(viewport={"width": 1500, "height": 900})
    page.goto(report.as_uri())
    page.wait_for_function("window.harosReport && window.harosReport.ready")
    page.select_option("#config", label="husky_gazebo/husky_playpen")
    page.click("#tab-launch")
    page.click('#launch .lt-file[data-name="husky_control/launch/control.launch"] > .lt-head')
    page.wait_for_timeout(300)
    page.screenshot(path=str(DOCS / "report-launch.png"))
    page.close()
    print("wrote docs/report-launch.png")


def launch_shot_ros2(browser: Any, nav2: str, tmp: str) -> None:
    report = Path(tmp) / "nav2.html"
    launch = Path(nav2) / "src/nav2_bringup/launch/bringup_launch.py"
    subprocess.run([sys.executable, "-m", "haros_arch.cli", "report", str(launch), "-o",
                    str(report), "--jobs", "1"], check=True, stdout=subprocess.DEVNULL)
    page = browser.new_page(viewport={"width": 1400, "height": 820})
    page.goto(report.as_uri())
    page.wait_for_function("window.harosReport && window.harosReport.ready")
    page.click("#tab-launch")
    navigation = "nav2_bringup/launch/navigation_launch.py"
    page.click(f'#launch .lt-file[data-name="{navigation}"] > .lt-head')
    page.eval_on_selector("#launch .lt-remap-code", "e => { const row = e.closest('.lt'); "
                          "(row.previousElementSibling || row).scrollIntoView(); }")
    page.wait_for_timeout(300)
    page.screenshot(path=str(DOCS / "report-launch-ros2.png"))
    page.close()
    print("wrote docs/report-launch-ros2.png")


def option(name: str) -> str | None:
    return sys.argv[sys.argv.index(name) + 1] if name in sys.argv[:-1] else None


def main() -> int:
    husky, nav2 = option("--husky"), option("--nav2")
    with tempfile.TemporaryDirectory() as tmp:
        reports: dict[Path, Path] = {}
        for project in dict.fromkeys(shot[1] for shot in SHOTS):
            reports[project] = Path(tmp) / f"report-{len(reports)}.html"
            subprocess.run([sys.executable, "-m", "haros_arch.cli", "report", str(project),
                            "-o", str(reports[project])], check=True)
        with sync_playwright() as driver:
            browser = driver.chromium.launch(executable_path=chromium_path(),
                                             args=CHROMIUM_ARGS)
            for name, project, config, rule, vertex in SHOTS:
                page = browser.new_page(viewport={"width": 1500, "height": 820})
                page.goto(reports[project].as_uri())
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
            fleet = Path(tmp) / "fleet.html"
            write_report(scale_model(), [], tmp, str(fleet))
            page = browser.new_page(viewport={"width": 1500, "height": 760})
            page.goto(fleet.as_uri())
            page.wait_for_function("window.harosReport && window.harosReport.ready")
            page.wait_for_timeout(400)
            page.locator("#stage").screenshot(path=str(DOCS / "report-scale.png"))
            print("wrote docs/report-scale.png")
            nested = Path(tmp) / "nested.html"
            write_report(scale_model("nested", 60, 150), [], tmp, str(nested))
            page = browser.new_page(viewport={"width": 1500, "height": 760})
            page.goto(nested.as_uri())
            page.wait_for_function("window.harosReport && window.harosReport.ready")
            page.click('#graph .vertex[data-id="namespace:/robot1/base/"]')
            page.click("#fit")
            page.wait_for_timeout(400)
            page.locator("#stage").screenshot(path=str(DOCS / "report-nested.png"))
            print("wrote docs/report-nested.png")
            if husky:
                launch_shot(browser, husky, tmp)
            if nav2:
                launch_shot_ros2(browser, nav2, tmp)
            browser.close()
    return 0


if __name__ == "__main__":
    sys.exit(main())
