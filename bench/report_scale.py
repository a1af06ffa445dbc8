"""How fast the HTML report opens for a large configuration, in headless Chromium.

Generates a model with 300 node instances and 1,000 topics (plus services and
parameters), writes the report, opens it in Debian's chromium and prints the time from
navigation to the first drawn graph (namespaces collapsed, as a configuration this big
opens), and how long it takes to open a namespace, click a node in it and a finding,
search + Enter a name in a collapsed namespace, and open every namespace (the whole
graph laid out with its dummy points).

    PYTHONPATH=. .venv/bin/python bench/report_scale.py [--nodes 300] [--topics 1000]
        [--shape robots|nested|flat]

(PYTHONPATH=. so that this checkout's haros_arch is measured, not an installed one.)
"""

from __future__ import annotations

import argparse
import os
import random
import sys
import tempfile
import time
from typing import Any

from haros_arch.viz import write_report
from haros_arch.viz.browser import CHROMIUM_ARGS, chromium_path, why_no_browser

# Subsystems of a robot (shape "nested") and first words of names (shape "flat").
PARTS = ("sensors", "sensors", "sensors", "base", "base", "base", "arm", "arm", "arm", "arm")
WORDS = ("camera", "lidar", "imu", "gps", "odom", "planner", "controller", "arm", "gripper",
         "battery", "map", "localization", "perception", "safety", "teleop")


def scale_model(nodes: int, topics: int, seed: int = 7, shape: str = "robots") -> dict[str, Any]:
    # A fleet: robots of ten nodes each, data flowing down a pipeline inside a robot
    # (each topic read by one to three later nodes), some topics read by fleet nodes.
    # shape "robots": /robot3/node4; "nested": /robot3/base/node4, a topic in the
    # namespace of its publisher; "flat": everything in /, as /camera_3_4 and /camera/topic7.
    rng = random.Random(seed)
    per = 10
    robots = max(1, nodes // per)
    where = {"package": "fleet", "file": "fleet/src/node.cpp", "line": 12, "column": 3}
    node_names = [f"/robot{i // per}/node{i % per}" for i in range(nodes)]
    topic_names = [f"/robot{t % robots}/topic{t // robots}" for t in range(topics)]
    if shape == "nested":
        node_names = [f"/robot{i // per}/{PARTS[i % per]}/node{i % per}" for i in range(nodes)]
    if shape == "flat":
        node_names = [f"/{WORDS[i // per % len(WORDS)]}_{i // per}_{i % per}" for i in range(nodes)]
    links: list[dict[str, Any]] = []
    pubs: dict[str, list[str]] = {}
    subs: dict[str, list[str]] = {}
    for t in range(topics):
        robot = t % robots
        stage = rng.randrange(per - 1)
        publisher = node_names[robot * per + stage]
        if shape != "robots":  # the topic is named where its publisher is
            base = (publisher.rsplit("/", 1)[0] if shape == "nested"
                    else "/" + publisher[1:].split("_")[0])
            topic_names[t] = f"{base}/topic{t}"
        topic = topic_names[t]
        pubs[topic], subs[topic] = [publisher], []
        for later in rng.sample(range(stage + 1, per), min(per - stage - 1, rng.randint(1, 3))):
            subs[topic].append(node_names[robot * per + later])
        if rng.random() < 0.05:
            subs[topic].append(node_names[rng.randrange(nodes)])
    for topic in topic_names:
        for kind, users in (("publish", pubs[topic]), ("subscribe", subs[topic])):
            links += [{"kind": kind, "node": n, "name": topic, "given": topic.rsplit("/", 1)[1],
                       "type": "std_msgs/String", "queue_size": 10, "qos": None,
                       "conditions": [], "location": where} for n in dict.fromkeys(users)]
    services = []
    for i in range(nodes // 3):
        name = f"{node_names[i]}/reset"
        caller = rng.choice(node_names)
        services.append({"name": name, "id": f"service:{name}", "types": ["std_srvs/Empty"],
                         "servers": [node_names[i]], "clients": [caller], "conditions": []})
        links += [{"kind": k, "node": n, "name": name, "given": "reset", "type": "std_srvs/Empty",
                   "queue_size": None, "qos": None, "conditions": [], "location": where}
                  for k, n in (("server", node_names[i]), ("client", caller))]
    params = []
    for i in range(nodes):
        name = f"{node_names[i]}/rate"
        params.append({"name": name, "id": f"parameter:{name}", "type": "double", "value": 10.0,
                       "readers": [node_names[i]], "writers": ["<launch>"], "conditions": []})
        links.append({"kind": "read", "node": node_names[i], "name": name, "given": "~rate",
                      "type": "double", "queue_size": None, "qos": None, "conditions": [],
                      "location": where})
    config = {
        "name": "fleet", "launch": ["fleet/launch/fleet.launch"], "args": {},
        "nodes": [{"name": n, "id": f"node:{n}", "node": "fleet/node",
                   "namespace": n.rsplit("/", 1)[0] + "/", "remaps": [], "args": "",
                   "conditions": [], "location": where} for n in node_names],
        "topics": [{"name": t, "id": f"topic:{t}", "types": ["std_msgs/String"],
                    "publishers": pubs[t], "subscribers": list(dict.fromkeys(subs[t])),
                    "conditions": []} for t in topic_names],
        "services": services, "actions": [], "parameters": params, "links": links,
        "diagnostics": []}
    return {"schema": "haros-arch/1", "project": "fleet", "packages": [], "diagnostics": [],
            "configurations": [config]}


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--nodes", type=int, default=300)
    parser.add_argument("--topics", type=int, default=1000)
    parser.add_argument("--shape", choices=("robots", "nested", "flat"), default="robots",
                        help="robots: /robot3/node4; nested: /robot3/base/node4; "
                             "flat: all in /, as /camera_3_4")
    args = parser.parse_args()
    reason = why_no_browser()
    if reason:
        print(f"report_scale: cannot run: {reason}", file=sys.stderr)
        return 2
    from playwright.sync_api import sync_playwright

    model = scale_model(args.nodes, args.topics, shape=args.shape)
    config = model["configurations"][0]
    findings = [{"rule": "bench", "severity": "warning", "title": "sample", "message": "m",
                 "configuration": "fleet", "entities": [config["topics"][0]["id"]],
                 "location": {"file": None, "line": 0}}]
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "report.html")
        started = time.perf_counter()
        write_report(model, findings, folder, path)
        written = time.perf_counter() - started
        size = os.path.getsize(path)
        with sync_playwright() as driver:
            browser = driver.chromium.launch(executable_path=chromium_path(), args=CHROMIUM_ARGS)
            page = browser.new_page(viewport={"width": 1400, "height": 800})
            page.goto(f"file://{path}")
            page.wait_for_function("window.harosReport && window.harosReport.ready",
                                   timeout=60000)
            ready = page.evaluate("window.harosReport.readyAt")
            script = page.evaluate("window.harosReport.scriptMs")
            drawn = page.eval_on_selector_all("#graph .vertex", "els => els.length")
            target = config["nodes"][150]

            def box_of_target() -> str | None:
                """The drawn namespace box that holds the target node, if any."""
                boxes = page.eval_on_selector_all(
                    "#graph .vertex.k-namespace",
                    "els => els.map(e => e.getAttribute('data-id').slice('namespace:'.length))")
                inside = [b for b in boxes if target["name"].startswith(b.rstrip("*"))]
                return max(inside, key=len) if inside else None

            def timed(act: Any) -> float:
                page.evaluate("window.__t = performance.now()")
                act()
                took = page.evaluate("new Promise(r => requestAnimationFrame("
                                     "() => r(performance.now() - window.__t)))")
                page.wait_for_timeout(400)  # let the zoom transition end
                return float(took)

            times: dict[str, float] = {}
            space = box_of_target()
            while space:  # open the boxes around the target, outermost first
                what = "open a namespace" if not times else f"open {space} inside it"
                box = f'#graph .vertex[data-id="namespace:{space}"]'
                times[what] = timed(lambda box=box: page.click(box))
                space = box_of_target()
            times["click a node"] = timed(lambda: page.click(
                f'#graph .vertex[data-id="{target["id"]}"]', force=True))
            times["click a finding"] = timed(lambda: page.click("#findings .item"))
            other = config["nodes"][40]["name"]
            page.fill("#search", other)
            times["search + Enter (opens its namespace)"] = timed(
                lambda: page.press("#search", "Enter"))
            times["open all namespaces"] = timed(lambda: page.click("#open-all"))
            everything = page.eval_on_selector_all("#graph .vertex", "els => els.length")
            times["click a node, all open"] = timed(lambda: page.click(
                f'#graph .vertex[data-id="{target["id"]}"]', force=True))
            browser.close()
    print(f"model: {len(config['nodes'])} node instances, {len(config['topics'])} topics, "
          f"{len(config['services'])} services, {len(config['parameters'])} parameters, "
          f"{len(config['links'])} links; {drawn} vertices drawn first "
          f"(namespaces collapsed), {everything} with all open")
    print(f"report: {size / 1e6:.2f} MB written in {written:.2f} s")
    print(f"open to first drawn graph: {ready / 1000:.2f} s (our script {script / 1000:.2f} s); "
          f"budget 3 s -> {ready / 3000:.2f} of budget")
    for what, took in times.items():
        print(f"{what}: {took:.0f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
