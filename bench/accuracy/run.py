#!/usr/bin/env python3
"""Accuracy benchmark: haros-arch's extracted graph against real ROS 1 systems run here.

    .venv/bin/python bench/accuracy/run.py all          # setup, fetch, build, capture, score
    .venv/bin/python bench/accuracy/run.py score        # re-score the committed captures

Steps (each can be run alone; see README.md beside this file):
  setup    apt-get install Debian's ROS 1 build and run dependencies (root; idempotent)
  fetch    unpack the pinned public repositories into WS/src (never into this repo)
  build    catkin_make the workspace with Debian's catkin
  capture  for each configuration: roscore + roslaunch on a fresh loopback port, wait until
           the graph settles, `haros-arch capture` to live/NAME.json, shut everything down
  score    write projects/NAME.yaml, `haros-arch extract` it, compare with live/NAME.json;
           again with the hints of hints.yaml (projects_hints/NAME.yaml); write
           results.md and results.json (both tables: without hints, with hints)
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import roslive
import scoring
import yaml

from haros_arch.live.compare import CompareError, compare

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
VENV_BIN = Path(sys.executable).parent
HAROS = [str(VENV_BIN / "haros-arch")] if (VENV_BIN / "haros-arch").exists() else [
    sys.executable, "-m", "haros_arch.cli"]

# Debian's names for the ROS 1 (Noetic-era) packages the workspace needs to build and run
DEBS = ["catkin", "ros-core-dev", "ros-base-dev", "rosout", "rosbash", "python3-roslaunch",
        "python3-rospy", "python3-rosnode", "python3-rostopic", "python3-rosservice",
        "python3-rosparam", "python3-std-msgs", "python3-std-srvs", "python3-geometry-msgs",
        "python3-sensor-msgs", "python3-actionlib", "python3-actionlib-msgs",
        "python3-dynamic-reconfigure", "libtf-dev", "python3-tf", "libtf2-ros-dev",
        "python3-tf2-ros", "libangles-dev", "python3-angles", "python3-nodelet",
        "qtbase5-dev", "libboost-thread-dev", "g++", "cmake",
        "python-is-python3"]  # scripts of the tutorials start with `#!/usr/bin/env python`

# (repository, pinned commit, folder of the repository that holds packages)
SOURCES = [
    ("ros/ros_tutorials", "db6328879831b4abadac939bd69b43133414c0db", ""),
    ("ros/common_tutorials", "b3a86ff8a60efd678f942deab47efcadd52a5336", ""),
    ("ros/geometry_tutorials", "c9bc222f286562dfbc8c02789cb1fb8ea00e31a2", ""),
    ("git-afsantos/haros_tutorials", "6576ae667894f5cca2c4c242c16bbc84b8ac865f", "src"),
]
# packages that do not build against Debian's ROS: they include pluginlib's old `.h`
# headers, which Debian's pluginlib-dev no longer ships
IGNORED_PACKAGES = ["pluginlib_tutorials", "nodelet_tutorial_math"]
CMAKE_ARGS = ["-DPYTHON_EXECUTABLE=/usr/bin/python3",
              # Debian's Boost no longer puts bind's _1, _2 in the global namespace
              "-DCMAKE_CXX_FLAGS=-DBOOST_BIND_GLOBAL_PLACEHOLDERS"]
SYSTEM_PATH = "/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin"


def log(message: str) -> None:
    print(f"[accuracy] {message}", flush=True)


def configurations(names: list[str] | None = None) -> list[dict[str, Any]]:
    with open(HERE / "configs.yaml") as handle:
        configs = yaml.safe_load(handle)
    if names:
        unknown = set(names) - {c["name"] for c in configs}
        if unknown:
            sys.exit(f"unknown configuration(s): {', '.join(sorted(unknown))}")
        configs = [c for c in configs if c["name"] in names]
    return configs


# ---- setup, fetch, build -------------------------------------------------------------

def setup() -> None:
    missing = [deb for deb in DEBS if subprocess.run(
        ["dpkg", "-s", deb], capture_output=True).returncode != 0]
    if not missing:
        log("setup: all Debian packages present")
        return
    if os.geteuid() != 0:
        sys.exit(f"setup: needs root to apt-get install {' '.join(missing)}")
    log(f"setup: apt-get install {' '.join(missing)}")
    env = {**os.environ, "DEBIAN_FRONTEND": "noninteractive"}
    subprocess.run(["apt-get", "update", "-qq"], check=True, timeout=900, env=env)
    subprocess.run(["apt-get", "install", "-y", "-qq", *missing], check=True, timeout=1800,
                   env=env)


def _git_dir(mirror: Path, repo: str) -> Path:
    owner, name = repo.split("/")
    for candidate in (mirror / f"{owner}+{name}" / "repo", mirror / f"{owner}+{name}",
                      mirror / name / ".git", mirror / f"{name}.git"):
        if (candidate / "HEAD").exists():
            return candidate
    sys.exit(f"fetch: no git directory for {repo} under {mirror} "
             f"(clone it there: git clone --bare <its public URL> {mirror}/{owner}+{name}/repo)")


def fetch(ws: Path, mirror: Path, force: bool) -> None:
    src = ws / "src"
    src.mkdir(parents=True, exist_ok=True)
    for repo, commit, folder in SOURCES:
        stamp = src / f".fetched-{repo.replace('/', '+')}"
        if stamp.exists() and stamp.read_text().strip() == commit and not force:
            log(f"fetch: {repo} already at {commit[:12]}")
            continue
        git_dir = _git_dir(mirror, repo)
        log(f"fetch: {repo} {commit[:12]} from {git_dir}")
        archive = subprocess.run(["git", "--git-dir", str(git_dir), "archive", commit,
                                  *([folder] if folder else [])],
                                 check=True, capture_output=True, timeout=300).stdout
        strip = [f"--strip-components={folder.count('/') + 1}"] if folder else []
        subprocess.run(["tar", "-x", *strip, "-C", str(src)], input=archive, check=True,
                       timeout=300)
        stamp.write_text(commit + "\n")
    for package in IGNORED_PACKAGES:
        if (src / package).is_dir():
            (src / package / "CATKIN_IGNORE").write_text("")
    ours = src / "accuracy_bench"
    if ours.exists():
        shutil.rmtree(ours)
    shutil.copytree(HERE / "launch", ours)
    log(f"fetch: our launch files in {ours}")


def build(ws: Path, jobs: int) -> None:
    env = {**os.environ, "PATH": SYSTEM_PATH}
    log_file = ws / "build.log"
    log(f"build: catkin_make -j{jobs} in {ws} (log: {log_file})")
    with open(log_file, "wb") as out:
        result = subprocess.run(["catkin_make", f"-j{jobs}", "-k", *CMAKE_ARGS], cwd=ws,
                                env=env, stdout=out, stderr=subprocess.STDOUT, timeout=3600)
    lib = ws / "devel" / "lib"
    built = sorted(f"{p.parent.name}/{p.name}" for p in lib.glob("*/*")
                   if p.is_file() and os.access(p, os.X_OK) and p.suffix != ".so")
    log(f"build: exit {result.returncode}; {len(built)} C++ executables: {' '.join(built)}")
    if result.returncode != 0:
        log(f"build: some targets failed, see {log_file}")


def ros_environment(ws: Path) -> dict[str, str]:
    """The environment after sourcing the workspace's devel/setup.bash."""
    setup_file = ws / "devel" / "setup.bash"
    if not setup_file.exists():
        sys.exit(f"no {setup_file}: run the build step first")
    env = {**os.environ, "PATH": SYSTEM_PATH}
    out = subprocess.run(["bash", "-c", f"source {setup_file} && env -0"], env=env,
                         check=True, capture_output=True, timeout=60).stdout
    pairs = (item.split("=", 1) for item in out.decode().split("\0") if "=" in item)
    return dict(pairs)


# ---- capture -------------------------------------------------------------------------

def capture_all(ws: Path, configs: list[dict[str, Any]], timeout: float) -> None:
    env = ros_environment(ws)
    live_dir = HERE / "live"
    live_dir.mkdir(exist_ok=True)
    runs_file = live_dir / "runs.json"
    runs = json.loads(runs_file.read_text()) if runs_file.exists() else {}
    log_dir = ws / "logs"
    for config in configs:
        name = config["name"]
        launch_file = ws / "src" / config["launch"]
        if not launch_file.exists():
            log(f"capture {name}: no {launch_file}, skipped")
            continue
        args = {str(k): str(v) for k, v in (config.get("args") or {}).items()}
        record = roslive.run_configuration(
            name, launch_file, config["launch"], args, env, live_dir / f"{name}.json",
            [*HAROS, "capture"], settle=float(config.get("settle", 3.0)), timeout=timeout,
            log_dir=log_dir)
        runs[name] = record.to_data()
        runs_file.write_text(json.dumps(runs, indent=1, sort_keys=True) + "\n")
        log(f"capture {name}: settled={record.settled} {record.seconds}s "
            f"roslaunch_exit={record.launch_exit} killed={record.killed} {record.error}")


# ---- score ---------------------------------------------------------------------------

PASSES = ("without_hints", "with_hints")
# per pass: the folder of project files (here and in WS) and of models (in WS)
PROJECTS = {"without_hints": "projects", "with_hints": "projects_hints"}
MODELS = {"without_hints": "haros_models", "with_hints": "haros_models_hints"}


def project_data(config: dict[str, Any]) -> dict[str, Any]:
    """The project file for one configuration; it lives in WS/haros_projects/."""
    spec: dict[str, Any] = {"launch": [config["launch"]]}
    if config.get("args"):
        spec["args"] = {str(k): str(v) for k, v in config["args"].items()}
    return {"project": config["name"], "workspace": "../src",
            "packages": [config["launch"].split("/")[0]],
            "configurations": {config["name"]: spec}}


def load_hints() -> dict[str, Any]:
    """hints.yaml: global ``nodes:`` hints and per-configuration ``hints:``."""
    with open(HERE / "hints.yaml") as handle:
        data = yaml.safe_load(handle) or {}
    # plain data (no shared objects), so that safe_dump writes no YAML aliases
    return json.loads(json.dumps(data))


def hinted_project(config: dict[str, Any], hints: dict[str, Any],
                   model: dict[str, Any] | None) -> dict[str, Any] | None:
    """The project with hints: the node hints of the node types this configuration runs
    (as extracted without hints) and its own configuration hints; None when none apply."""
    name = config["name"]
    launched = {n.get("node") for c in (model or {}).get("configurations", [])
                for n in c.get("nodes", [])}
    nodes = {t: h for t, h in (hints.get("nodes") or {}).items() if t in launched}
    own = (hints.get("configurations") or {}).get(name)
    if not nodes and not own:
        return None
    data = project_data(config)
    if own:
        data["configurations"][name]["hints"] = own
    if nodes:
        data["nodes"] = nodes
    return data


def _extract_and_compare(ws: Path, name: str, data: dict[str, Any], which: str,
                         live: dict[str, Any], timeout: float
                         ) -> tuple[dict[str, Any], dict[str, Any] | None]:
    """Write the project file (here and in WS), extract it, compare with the capture."""
    text = "%YAML 1.1\n---\n" + yaml.safe_dump(data, sort_keys=False)
    here, ws_projects = HERE / PROJECTS[which], ws / f"haros_{PROJECTS[which]}"
    models = ws / MODELS[which]
    for folder in (here, ws_projects, models):
        folder.mkdir(parents=True, exist_ok=True)
    (here / f"{name}.yaml").write_text(text)
    (ws_projects / f"{name}.yaml").write_text(text)
    model_file = models / f"{name}.json"
    result: dict[str, Any] = {"configuration": name, "hints": which == "with_hints"}
    model = None
    started = time.monotonic()
    try:
        model_file.unlink(missing_ok=True)
        done = subprocess.run([*HAROS, "extract", str(ws_projects / f"{name}.yaml"),
                               "-o", str(model_file), "-q"], capture_output=True,
                              text=True, timeout=timeout)
        if not model_file.exists() or done.returncode not in (0, 1):
            raise RuntimeError(f"extract exit {done.returncode}: "
                               f"{(done.stderr or done.stdout).strip()[-300:]}")
        model = json.loads(model_file.read_text())
        result.update(compare(model, live, name).to_data())
    except (RuntimeError, CompareError, subprocess.SubprocessError, ValueError) as err:
        result["error"] = str(err)
    result["extract_seconds"] = round(time.monotonic() - started, 1)
    return result, model


def _previous_results(results_file: Path) -> dict[str, dict[str, dict[str, Any]]]:
    if not results_file.exists():
        return {which: {} for which in PASSES}
    data = json.loads(results_file.read_text())
    if isinstance(data, list):  # written before the with-hints pass existed
        data = {"without_hints": data}
    return {which: {r["configuration"]: r for r in data.get(which, [])} for which in PASSES}


def score_all(ws: Path, configs: list[dict[str, Any]], timeout: float) -> None:
    """Score each configuration twice: the extractor alone, and with hints.yaml."""
    runs_file = HERE / "live" / "runs.json"
    runs = json.loads(runs_file.read_text()) if runs_file.exists() else {}
    results_file = HERE / "results.json"
    previous = _previous_results(results_file)
    hints = load_hints()
    for config in configs:
        name = config["name"]
        live_file = HERE / "live" / f"{name}.json"
        if not live_file.exists():
            log(f"score {name}: no capture, skipped")
            continue
        live = json.loads(live_file.read_text())
        plain, model = _extract_and_compare(ws, name, project_data(config),
                                            "without_hints", live, timeout)
        plain["run"] = runs.get(name)
        previous["without_hints"][name] = plain
        log(f"score {name}: {_summary(plain)}")
        hinted_data = hinted_project(config, hints, model)
        stale = HERE / PROJECTS["with_hints"] / f"{name}.yaml"
        if hinted_data is None:
            stale.unlink(missing_ok=True)
            hinted = {**plain, "hints": False}
        else:
            hinted, _model = _extract_and_compare(ws, name, hinted_data, "with_hints", live,
                                                  timeout)
            hinted["run"] = runs.get(name)
            log(f"score {name} with hints: {_summary(hinted)}")
        previous["with_hints"][name] = hinted
    order = [c["name"] for c in configurations()]
    results = {which: [previous[which][n] for n in order if n in previous[which]]
               for which in PASSES}
    results_file.write_text(json.dumps(results, indent=1) + "\n")
    unscored = [f"`{c['name']}` ({(runs.get(c['name']) or {}).get('error') or 'no capture'})"
                for c in configurations() if c["name"] not in previous["without_hints"]]
    header = _header() + ([f"Not scored: {'; '.join(unscored)}."] if unscored else [])
    (HERE / "results.md").write_text(
        scoring.markdown(results["without_hints"], results["with_hints"], header))
    log(f"wrote {HERE / 'results.md'}")


def _summary(result: dict[str, Any]) -> str:
    if "error" in result and not result.get("scores"):
        return f"error: {result['error']}"
    return " ".join(f"{scoring.SHORT[s['kind']]}={s['precision']:.2f}/{s['recall']:.2f}"
                    for s in result["scores"])


def _header() -> list[str]:
    head = subprocess.run(["git", "-C", str(REPO), "rev-parse", "--short", "HEAD"],
                          capture_output=True, text=True).stdout.strip()
    changed = subprocess.run(["git", "-C", str(REPO), "status", "--porcelain", "haros_arch"],
                             capture_output=True, text=True).stdout.splitlines()
    folders = sorted({os.path.dirname(line[3:]) for line in changed})
    dirty = f" with uncommitted changes in {', '.join(folders)}" if folders else ""
    sources = ", ".join(f"{repo}@{commit[:12]}" for repo, commit, _f in SOURCES)
    return [f"Generated by `bench/accuracy/run.py score` on {time.strftime('%Y-%m-%d')}, "
            f"haros_arch at commit {head}{dirty}.",
            f"Sources: {sources}, plus our launch files in `bench/accuracy/launch/`.",
            "Live data: `bench/accuracy/live/NAME.json` (`haros-arch capture`), run notes in "
            "`live/runs.json`; the element kinds are those of `haros-arch compare`."]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("step", choices=["setup", "fetch", "build", "capture", "score", "all"])
    parser.add_argument("names", nargs="*", help="configurations (default: all)")
    parser.add_argument("--ws", type=Path, default=Path("/tmp/accuracy_ws"),
                        help="scratch catkin workspace, outside this repository")
    parser.add_argument("--mirror", type=Path, default=Path("/work/.mirror"),
                        help="folder with git directories of the SOURCES repositories")
    parser.add_argument("--force", action="store_true", help="fetch again")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=60.0,
                        help="seconds to wait for a graph to settle")
    parser.add_argument("--extract-timeout", type=float, default=900.0)
    options = parser.parse_args()
    ws = options.ws.resolve()
    if ws == REPO or REPO in ws.parents:
        sys.exit("--ws must be outside this repository: fetched code is never committed")
    step = options.step
    if step in ("setup", "all"):
        setup()
    if step in ("fetch", "all"):
        fetch(ws, options.mirror, options.force)
    if step in ("build", "all"):
        build(ws, options.jobs)
    configs = configurations(options.names)
    if step in ("capture", "all"):
        capture_all(ws, configs, options.timeout)
    if step in ("score", "all"):
        score_all(ws, configs, options.extract_timeout)


if __name__ == "__main__":
    main()
