"""The launch tree in the terminal (``haros-arch launch FILE --tree``), as a rich Tree."""

from __future__ import annotations

from rich.markup import escape
from rich.tree import Tree

from ..model.launch_tree import LaunchCondition, LaunchItem

MAX_SHOWN = 20_000  # items drawn at most; the rest is counted
MAX_PARAMS = 8  # a scope's parameters listed one by one up to this many


def as_rich(items: list[LaunchItem]) -> Tree:
    top = Tree("launch", hide_root=True)
    budget = [MAX_SHOWN]
    for item in items:
        _add(top, item, budget)
    if budget[0] < 0:
        top.add(f"[dim]... {-budget[0]} more items not shown[/]")
    return top


def label(item: LaunchItem) -> str:
    where = escape(str(item.location))
    left_out = "  [red](left out)[/]" if item.skipped else ""
    if item.kind == "file":
        reached = f"  [dim]included at {where}[/]" if item.location.file != item.name else ""
        text = f"[bold]{escape(item.name)}[/]{reached}"
        if item.namespace not in ("", "/"):
            text += f"  ns {escape(item.namespace)}"
    elif item.kind == "include" and item.detail == "action":
        text = f"action not interpreted: {escape(item.name)}  [dim]{where}[/]"
    elif item.kind == "include":
        text = f"include [bold]{escape(item.name)}[/]  [dim]{where}[/]"
    elif item.kind == "group":
        pushed = " ".join(escape(p) for p in item.pushed)
        ns = escape(item.name or pushed)
        text = f"group{' ns ' + ns if ns else ''}  [dim]{where}[/]"
    else:
        text = (f"node [bold cyan]{escape(item.name)}[/]  {escape(item.detail)}"
                f"  [dim]{where}[/]")
    return text + left_out


def condition(cond: LaunchCondition) -> str:
    values = ", ".join(f"{escape(k)}={'?' if v is None else escape(v)}"
                       for k, v in cond.values.items())
    outcome = {True: "holds", False: "[red]false[/]", None: "[yellow]unknown[/]"}[cond.holds]
    decided = f" with {values}" if values else ""
    return f"[magenta]{cond.statement} {escape(cond.text)}[/]{decided}: {outcome}"


def _add(parent: Tree, item: LaunchItem, budget: list[int]) -> None:
    stack: list[tuple[Tree, LaunchItem]] = [(parent, item)]
    while stack:  # iterative: a deep tree does not exhaust Python's stack
        into, current = stack.pop()
        budget[0] -= 1
        if budget[0] < 0:
            continue
        branch = into.add(label(current))
        if current.condition is not None:
            branch.add(condition(current.condition))
        for arg in current.args:
            value = "?unset" if arg.value is None else escape(arg.value)
            where = f" {escape(str(arg.location))}" if arg.location.file else ""
            branch.add(f"arg [green]{escape(arg.name)}[/] = {value}  "
                       f"[dim]({arg.origin}{where})[/]")
        for source, target in current.remaps:
            branch.add(f"remap {escape(source)} -> {escape(target)}")
        shown = current.params if len(current.params) <= MAX_PARAMS else current.params[:3]
        for name in shown:
            branch.add(f"param {escape(name)}")
        if len(shown) < len(current.params):
            branch.add(f"[dim]... {len(current.params) - len(shown)} more parameters[/]")
        stack.extend((branch, child) for child in reversed(current.children))
