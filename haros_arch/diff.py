"""What a change does to the architecture: two models compared, for code review.

Configurations are matched by name. In each, node instances (by ROS name), topics,
services, actions and parameters (by name) and links (by kind, node instance and
resource name) are added, removed or changed; a change names the fields that differ
(what an instance runs, its remaps, arguments, conditions and completeness; a resource's
types; a link's type, QoS, queue size, latching and a read's default; a parameter's
value and type).
A node instance that moved to another name (same executable, same base name) is one
instance renamed, and what lived under its old name and is the same under the new one is
not listed again. Findings are matched by rule, entities and configuration, never by
line, so code that moves does not make them appear and disappear. Every entry carries
the file:line of the side it lives on: the new one, or the old one for what was removed.
The diagnostics ``check`` shows are compared by code, file and message.

``--rev BASE..HEAD`` analyses both revisions from git objects (``git archive``), each
written in turn into the same folder on every run: a C++ parse cache entry holds the
workspace headers it read by path, so the head and later runs (the next pull request)
reuse the entries of every file the change did not touch.
"""

from __future__ import annotations

import contextlib
import fcntl
import hashlib
import io
import json
import os
import shutil
import stat
import subprocess
import tarfile
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from itertools import takewhile
from typing import Any

from .model.diagnostic import SEVERITY_RANK, Diagnostic
from .model.finding import Finding
from .model.load import from_data, location
from .model.location import NOWHERE, Location
from .model.model import Model
from .model.runtime import REPEAT, Configuration, Link
from .model.serialise import json_text, to_data

Elements = dict[tuple[str, str], tuple[dict[str, Any], str]]
KINDS = ("node", "topic", "service", "action", "link", "parameter")
FAIL_ON = {"new-error": "error", "new-warning": "warning", "never": None}


@dataclass
class Change:
    """One element added, removed or changed; ``fields`` maps a changed field to its
    (old, new) values; ``location`` is where it lives (the old side when removed)."""

    kind: str
    key: str
    status: str  # "added", "removed", "changed", "renamed" (a node instance)
    location: str = ""
    fields: dict[str, tuple[Any, Any]] = field(default_factory=dict)

    def to_data(self) -> dict[str, Any]:
        data: dict[str, Any] = {"kind": self.kind, "key": self.key, "status": self.status,
                                "location": self.location}
        if self.fields:
            data["fields"] = {k: {"old": o, "new": n} for k, (o, n) in self.fields.items()}
        return data


@dataclass
class FindingChange:
    """A finding that appears ("new") or disappears ("gone") in one configuration."""

    status: str
    finding: Finding
    configuration: str | None

    @property
    def location(self) -> str:
        return "" if self.finding.location == NOWHERE else str(self.finding.location)

    def to_data(self) -> dict[str, Any]:
        return {"status": self.status, "configuration": self.configuration,
                "rule": self.finding.rule, "severity": self.finding.severity,
                "title": self.finding.title, "message": self.finding.message,
                "entities": list(self.finding.entities), "location": self.location}


@dataclass
class DiagnosticChange:
    """A diagnostic (a problem reading the workspace) that appears or disappears."""

    status: str  # "new", "gone"
    diagnostic: Diagnostic

    def to_data(self) -> dict[str, Any]:
        return {"status": self.status, "code": self.diagnostic.code,
                "severity": self.diagnostic.severity, "message": self.diagnostic.message,
                "location": _where(self.diagnostic.location)}


@dataclass
class ConfigDiff:
    name: str
    status: str  # "added", "removed", "changed", "renamed" (a node instance), "same"
    changes: list[Change] = field(default_factory=list)
    findings: list[FindingChange] = field(default_factory=list)


@dataclass
class DiffResult:
    old: str
    new: str
    configurations: list[ConfigDiff] = field(default_factory=list)
    diagnostics: list[DiagnosticChange] = field(default_factory=list)

    @property
    def findings(self) -> list[FindingChange]:
        return [f for c in self.configurations for f in c.findings]

    @property
    def changes(self) -> list[Change]:
        return [ch for c in self.configurations for ch in c.changes]

    def counts(self) -> dict[str, int]:
        found: dict[str, int] = {}
        for change in self.changes:
            found[change.status] = found.get(change.status, 0) + 1
        for item in self.findings:
            key = f"{item.status} {item.finding.severity}"
            found[key] = found.get(key, 0) + 1
        for said in self.diagnostics:
            key = f"{said.status} {said.diagnostic.severity} diagnostic"
            found[key] = found.get(key, 0) + 1
        return found

    def fails(self, fail_on: str) -> bool:
        """A new finding at or above ``fail_on`` (new-error, new-warning; never)."""
        floor = FAIL_ON[fail_on]
        return floor is not None and any(
            f.status == "new" and SEVERITY_RANK[f.finding.severity] >= SEVERITY_RANK[floor]
            for f in self.findings)

    def to_data(self) -> dict[str, Any]:
        return {"old": self.old, "new": self.new, "summary": self.counts(),
                "configurations": [
                    {"name": c.name, "status": c.status,
                     "changes": [ch.to_data() for ch in c.changes],
                     "findings": [f.to_data() for f in c.findings]}
                    for c in self.configurations],
                "diagnostics": [d.to_data() for d in self.diagnostics]}


# ------------------------------------------------------------------ comparing


def _where(loc: Location) -> str:
    return "" if loc == NOWHERE else str(loc)


def _link_fields(link: Link) -> dict[str, Any]:
    found: dict[str, Any] = {"type": link.type, "qos": to_data(link.qos),
                             "queue_size": link.queue_size, "latch": link.latch}
    if link.kind == "read" and link.call is not None:
        found["default"] = to_data(link.call.default) if link.call.has_default else None
    return found


def _elements(config: Configuration) -> Elements:
    """Every comparable element: (kind, key) -> (fields, location)."""
    found: dict[tuple[str, str], tuple[dict[str, Any], str]] = {}
    for node in config.nodes:
        found["node", node.name] = ({
            "runs": node.node.name if node.node is not None else None,
            "remaps": [list(r) for r in node.remaps], "args": node.args,
            "conditions": to_data(node.conditions),
            # a change that makes an interface unknown matters: absences are not facts
            "completeness": node.completeness}, _where(node.location))
    for kind, resources in (("topic", config.topics), ("service", config.services),
                            ("action", config.actions)):
        for resource in resources:  # unresolved names ("/?") may repeat: one entry
            first = resource.links[0].location if resource.links else NOWHERE
            known = found.get((kind, resource.name))
            types = sorted({*resource.types, *(known[0]["types"] if known else ())})
            found[kind, resource.name] = ({"types": types},
                                          known[1] if known else _where(first))
    for param in config.parameters:
        found["parameter", param.name] = ({"value": to_data(param.value),
                                           "type": param.type}, _where(param.location))
    grouped: dict[str, list[Link]] = {}
    for link in config.direct_links:
        grouped.setdefault(f"{link.kind} {link.node.name} {link.name}", []).append(link)
    for key, links in grouped.items():
        variants = [_link_fields(link) for link in links]
        if len(variants) == 1:
            fields = variants[0]
        else:  # several calls for one link: each field is the set of values they give
            fields = {name: sorted({json.dumps(v[name], sort_keys=True) for v in variants})
                      for name in variants[0]}
        found["link", key] = (fields, _where(links[0].location))
    return found


def _finding_keys(findings: Iterable[Finding]
                  ) -> dict[tuple[str | None, str, tuple[str, ...]], Finding]:
    keyed: dict[tuple[str | None, str, tuple[str, ...]], Finding] = {}
    for finding in findings:
        for config in finding.configurations or (finding.configuration,):
            # the number of "topic:/?#2" depends on the order the graph met the
            # unresolved names in, which an unrelated change may shift
            entities = tuple(sorted(REPEAT.sub("", e) for e in finding.entities))
            keyed.setdefault((config, finding.rule, entities), finding)
    return keyed


def _order(kind_key: tuple[str, str]) -> tuple[int, str]:
    return KINDS.index(kind_key[0]), kind_key[1]


def compare_configuration(old: Configuration | None, new: Configuration | None
                          ) -> list[Change]:
    before: Elements = _elements(old) if old is not None else {}
    after: Elements = _elements(new) if new is not None else {}
    changes: list[Change] = []
    for kind_key in sorted(before.keys() | after.keys(), key=_order):
        kind, key = kind_key
        if kind_key not in after:
            changes.append(Change(kind, key, "removed", before[kind_key][1]))
        elif kind_key not in before:
            changes.append(Change(kind, key, "added", after[kind_key][1]))
        else:
            (was, _), (now, where) = before[kind_key], after[kind_key]
            differ = {name: (was.get(name), now.get(name))
                      for name in dict.fromkeys([*was, *now])
                      if was.get(name) != now.get(name)}
            if differ:
                changes.append(Change(kind, key, "changed", where, differ))
    return _renamed(changes, before, after)


def _renamed(changes: list[Change], before: Elements, after: Elements) -> list[Change]:
    """A node instance removed and one added that runs the same executable under the same
    base name (a new namespace or a renamed parent) is one instance renamed; what lived
    under its old name and is the same under the new one (its private parameters,
    topics, services, and its links to them) moved with it, and is not listed again."""
    removed = [c.key for c in changes if c.kind == "node" and c.status == "removed"]
    added = [c.key for c in changes if c.kind == "node" and c.status == "added"]
    def candidates(old: str, among: list[str], side: Elements, runs: Any) -> list[str]:
        """Same executable and base name; of those, the ones sharing the most leading
        namespaces with ``old`` (/a/x/n pairs with /a/y/n, not with /b/y/n)."""
        same = [n for n in among if runs is not None and side["node", n][0]["runs"] == runs
                and n.rsplit("/", 1)[-1] == old.rsplit("/", 1)[-1]]
        shared = {n: sum(1 for _ in takewhile(
            lambda pair: pair[0] == pair[1],
            zip(n.split("/"), old.split("/"), strict=False))) for n in same}
        return [n for n in same if shared[n] == max(shared.values())]

    pairs: dict[str, str] = {}
    for old in removed:
        runs = before["node", old][0]["runs"]
        best = candidates(old, added, after, runs)
        # one-to-one: the added instance's best match among the removed is this one
        if len(best) == 1 and candidates(best[0], removed, before, runs) == [old]:
            pairs[old] = best[0]
    if not pairs:
        return changes
    hidden: set[tuple[str, str]] = set()
    for old, new in pairs.items():
        def moved(name: str, old: str = old, new: str = new) -> str | None:
            return new + name[len(old):] if name.startswith(old + "/") else None

        for change in changes:
            if change.status != "removed" or change.kind == "node":
                continue
            if change.kind == "link":
                kind, node, name = change.key.split(" ", 2)
                target = moved(name) if node == old else None
                key = f"{kind} {new} {target}" if target else None
            else:
                key = moved(change.key)
            if key is not None and (change.kind, key) in after \
                    and after[change.kind, key][0] == before[change.kind, change.key][0]:
                hidden |= {(change.kind, change.key), (change.kind, key)}
    kept: list[Change] = []
    for change in changes:
        if change.kind == "node" and change.key in pairs:
            new = pairs[change.key]
            (was, _), (now, where) = before["node", change.key], after["node", new]
            differ = {"name": (change.key, new), **{
                name: (was[name], now[name]) for name in was if was[name] != now[name]}}
            kept.append(Change("node", new, "renamed", where, differ))
        elif not (change.kind == "node" and change.key in pairs.values()) and (
                change.status == "changed" or (change.kind, change.key) not in hidden):
            kept.append(change)
    return kept


def compare(old: Model, new: Model, old_findings: Iterable[Finding] = (),
            new_findings: Iterable[Finding] = (), old_label: str = "old",
            new_label: str = "new") -> DiffResult:
    """The difference between two models and their findings."""
    result = DiffResult(old_label, new_label)
    before = {c.name: c for c in old.configurations}
    after = {c.name: c for c in new.configurations}
    found_before, found_after = _finding_keys(old_findings), _finding_keys(new_findings)
    keys = [*found_before, *found_after]
    names: list[str | None] = [*dict.fromkeys(
        [*before, *after, *(k[0] for k in keys if k[0] is not None)])]
    if any(k[0] is None for k in keys):
        names.append(None)  # findings about the model as a whole
    for name in names:
        if name is None:
            diff = ConfigDiff("", "same")
        else:  # (a configuration only findings name is compared by its findings)
            status = ("same" if (name in before) == (name in after)
                      else "added" if name not in before else "removed")
            diff = ConfigDiff(name, status)
            if name in before and name in after:
                diff.changes = compare_configuration(before[name], after[name])
                diff.status = "changed" if diff.changes else "same"
        for key in sorted(found_after.keys() - found_before.keys(), key=str):
            if key[0] == name:
                diff.findings.append(FindingChange("new", found_after[key], name))
        for key in sorted(found_before.keys() - found_after.keys(), key=str):
            if key[0] == name:
                diff.findings.append(FindingChange("gone", found_before[key], name))
        if diff.findings and diff.status == "same":
            diff.status = "changed"
        result.configurations.append(diff)
    was, now = _diagnostic_keys(old), _diagnostic_keys(new)
    result.diagnostics = [
        *(DiagnosticChange("new", now[k]) for k in sorted(now.keys() - was.keys())),
        *(DiagnosticChange("gone", was[k]) for k in sorted(was.keys() - now.keys()))]
    return result


def _diagnostic_keys(model: Model) -> dict[tuple[str, str, str], Diagnostic]:
    """The diagnostics ``check`` shows (not those a finding says better), by code, file
    and message: not by line, so moved code does not churn."""
    from .query.catalogue import absorbed

    said = absorbed(model)
    return {(d.code, d.location.file or "", d.message): d
            for d in model.all_diagnostics if d not in said}


# ------------------------------------------------------------------ inputs


class DiffError(Exception):
    """An input that cannot be compared: said in one line, never a traceback."""


def finding_from_data(data: dict[str, Any]) -> Finding:
    return Finding(str(data["rule"]), data.get("severity", "info"), str(data.get("title", "")),
                   str(data.get("message", "")), data.get("configuration"),
                   tuple(str(e) for e in data.get("entities", ())),
                   location(data.get("location")),
                   tuple(str(c) for c in data.get("configurations", ())),
                   tuple(location(a) for a in data.get("also", ()) if isinstance(a, dict)))


def load_saved(path: str) -> tuple[Model, list[Finding]]:
    """A model written by ``haros-arch extract -o`` and its findings (the document's
    ``findings``; the catalogue's when the document has none)."""
    from .model.load import ModelDataError

    try:
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
        model = from_data(data)
        if isinstance(data.get("findings"), list):
            findings = [finding_from_data(f) for f in data["findings"]]
        else:
            from .query.catalogue import run_catalogue

            findings = run_catalogue(model)
    except OSError as err:
        raise DiffError(f"cannot read {path}: {err.strerror or err}") from None
    except (ValueError, RecursionError, ModelDataError) as err:
        raise DiffError(f"{path} is not a haros-arch model: {err}") from None
    except (KeyError, TypeError, AttributeError) as err:
        raise DiffError(f"{path}: a finding has the wrong shape ({err})") from None
    if any(f.severity not in SEVERITY_RANK for f in findings):
        raise DiffError(f"{path}: a finding has an unknown severity")
    return model, findings


def _git(repo: str, *args: str) -> bytes:
    try:
        done = subprocess.run(["git", "-C", repo, *args], capture_output=True, timeout=300,
                              check=False)
    except (OSError, subprocess.TimeoutExpired) as err:
        raise DiffError(f"git {args[0]}: {err}") from None
    if done.returncode != 0:
        message = done.stderr.decode("utf-8", "replace").strip().splitlines()
        raise DiffError(f"git {args[0]} {' '.join(args[1:])}: "
                        f"{message[-1] if message else 'failed'}")
    return done.stdout


def split_range(text: str) -> tuple[str, str]:
    base, dots, head = text.partition("..")
    head = head if dots and head else "HEAD"
    # a revision is never an option of git ("--output=..." would write a file)
    if not base or head.startswith(".") or base.startswith("-") or head.startswith("-"):
        raise DiffError(f"--rev takes BASE..HEAD (two revisions), not {text!r}")
    return base, head


@contextlib.contextmanager
def _tree_folder(root: str) -> Iterator[str]:
    """One folder per repository, the same on every run (a parse cache entry names the
    workspace headers it read by path), in the cache folder, held under a lock while in
    use."""
    from .files import cache_folder

    digest = hashlib.sha256(os.path.realpath(root).encode()).hexdigest()[:12]
    base = os.path.join(cache_folder(root), "diff", digest)  # beside the parse cache
    os.makedirs(base, mode=0o700, exist_ok=True)
    state = os.lstat(base)  # made by us, for us alone (not another user's or a link)
    if not stat.S_ISDIR(state.st_mode) or state.st_uid != os.getuid() \
            or state.st_mode & 0o077:
        raise DiffError(f"{base} is not a private folder of this user")
    with open(os.path.join(base, "lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield os.path.join(base, "tree")
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def _unpack(root: str, rev: str, folder: str) -> None:
    """The revision's tree, from git objects: nothing in the working tree is touched
    and nothing from the repository runs."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    archive = _git(root, "archive", "--format=tar", rev)
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        members = [m for m in tar.getmembers() if _inside(m)]
        tar.extractall(folder, members=members, filter="data")


def _inside(member: tarfile.TarInfo) -> bool:
    """A file, folder or symbolic link that stays in the tree (no other kind)."""
    if not (member.isfile() or member.isdir() or member.issym()):
        return False
    name = os.path.normpath(member.name)
    if os.path.isabs(name) or name.startswith(".."):
        return False
    if member.issym():
        target = os.path.normpath(os.path.join(os.path.dirname(name), member.linkname))
        return not (os.path.isabs(member.linkname) or target.startswith(".."))
    return True


def analyse_revision(root: str, rev: str, path: str, folder: str, options: Any = None
                     ) -> tuple[Model, list[Finding], list[str]]:
    """The model and findings of PATH (a project file or a folder, relative to the
    repository root) at revision ``rev``, analysed in ``folder``; and notes to print."""
    from .autoproject import open_choice
    from .pipeline import analyse
    from .project import ProjectError
    from .query.catalogue import run_catalogue

    _git(root, "rev-parse", "--verify", "--quiet", f"{rev}^{{commit}}")
    _unpack(root, rev, folder)
    here = os.getcwd()
    os.chdir(folder)  # file names in the model are then relative to the repository root
    try:
        if not os.path.exists(path):
            raise DiffError(f"{path} does not exist at {rev}")
        try:
            choice = open_choice(path)
        except ProjectError as err:
            raise DiffError(f"{rev}: {err}") from None
        model = analyse(choice.project, options=options)
        findings = run_catalogue(model, choice.project)
    finally:
        os.chdir(here)
    # the notes name the temporary tree: said from the repository root instead
    return model, findings, [f"{rev}: " + note.replace(folder + os.sep, "").replace(
        folder, ".") for note in choice.notes]


def compare_revisions(spec: str, path: str = ".", repo: str = ".", options: Any = None
                      ) -> tuple[DiffResult, list[str]]:
    base, head = split_range(spec)
    if _git(repo, "rev-parse", "--is-bare-repository").strip() == b"true":
        root = _git(repo, "rev-parse", "--absolute-git-dir").decode().strip()
    else:  # PATH is relative to the root of the repository's work tree
        root = _git(repo, "rev-parse", "--show-toplevel").decode().strip()
    if os.path.isabs(path):
        path = os.path.relpath(path, root)
    sides = []
    notes: list[str] = []
    with _tree_folder(root) as folder:
        try:
            for rev in (base, head):
                model, findings, said = analyse_revision(root, rev, path, folder, options)
                sides.append((model, findings))
                notes.extend(said)
        finally:  # the cache keeps what the next run needs: the files are not
            shutil.rmtree(folder, ignore_errors=True)
    (old, old_found), (new, new_found) = sides
    return compare(old, new, old_found, new_found, base, head), notes


# ------------------------------------------------------------------ output

MARK = {"added": "+", "removed": "-", "changed": "~", "renamed": "~", "new": "+", "gone": "-"}


def _value(value: Any) -> str:
    return json.dumps(value, sort_keys=True, ensure_ascii=False)


def summary(result: DiffResult) -> str:
    counts = result.counts()
    parts = [f"{counts[s]} {s}" for s in ("added", "removed", "changed", "renamed")
             if counts.get(s)]
    def ranked(keys: Iterable[str]) -> list[str]:  # new before gone, errors first
        return sorted(keys, key=lambda k: (k.split()[0] != "new",
                                           -SEVERITY_RANK.get(k.split()[1], 0)))

    found = [f"{counts[k]} {k}" for k in ranked(
        k for k in counts if " " in k and not k.endswith(" diagnostic"))]
    said = [f"{counts[k]} {k}(s)" for k in ranked(k for k in counts
                                                  if k.endswith(" diagnostic"))]
    configs = [f"configuration {c.name} {c.status}" for c in result.configurations
               if c.status in ("added", "removed")]
    text = ", ".join([*configs, *parts]) or "no change to the graph"
    findings = ", ".join(f"{f} finding(s)" for f in found) or "no finding appears or disappears"
    return f"{result.old}..{result.new}: {text}; {', '.join([findings, *said])}"


def _change_line(change: Change) -> str:
    where = f"  ({change.location})" if change.location else ""
    line = f"{MARK[change.status]} {change.kind} {change.key}{where}"
    details = "; ".join(f"{name}: {_value(old)} -> {_value(new)}"
                        for name, (old, new) in change.fields.items())
    return f"{line}\n    {details}" if details else line


def _finding_line(item: FindingChange, mark: bool = True) -> str:
    """The finding as a line; ``mark``: led by + or - (not in a Markdown list, where
    "- -" would open a nested one)."""
    where = f"  ({item.location})" if item.location else ""
    lead = f"{MARK[item.status]} " if mark else ""
    return (f"{lead}{item.status} {item.finding.severity} "
            f"[{item.finding.rule}] {item.finding.message}{where}")


def to_text(result: DiffResult) -> str:
    lines = [summary(result)]
    for config in result.configurations:
        if config.status == "same":
            continue
        title = f"configuration {config.name}" if config.name else "the whole model"
        lines.append(f"\n{title} ({config.status})")
        lines.extend("  " + _change_line(c).replace("\n", "\n  ") for c in config.changes)
        lines.extend("  " + _finding_line(f) for f in config.findings)
    if result.diagnostics:
        lines.append("\ndiagnostics")
        lines.extend("  " + _diagnostic_line(d) for d in result.diagnostics)
    return "\n".join(lines) + "\n"


def _diagnostic_line(item: DiagnosticChange, mark: bool = True) -> str:
    said = item.diagnostic
    where = f"  ({said.location})" if said.location != NOWHERE else ""
    lead = f"{MARK[item.status]} " if mark else ""
    return f"{lead}{item.status} {said.severity} [{said.code}] {said.message}{where}"


STYLE = {"+": "green", "-": "red", "~": "yellow"}


def print_text(result: DiffResult, console: Any) -> None:
    """``to_text`` on a rich console: the summary in bold, additions green, removals red,
    changes yellow (plain when the console has no colour)."""
    from rich.markup import escape

    for number, line in enumerate(to_text(result).splitlines()):
        style = "bold" if number == 0 or line.startswith(("configuration", "diagnostics",
                                                          "the whole model")) else \
            STYLE.get(line.strip()[:1], "")
        text = escape(line)
        console.print(f"[{style}]{text}[/{style}]" if style else text, highlight=False)


def _md(text: str) -> str:
    """Text for a Markdown table cell or list item: no markup from the analysed code."""
    escaped = text.replace("\\", "\\\\").replace("|", "\\|").replace("<", "&lt;")
    for char in "`*_[]#":
        escaped = escaped.replace(char, "\\" + char)
    return escaped.replace("\n", " ")


# GitHub refuses comments over 65,536 characters: the details stop before that
MARKDOWN_LIMIT = 60_000


def to_markdown(result: DiffResult, limit: int = MARKDOWN_LIMIT) -> str:
    """A pull-request comment: the summary and the new findings first, the rest folded;
    configurations whose entries read the same are one block; past ``limit`` characters
    the rest is counted, not shown."""
    new = [f for f in result.findings if f.status == "new"]
    head = ["### haros-arch: architecture diff", "", _md(summary(result)), ""]
    if new:
        head.extend(["**New findings**", "",
                     *(f"- {_md(_finding_line(f, mark=False))}" for f in new), ""])
    blocks: dict[tuple[str, ...], list[ConfigDiff]] = {}
    for config in result.configurations:
        if config.status != "same":
            blocks.setdefault(_block_rows(config), []).append(config)
    body: list[str] = []
    for rows, configs in blocks.items():
        names = ", ".join(c.name or "the whole model" for c in configs)
        first = configs[0]
        title = (f"{'configurations' if len(configs) > 1 else 'configuration'} {names}: "
                 f"{first.status}, {len(first.changes)} change(s), {len(first.findings)} "
                 "finding change(s)")
        body.extend([f"<details><summary>{_md(title)}</summary>", ""])
        body.extend(rows)
        body.extend(["", "</details>", ""])
    if result.diagnostics:
        body.extend([f"<details><summary>diagnostics: {len(result.diagnostics)} "
                     "change(s)</summary>", ""])
        body.extend(f"- {_md(_diagnostic_line(d, mark=False))}" for d in result.diagnostics)
        body.extend(["", "</details>", ""])
    lines, size = list(head), sum(len(line) + 1 for line in head)
    for number, line in enumerate(body):
        if size + len(line) > limit:
            rest = sum(1 for b in body[number:] if b.startswith(("| ", "- ")))
            inside = sum(1 for b in lines if b.startswith("<details>")) > sum(
                1 for b in lines if b == "</details>")
            lines.extend(["", *(["</details>", ""] if inside else []),
                          f"*{rest} more entries left out (the comment's size limit): "
                          "run haros-arch diff for all of them*"])
            break
        lines.append(line)
        size += len(line) + 1
    return "\n".join(lines).rstrip("\n") + "\n"


def _block_rows(config: ConfigDiff) -> tuple[str, ...]:
    rows: list[str] = []
    if config.changes:
        rows.extend(["| | kind | name | where | what changed |", "|---|---|---|---|---|"])
        for change in config.changes:
            what = "; ".join(f"{name}: {_value(old)} → {_value(new)}"
                             for name, (old, new) in change.fields.items())
            rows.append(f"| {change.status} | {change.kind} | {_md(change.key)} | "
                        f"{_md(change.location)} | {_md(what)} |")
        rows.append("")
    rows.extend(f"- {_md(_finding_line(f, mark=False))}" for f in config.findings)
    return tuple(rows)


def to_json(result: DiffResult) -> str:
    return json_text(result.to_data(), indent=2, ensure_ascii=False) + "\n"
