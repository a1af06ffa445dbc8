"""A census of the ROS API call sites written in the C++ node sources of real workspaces
against the calls the extractor finds at those lines.

    .venv/bin/python bench/cpp_census.py WORKSPACE[:PKG,PKG...] ... [--jobs N]
        [--misses N] [--no-synthesis]

For every workspace (optionally only the packages named after a colon): the C++ nodes
of its CMake packages (sources under a test folder left out), every line of their
sources where a grep finds a ROS API call (publishers, subscriptions, services and
clients, action servers and clients, parameter declarations, reads and writes; roscpp,
rclcpp, actionlib, rclcpp_action, image_transport, message_filters forms), and whether
the extraction (no cache, each translation unit parsed once) has a call of that kind
within a line or two. Prints recall by call site per workspace and per kind, the misses
grouped by cause (the clang error left in the function that holds the site, else the
API form, in a unit with errors elsewhere or in a clean one), the nodes complete and
partial with what makes them partial, the clang errors (at most 50 per file) per unit
before and after the names clang did not know were declared (``CPP_NAMES_DECLARED``), and
the cold extraction time per unit. ``--misses N`` lists N missed sites per workspace;
``--no-synthesis`` turns the declaration of unknown names off; ``--timing`` first
extracts the same units without it and prints the ratio of the two cold times. Times are
this process's CPU time (with ``--jobs 1`` every parse is in it), so the load of other
processes on the machine does not change them.
"""

from __future__ import annotations

import argparse
import collections
import os
import re
import time

import checkout  # bench/checkout.py: says which haros_arch is measured

HERE = os.path.dirname(os.path.abspath(__file__))

from haros_arch import cmake  # noqa: E402
from haros_arch.extract import completeness  # noqa: E402
from haros_arch.extract.cpp import extract_cpp_nodes  # noqa: E402
from haros_arch.manifest import ros_version  # noqa: E402
from haros_arch.workspace import scan  # noqa: E402

# (category, form, pattern); a category matches calls of these kinds
KINDS = {"publish": {"publish"}, "subscribe": {"subscribe"}, "server": {"server"},
         "client": {"client"}, "action-server": {"action-server"},
         "action-client": {"action-client"}, "param": {"read", "declare", "write"}}
SITES: list[tuple[str, str, re.Pattern[str]]] = [
    (cat, form, re.compile(pattern)) for cat, form, pattern in (
        ("publish", "create_publisher", r"\bcreate_publisher\s*[<(]"),
        ("publish", "advertise", r"[.>]\s*advertise\s*[<(]"),
        ("subscribe", "create_subscription", r"\bcreate_subscription\s*[<(]"),
        ("subscribe", "subscribe", r"[.>]\s*subscribe\s*[<(]"),
        ("server", "create_service", r"\bcreate_service\s*[<(]"),
        ("server", "advertiseService", r"\badvertiseService\s*[<(]"),
        ("client", "create_client", r"(?<!rclcpp_action::)\bcreate_client\s*<"),
        ("client", "serviceClient", r"\bserviceClient\s*[<(]"),
        ("action-server", "rclcpp_action::create_server",
         r"rclcpp_action::create_server\s*<"),
        ("action-server", "actionlib server", r"\bnew\s+[\w:]*SimpleActionServer\s*<|"
                                              r"\bSimpleActionServer\s*<[^;]*>\s*\w+\s*[({]"),
        ("action-client", "rclcpp_action::create_client",
         r"rclcpp_action::create_client\s*<"),
        ("action-client", "actionlib client", r"\bnew\s+[\w:]*SimpleActionClient\s*<|"
                                              r"\bSimpleActionClient\s*<[^;]*>\s*\w+\s*[({]"),
        ("param", "declare_parameter<T>(name)", r"\bdeclare_parameter\s*<[^>]*>\s*\(\s*[^,()]*\)"),
        ("param", "declare_parameter", r"\bdeclare_parameter\s*[<(]"),
        ("param", "declare_parameters", r"\bdeclare_parameters\s*[<(]"),
        ("param", "get_parameter_or", r"\bget_parameter_or\s*[<(]"),
        ("param", "get_parameter", r"\bget_parameters?\s*[<(]"),
        ("param", "set_parameter", r"\bset_parameters?\s*\("),
        ("param", "param", r"[.>]\s*param\s*[<(]|\bros::param::\w+\s*[<(]"),
        ("param", "getParam", r"\bgetParam(Cached)?\s*\("),
        ("param", "setParam", r"\bsetParam\s*\("),
    )]
# roscpp's forms: in a ROS 2 package a ``getParam()`` / ``setParam(p)`` is a method of the
# package's own classes (Autoware's smoothers), not a ROS API call
ROS1_FORMS = frozenset({"advertiseService", "serviceClient", "actionlib server",
                        "actionlib client", "param", "getParam", "setParam"})
_COMMENT = re.compile(r"//.*$")
_DEFINITION = re.compile(r"^\s*(virtual\s+|static\s+|inline\s+)*[\w:<>,\s*&]+\s+\w+::"
                         r"(create_publisher|declare_parameter|get_parameter)\w*\s*\(")
_DECLARED = re.compile(r"(\d+) name\(s\) .* errors in this unit: (\d+) before, (\d+) after")
_QUOTED = re.compile(r"'[^']*'")
_SPAN = re.compile(r"\(lines (\d+)-(\d+)\)")


def sites(path: str, ros2: bool = False) -> list[tuple[int, str, str]]:
    """(line, category, form) of the API call sites grep finds in one source file (of a
    ROS 2 package: roscpp's forms left out)."""
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            lines = handle.read().splitlines()
    except OSError:
        return []
    found = []
    in_comment = False
    for number, line in enumerate(lines, 1):
        if in_comment:
            if "*/" not in line:
                continue
            line, in_comment = line.split("*/", 1)[1], False
        if "/*" in line and "*/" not in line.split("/*", 1)[1]:
            line, in_comment = line.split("/*", 1)[0], True
        code = _COMMENT.sub("", line)
        if _DEFINITION.match(code):
            continue
        for category, form, pattern in SITES:
            if ros2 and form in ROS1_FORMS:
                continue
            if pattern.search(code):
                found.append((number, category, form))
                break
    return found


def census(spec: str, jobs: int, timing: bool) -> None:
    root, _, only = spec.partition(":")
    root = os.path.abspath(root)
    workspace = scan([root], dict(os.environ))
    names = only.split(",") if only else sorted(workspace.packages)
    nodes = []
    ros2_units: set[str] = set()
    for name in names:
        package = workspace.packages.get(name)
        if package is None:
            continue
        if package.build_type in ("catkin", "ament_cmake", "cmake"):
            package.nodes, _ = cmake.parse_package(package, workspace)
        mine = [n for n in package.nodes if n.language == "cpp" and n.sources]
        nodes += mine
        if ros_version(package) == 2:
            ros2_units.update(os.path.join(workspace.root, s) for n in mine for s in n.sources)
    units = sorted({os.path.join(workspace.root, s) for n in nodes for s in n.sources
                    if "/test/" not in f"/{s}" and "/tests/" not in f"/{s}"})
    baseline = None
    if timing:  # the same units without the declaration of unknown names, first
        from haros_arch.extract.cpp import synthesis
        rounds, synthesis.MAX_ROUNDS = synthesis.MAX_ROUNDS, 0
        started = time.process_time()
        extract_cpp_nodes([[unit] for unit in units], workspace, cache_dir=None, jobs=jobs)
        baseline = time.process_time() - started
        synthesis.MAX_ROUNDS = rounds
    started = time.process_time()
    # one "node" per translation unit: each result holds that unit's calls and errors
    batch = extract_cpp_nodes([[unit] for unit in units], workspace, cache_dir=None,
                              jobs=jobs)
    elapsed = time.process_time() - started
    before_after = [0, 0, 0, 0]  # errors before, after; units with errors before, after
    calls: dict[str, dict[int, set[str]]] = collections.defaultdict(
        lambda: collections.defaultdict(set))
    errors: dict[str, list[str]] = {}
    spans: dict[str, list[tuple[int, int, str]]] = collections.defaultdict(list)
    for unit, result in zip(units, batch.results, strict=True):
        for item in result.diagnostics:  # errors in a function that calls the API
            span = _SPAN.search(item.message) if item.code == "CPP_ERROR_NEAR_CALL" else None
            if span and item.location.file:
                spans[item.location.file].append(
                    (int(span.group(1)), int(span.group(2)), item.message.split(": ", 1)[-1]))
        for call in result.calls:
            if call.location.file:
                calls[call.location.file][call.location.line].add(call.kind)
        rel = workspace.relpath(unit)
        errors[rel] = [d.message for d in result.diagnostics
                       if d.code in ("CPP_PARSE_ERROR", "CPP_MESSAGE_FIELD")]
        before = after = len(errors[rel])
        for item in result.diagnostics:
            match = _DECLARED.search(item.message) if item.code == "CPP_NAMES_DECLARED" \
                else None
            if match:
                before, after = int(match.group(2)), int(match.group(3))
        before_after[0] += before
        before_after[1] += after
        before_after[2] += before > 0
        before_after[3] += after > 0
    per_kind: dict[str, list[int]] = collections.defaultdict(lambda: [0, 0])
    causes: collections.Counter[str] = collections.Counter()
    missed: list[str] = []
    for unit in units:
        rel = workspace.relpath(unit)
        unit_errors = errors.get(rel, [])
        here = calls.get(rel, {})
        for line, category, form in sites(unit, unit in ros2_units):
            near = set().union(*(here.get(n, set()) for n in range(line - 3, line + 2)))
            ok = bool(near & KINDS[category])
            per_kind[category][0] += ok
            per_kind[category][1] += 1
            if not ok:
                inside = [m for a, b, m in spans.get(rel, ()) if a <= line <= b]
                if inside:
                    cause = f"error in its function: {_QUOTED.sub('…', inside[0])[:70]}"
                elif unit_errors:
                    cause = f"errors only elsewhere in the unit: {form}"
                else:
                    cause = f"clean unit: {form}"
                causes[cause] += 1
                missed.append(f"{rel}:{line} {category} ({cause})")
    by_unit = dict(zip(units, batch.results, strict=True))
    states: collections.Counter[str] = collections.Counter()
    hiding: collections.Counter[str] = collections.Counter()  # what makes nodes partial
    for result in batch.results:
        for item in result.diagnostics:
            if item.code == "CPP_ERROR_NEAR_CALL":
                hiding[_QUOTED.sub("…", item.message.split(": ", 1)[-1])[:80]] += 1
            elif item.code == "CPP_CALL_MISSED":
                hiding["call site with no call extracted"] += 1
    for node in nodes:  # each node's completeness from the diagnostics of its units
        found = [*batch.diagnostics, *(d for s in node.sources
                                       for d in getattr(by_unit.get(
                                           os.path.join(workspace.root, s)), "diagnostics", ()))]
        node.completeness, node.completeness_reasons = "complete", []
        completeness(node, found)
        states[node.completeness] += 1
    hit = sum(v[0] for v in per_kind.values())
    total = sum(v[1] for v in per_kind.values())
    print(f"== {os.path.basename(root)}{':' + only if only else ''}: {len(nodes)} C++ nodes, "
          f"{len(units)} units; call sites {hit}/{total} = {100 * hit / max(total, 1):.0f}%")
    print("   by kind: " + ", ".join(f"{k} {v[0]}/{v[1]}" for k, v in sorted(per_kind.items())))
    print("   nodes: " + ", ".join(f"{k} {v}" for k, v in sorted(states.items())))
    for reason, count in hiding.most_common(8):
        print(f"   partial {count:4}  {reason}")
    failed = sum(any(d.code == "CPP_PARSE_FAILED" for d in r.diagnostics)
                 for r in batch.results)
    if failed:
        print(f"   units libclang could not parse: {failed}")
    print(f"   clang errors: {before_after[0]} before synthesis in {before_after[2]} units, "
          f"{before_after[1]} after in {before_after[3]} units")
    print(f"   cold extraction {elapsed:.1f} s CPU, {1000 * elapsed / max(len(units), 1):.0f} ms "
          f"per unit (jobs {jobs})" + ("" if baseline is None else
                                       f"; without synthesis {baseline:.1f} s, ratio "
                                       f"{elapsed / max(baseline, 1e-9):.2f}"))
    for cause, count in causes.most_common(12):
        print(f"   miss {count:4}  {cause}")
    return_missed.extend(missed)


return_missed: list[str] = []


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspaces", nargs="+")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--misses", type=int, default=0)
    parser.add_argument("--no-synthesis", action="store_true")
    parser.add_argument("--timing", action="store_true")
    args = parser.parse_args()
    if args.no_synthesis:
        try:
            from haros_arch.extract.cpp import synthesis
            synthesis.MAX_ROUNDS = 0
        except ImportError:
            pass  # a version without it
    for spec in args.workspaces:
        return_missed.clear()
        census(spec, args.jobs, args.timing)
        for line in return_missed[:args.misses]:
            print("     " + line)


if __name__ == "__main__":
    checkout.announce()
    main()
