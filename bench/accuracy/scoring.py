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


def markdown(results: list[dict[str, Any]], header: list[str]) -> str:
    """results.md: overall table, per-configuration table, then every miss."""
    lines = ["# Accuracy benchmark: results", "", *header, ""]
    summed = totals(results)
    lines += ["## Overall (micro-averaged over all scored configurations)", "",
              "| element | matched | extracted | live | precision | recall |",
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
    perfect = sum(1 for r in results if r.get("scores") and all(
        s["precision"] == 1 and s["recall"] == 1 for s in r["scores"]))
    lines += [f"{len(results)} configurations; {perfect} match the running system exactly.",
              "", "## Per configuration", "",
              "A cell is `precision/recall (matched/live)`, or `N ✓` when all N agree.", "",
              "| configuration | run | " + " | ".join(SHORT[k] for k in KINDS) + " |",
              "|---|---|" + "---|" * len(KINDS)]
    for result in results:
        cells = [_cell(_score(result, kind)) for kind in KINDS]
        lines.append(f"| {result['configuration']} | {_run_note(result)} | "
                     + " | ".join(cells) + " |")
    lines += ["", "## Every difference", "",
              "`missing`: on the running system, not in our model (hurts recall). "
              "`extra`: in our model, not on the running system (hurts precision).", ""]
    for result in results:
        diffs = []
        if result.get("error"):
            diffs.append(f"- error: {result['error']}")
        for score in result.get("scores", []):
            for what in ("missing", "extra"):
                for item in score[what]:
                    diffs.append(f"- {score['kind']} {what}: `{item}`")
        if diffs:
            lines += [f"### {result['configuration']}", "", *diffs, ""]
    return "\n".join(lines) + "\n"


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
