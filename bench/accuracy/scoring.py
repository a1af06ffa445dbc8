"""Tables of the accuracy benchmark: per configuration and overall, every miss listed."""

from __future__ import annotations

from typing import Any

KINDS = ("nodes", "topics", "topic types", "publish links", "subscribe links", "services",
         "service links", "parameters")
SHORT = {"nodes": "nodes", "topics": "topics", "topic types": "types",
         "publish links": "pub", "subscribe links": "sub", "services": "srv",
         "service links": "srv links", "parameters": "params"}


def totals(results: list[dict[str, Any]]) -> dict[str, dict[str, float]]:
    """Micro-averaged precision and recall per kind over all configurations."""
    summed: dict[str, dict[str, float]] = {}
    for kind in KINDS:
        ours = live = matched = 0
        for result in results:
            score = _score(result, kind)
            if score is None:
                continue
            ours += score["ours"]
            live += score["live"]
            matched += score["matched"]
        summed[kind] = {"ours": ours, "live": live, "matched": matched,
                        "precision": matched / ours if ours else 1.0,
                        "recall": matched / live if live else 1.0}
    return summed


def _score(result: dict[str, Any], kind: str) -> dict[str, Any] | None:
    for score in result.get("scores", []):
        if score["kind"] == kind:
            return score
    return None


def _cell(score: dict[str, Any] | None) -> str:
    if score is None:
        return "-"
    if score["ours"] == score["live"] == score["matched"]:
        return f"{score['matched']} ✓"
    return f"{score['precision']:.2f}/{score['recall']:.2f} ({score['matched']}/{score['live']})"


def _overall(results: list[dict[str, Any]]) -> list[str]:
    summed = totals(results)
    lines = ["| element | matched | extracted | live | precision | recall |",
             "|---|---:|---:|---:|---:|---:|"]
    for kind in KINDS:
        s = summed[kind]
        lines.append(f"| {kind} | {s['matched']:.0f} | {s['ours']:.0f} | {s['live']:.0f} | "
                     f"{s['precision']:.3f} | {s['recall']:.3f} |")
    all_ours = sum(s["ours"] for s in summed.values())
    all_live = sum(s["live"] for s in summed.values())
    all_matched = sum(s["matched"] for s in summed.values())
    lines += [f"| **all** | {all_matched:.0f} | {all_ours:.0f} | {all_live:.0f} | "
              f"{all_matched / all_ours if all_ours else 1:.3f} | "
              f"{all_matched / all_live if all_live else 1:.3f} |", ""]
    return lines


def _perfect(results: list[dict[str, Any]]) -> int:
    return sum(1 for r in results if r.get("scores") and all(
        s["precision"] == 1 and s["recall"] == 1 for s in r["scores"]))


def _table(results: list[dict[str, Any]]) -> list[str]:
    lines = ["| configuration | run | " + " | ".join(SHORT[k] for k in KINDS) + " |",
             "|---|---|" + "---|" * len(KINDS)]
    for result in results:
        cells = [_cell(_score(result, kind)) for kind in KINDS]
        lines.append(f"| {result['configuration']} | {_run_note(result)} | "
                     + " | ".join(cells) + " |")
    return [*lines, ""]


def _differences(results: list[dict[str, Any]]) -> list[str]:
    lines: list[str] = []
    for result in results:
        diffs = []
        if result.get("error"):
            diffs.append(f"- error: {result['error']}")
        for score in result.get("scores", []):
            for what in ("missing", "extra"):
                for item in score[what]:
                    diffs.append(f"- {score['kind']} {what}: `{item}`")
        if diffs:
            lines += [f"#### {result['configuration']}", "", *diffs, ""]
    return lines


def markdown(plain: list[dict[str, Any]], hinted: list[dict[str, Any]],
             header: list[str]) -> str:
    """results.md: both overall tables (without / with hints), per-configuration tables,
    then every difference."""
    with_hints = [r for r in hinted if r.get("hints")]
    names = {r["configuration"] for r in with_hints}
    lines = ["# Accuracy benchmark: results", "", *header, "",
             "Each configuration is scored twice. **Without hints**: the project file has "
             "no hints (`projects/NAME.yaml`), the extractor alone. **With hints**: the "
             "project file adds the hints of `hints.yaml` (`projects_hints/NAME.yaml`), "
             "written from the packages' documentation and sources, for what only exists "
             f"at run time; {len(with_hints)} configurations get hints "
             f"({', '.join(f'`{r}`' for r in sorted(names)) or 'none'}), the others have "
             "the same project file and score in both passes.", "",
             "## Overall, without hints (the extractor alone)", "",
             "Micro-averaged over all scored configurations.", "",
             *_overall(plain),
             f"{len(plain)} configurations; {_perfect(plain)} match the running system "
             "exactly.", "",
             "## Overall, with hints (`hints.yaml`)", "",
             *_overall(hinted),
             f"{len(hinted)} configurations; {_perfect(hinted)} match the running system "
             "exactly.", "",
             "## Per configuration, without hints", "",
             "A cell is `precision/recall (matched/live)`, or `N ✓` when all N agree.", "",
             *_table(plain),
             "## Per configuration, with hints (only those that get hints)", "",
             *_table(with_hints),
             "## Every difference", "",
             "`missing`: on the running system, not in our model (hurts recall). "
             "`extra`: in our model, not on the running system (hurts precision).", "",
             "### With hints (what remains; configurations without hints are the same "
             "without them)", "",
             *_differences(hinted),
             "### Without hints, the configurations that get hints", "",
             *_differences([r for r in plain if r["configuration"] in names])]
    return "\n".join(lines).rstrip("\n") + "\n"


def _run_note(result: dict[str, Any]) -> str:
    run = result.get("run") or {}
    notes = []
    if run and not run.get("settled", True):
        notes.append("unsettled")
    if run.get("launch_exit") not in (None, 0):
        notes.append(f"roslaunch exit {run['launch_exit']}")
    if result.get("error"):
        notes.append("error")
    return ", ".join(notes) or "ok"
