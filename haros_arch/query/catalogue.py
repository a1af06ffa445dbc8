"""The query catalogue: rules from ``queries/*.yaml`` and from the project file, run per
configuration, their matches turned into ``Finding`` values.

A rule has ``id``, ``severity``, ``title``, ``description`` (why it matters, how to fix),
``query`` and optionally ``message``, a template whose ``{name.field}`` parts are read
through the same allow-list as queries (never ``str.format``). Project files give rules
as ``queries:`` (our form), HAROS ``rules:`` (those with a ``query``) and HAROS's pyflwor
plugin entries in a configuration's ``user_data``.
"""

from __future__ import annotations

import functools
import re
import sys
import time
from collections.abc import Iterable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import yaml

from ..model.conditions import Condition
from ..model.diagnostic import SEVERITY_RANK, Diagnostic, Severity
from ..model.finding import Finding
from ..model.location import NOWHERE, Location, is_upstream
from ..model.model import Model
from ..model.runtime import REPEAT, Configuration, Link
from . import compile, config_scope, model_scope
from .errors import QueryError, QueryLimitError
from .interpreter import DEFAULT_STEPS, Evaluator
from .results import (
    best_location,
    entities,
    entity_ids,
    label,
    location_of,
    place_of,
    placed,
    plain,
)
from .suppress import Suppressions
from .syntax import Literal

# queries/ of the source tree (editable installs), else where a wheel puts it
CATALOGUE_DIRS = (Path(__file__).resolve().parent.parent.parent / "queries",
                  Path(sys.prefix) / "share" / "haros-arch" / "queries")
CATALOGUE_DIR = next((d for d in CATALOGUE_DIRS if d.is_dir()), CATALOGUE_DIRS[0])
QUERY_ERROR = "query-error"
QUERY_LIMIT = "query-limit"  # a rule stopped by the step budget: a warning, not an error
# The step budget (deterministic) bounds a rule's work; the clock is only a safety net
# far above it, so findings do not depend on how busy the machine is.
SAFETY_SECONDS = 300.0
STEPS = DEFAULT_STEPS
UNDECIDED = "-undecided"  # suffix of the id of a rule's info on matches it cannot decide
# suffix of the id of a rule's info on matches about installed packages' own files only
UPSTREAM = "-upstream"
# diagnostics whose codes a catalogue rule reports as findings (``check`` shows them once)
ABSORBED_CODES = frozenset({"LAUNCH_FILE_MISSING", "PACKAGE_NOT_FOUND", "NODE_NOT_FOUND",
                            "NODE_NOT_EXECUTABLE", "NODE_EXECUTABLE_BLANK"})
# a name computed at run time, said by the extractor about a call; where a configuration
# instantiates the call, the graph says it better: unresolved-names reports the name per
# node instance, or a launch value or code default has completed it, or a condition
# false there has dropped it
DYNAMIC_NAME_CODES = frozenset({"CPP_DYNAMIC_NAME", "PY_DYNAMIC_NAME"})


def absorbed(model: Model) -> set[Diagnostic]:
    """The diagnostics that the graph or catalogue rules say better: a configuration's
    missing references (launch-missing-reference), and run-time names of calls that
    some configuration instantiates. ``check`` shows each problem once."""
    found = {d for config in model.configurations for d in config.diagnostics
             if d.code in ABSORBED_CODES}
    linked = {link.location for config in model.configurations
              for link in config.direct_links}
    # a call a configuration made and dropped, its condition false there (CONDITION_FALSE
    # says so at the call): the graph said what became of it
    linked.update(d.location for config in model.configurations
                  for d in config.diagnostics if d.code == "CONDITION_FALSE")
    found.update(d for d in model.diagnostics
                 if d.code in DYNAMIC_NAME_CODES and d.location in linked)
    return found


@dataclass(frozen=True)
class Rule:
    id: str
    severity: Severity
    title: str
    query: str
    description: str = ""
    message: str | None = None
    scope: str = "configuration"  # configuration | model | auto
    configurations: tuple[str, ...] | None = None  # only these (None: all)
    origin: str = ""
    # the key of a match that lists the nodes of partial or unknown interface that could
    # be the missing side: a match where it is not empty is not a finding; they are
    # counted in one info per configuration (the rule's id + UNDECIDED)
    undecided_by: str | None = None
    # what the undecided info says of those nodes (default: they could be the missing side)
    undecided_why: str | None = None
    # the key of a match that lists where the one problem it reports shows (places, or
    # entities at theirs: the instances of one duplicated name): the finding is at the
    # first, the others are its ``also``
    places_by: str | None = None


class CatalogueError(ValueError):
    pass


def _rule(data: Any, origin: str, default_id: str = "", scope: str = "auto") -> Rule:
    if isinstance(data, str):
        data = {"query": data}
    if not isinstance(data, dict) or not isinstance(data.get("query"), str):
        raise CatalogueError(f"{origin}: a rule needs a 'query' string")
    severity: Any = str(data.get("severity", "warning"))
    if severity not in SEVERITY_RANK:
        raise CatalogueError(f"{origin}: severity must be one of {', '.join(SEVERITY_RANK)}")
    rule_id = str(data.get("id") or default_id or data.get("name") or "query")
    return Rule(rule_id, severity, str(data.get("title") or data.get("name") or rule_id),
                data["query"], str(data.get("description", "")),
                data.get("message") or data.get("details"),
                str(data.get("scope", scope)), None, origin,
                str(data["undecided_by"]) if data.get("undecided_by") else None,
                str(data["undecided_why"]) if data.get("undecided_why") else None,
                str(data["places_by"]) if data.get("places_by") else None)


def load_catalogue(folder: Path | str | None = None) -> list[Rule]:
    """The shipped rules, one YAML file each, sorted by id."""
    folder = Path(folder) if folder is not None else CATALOGUE_DIR
    if not folder.is_dir():
        raise CatalogueError(f"the query catalogue is not at {folder}")
    files = []
    for path in sorted(folder.glob("*.yaml")):
        try:
            info = path.stat()
            files.append((str(path), info.st_mtime_ns, info.st_size))
        except OSError:
            files.append((str(path), 0, 0))
    return list(_rules(tuple(files)))  # read once per process while the files stay


@functools.lru_cache(maxsize=8)
def _rules(files: tuple[tuple[str, int, int], ...]) -> tuple[Rule, ...]:
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's when built with it
    rules = []
    for name, _mtime, _size in files:
        path = Path(name)
        data = yaml.load(path.read_text("utf-8"), Loader=loader)
        rules.append(_rule(data, str(path), path.stem, "configuration"))
    return tuple(rules)


def project_rules(project: Any) -> list[Rule]:
    """``queries:``, HAROS ``rules:`` with a ``query``, and pyflwor plugin user_data."""
    rules: list[Rule] = []
    origin = getattr(project, "path", "project")
    for i, item in enumerate(getattr(project, "queries", None) or ()):
        rules.append(_rule(item, f"{origin}: queries[{i}]", f"project-query-{i + 1}"))
    for key, item in (getattr(project, "rules", None) or {}).items():
        if isinstance(item, dict) and "query" in item:
            scope = "configuration" if item.get("scope") == "configuration" else "auto"
            rules.append(_rule({**item, "id": key}, f"{origin}: rules.{key}", key, scope))
    for spec in getattr(project, "configurations", None) or ():
        entries = (spec.user_data or {}).get("haros_plugin_pyflwor") or ()
        for i, item in enumerate(entries):
            rule = _rule(item, f"{origin}: configurations.{spec.name}.user_data",
                         f"{spec.name}-query-{i + 1}", "configuration")
            rules.append(Rule(**{**rule.__dict__, "configurations": (spec.name,)}))
    return rules


_NOWHERE_IN_QUERY = Literal(None)
_FIELD = re.compile(r"\{([A-Za-z_][A-Za-z_0-9]*(?:\.[A-Za-z_][A-Za-z_0-9]*)*)\}")


def render(template: str, match: Any, evaluator: Evaluator) -> str:
    """Fill ``{name.field}`` from a match through the query allow-list."""
    if isinstance(match, dict):
        names = dict(match)
    elif isinstance(match, tuple):
        names = {str(i): v for i, v in enumerate(match)}
    else:
        names = {"self": match, "0": match}
    names["entities"] = ", ".join(label(e) for e in entities(match))

    def fill(found: re.Match[str]) -> str:
        head, *fields = found.group(1).split(".")
        if head not in names:
            return found.group(0)
        value = names[head]
        try:
            for name in fields:
                value = evaluator.attribute(value, name, _NOWHERE_IN_QUERY)
        except QueryError:
            return ""
        if isinstance(value, list | tuple) and not value:
            return "none"
        if isinstance(value, list | tuple) and any(entities(v) for v in value):
            # entities by name, each once (the nodes of several links); a name that
            # several node instances have says how many ("/driver (2 instances)": a
            # launch file included twice), else the message would name one node
            instances: dict[str, set[str]] = {}
            for v in value:
                if isinstance(v, Link):
                    instances.setdefault(v.node.name, set()).add(v.node.id)
                else:
                    instances.setdefault(label(v) if entities(v) else str(plain(v)), set())
            return _items([name + (f" ({len(ids)} instances)" if len(ids) > 1 else "")
                           for name, ids in instances.items()])
        if isinstance(value, list | tuple) and all(isinstance(v, Location) for v in value):
            return _places_text(value)
        if isinstance(value, list | tuple):  # a value: every element, as it is
            return _items([str(plain(v)) for v in value])
        if isinstance(value, Location):  # a place is whole: its line ends it
            return str(plain(value))
        if isinstance(value, str) and fields and fields[-1] == "message" and (
            len(value) <= MAX_MESSAGE
        ):
            return value  # a diagnostic's own sentence, not data read from the workspace
        if isinstance(value, str) and not value and fields and fields[-1] == "value":
            return "''"  # an empty string value (a parameter's), not nothing
        return label(value) if entities(value) else _shorten(str(plain(value)))

    return _FIELD.sub(fill, template)


MESSAGE_VALUE = 120  # characters a long filled-in value (a binfile, a YAML map) is cut to
WHOLE_VALUE = 256  # a value up to this length is filled in whole (a long ROS name)
MESSAGE_ITEMS = 240  # characters of a list's items before the rest are only counted
MAX_MESSAGE = 2000  # a diagnostic's message filled in whole, up to this length


def _shorten(text: str) -> str:
    return text if len(text) <= WHOLE_VALUE else text[:MESSAGE_VALUE - 1] + "…"


def _items(items: list[str]) -> str:
    """A list's items, each whole, joined by commas; past ``MESSAGE_ITEMS`` characters
    the items left are counted ("and 12 more"), not cut in the middle of a name."""
    out: list[str] = []
    size = 0
    for index, item in enumerate(items):
        text = _shorten(item)
        if out and size + len(text) > MESSAGE_ITEMS:
            return f"{', '.join(out)} and {len(items) - index} more"
        out.append(text)
        size += len(text) + 2
    return ", ".join(out)


def _places_text(places: Iterable[Location]) -> str:
    """Places by file, each file once: ``a.launch:7``, ``b.launch lines 3, 9 and 12``,
    files apart by ``;`` (their number counted past ``MESSAGE_ITEMS`` characters)."""
    lines: dict[str, list[Location]] = {}
    for where in places:
        lines.setdefault(where.file or str(where), []).append(where)
    parts = []
    for file, here in lines.items():
        numbers = list(dict.fromkeys(str(w.line) for w in here if w.file and w.line))
        if len(numbers) < 2:
            parts.append(_shorten(str(here[0])))
        else:
            parts.append(f"{_shorten(file)} lines {', '.join(numbers[:-1])} and "
                         f"{numbers[-1]}")
    out: list[str] = []
    size = 0
    for index, part in enumerate(parts):
        if out and size + len(part) > MESSAGE_ITEMS:
            return f"{'; '.join(out)} and {len(parts) - index} more"
        out.append(part)
        size += len(part) + 2
    return "; ".join(out)


def _finding(rule: Rule, match: Any, config: Configuration | None,
             evaluator: Evaluator) -> Finding:
    involved = entities(match)
    if rule.message:
        # the template's layout (a YAML block over lines) is joined; the values filled
        # in keep their blanks (a package looked up by '   ', quoted as written)
        message = render(" ".join(rule.message.split()), match, evaluator)
    else:
        message = "; ".join(label(e) for e in involved) or str(plain(match))
    where = best_location(involved)
    if not where.file:
        where = place_of(match)
    places = [p for p in _places(rule, match) if p.file]
    where = places[0] if places else where
    also = tuple(p for p in dict.fromkeys(places) if p != where)
    return Finding(rule.id, rule.severity, rule.title, _one_line(message),
                   config.name if config else None, entity_ids(involved), where, also=also)


def _one_line(message: str) -> str:
    """A message on one line: each line break of a value filled in (and the blanks
    around it) one blank; the blanks inside a line kept as they are."""
    return " ".join(line.strip() for line in message.splitlines() if line.strip())


def _places(rule: Rule, match: Any) -> list[Location]:
    """The places a match's ``places_by`` list gives (a place, or an entity's)."""
    if rule.places_by is None or not isinstance(match, dict):
        return []
    items = match.get(rule.places_by)
    if not isinstance(items, list | tuple):
        return []
    return [item if isinstance(item, Location) else location_of(item) for item in items]


def _scopes(rule: Rule, query: Any, model: Model) -> Iterable[tuple[Configuration | None,
                                                                    dict[str, Any]]]:
    per_config = rule.scope == "configuration" or (rule.scope == "auto"
                                                  and query.needs_configuration)
    if not per_config:
        yield None, model_scope(model)
        return
    for config in model.configurations:
        if rule.configurations is None or config.name in rule.configurations:
            yield config, config_scope(config, model)


def run_rule(rule: Rule, model: Model) -> list[Finding]:
    """A rule's findings over every configuration (or the model, for model rules)."""
    return [finding for finding, _places in _run(rule, model)]


def _run(rule: Rule, model: Model) -> list[tuple[Finding, list[Location]]]:
    """Findings, each with the places of what it involves (for suppressions)."""
    from ..extract.cpp.interfaces import use_workspace

    # the wire types a rule compares read the definitions of the model's own packages
    use_workspace({package.name: package.root for package in model.packages})
    try:
        query = compile(rule.query)
    except QueryError as err:
        return [(_error_finding(rule, err, None), [])]
    found: list[tuple[Finding, list[Location]]] = []
    for config, scope in _scopes(rule, query, model):
        evaluator = Evaluator(query.text, scope, STEPS, SAFETY_SECONDS)
        try:
            value = evaluator.run(query.tree)
        except QueryLimitError as err:
            found.append((_limit_finding(rule, err, config), []))
            continue
        except QueryError as err:
            found.append((_error_finding(rule, err, config), []))
            continue
        matches = value if isinstance(value, list) else [value]
        undecided: list[tuple[Any, list[Any]]] = []
        upstream: list[Finding] = []
        for match in matches:
            if match is None or match is False or match == ():
                continue
            unseen = _unseen(rule, match)
            if unseen:
                undecided.append((match, unseen))
                continue
            finding = _finding(rule, match, config, evaluator)
            places = [finding.location, *(location_of(e) for e in entities(match))]
            if _upstream_only(places):
                upstream.append(finding)
                continue
            found.append((finding, places))
        if undecided:
            found.append((_undecided_finding(rule, undecided, config), []))
        if upstream:
            found.append((_upstream_finding(rule, upstream, config), []))
    return found


def _upstream_only(places: list[Location]) -> bool:
    """Whether every place a match involves is in an installed package's own file, as its
    model keeps it (``models.launch_files.upstream``: a launch file of gazebo_ros the
    workspace includes, a parameter file it loads, a node it starts), none in the
    workspace."""
    files = [place.file for place in places if place.file]
    return bool(files) and all(is_upstream(file) for file in files)


def _upstream_finding(rule: Rule, upstream: list[Finding], config: Configuration | None
                      ) -> Finding:
    """One info for the matches of a rule about installed packages' own files only
    (mavros' apm_config.yaml setting a parameter of a plugin its own list turns off,
    gazebo_ros' client waiting for physics services): true of any system that includes
    those files, and not the workspace's to change; counted, the first one named."""
    files = list(dict.fromkeys(f.location.file.split("@")[0] for f in upstream
                               if f.location.file))
    return Finding(rule.id + UPSTREAM, "info", f"{rule.title}: in installed packages",
                   f"{len(upstream)} finding(s) about installed packages' own launch and "
                   f"parameter files not reported (first: {upstream[0].message}): all they "
                   f"involve is in files of {', '.join(files)} that the workspace includes "
                   "but does not write", config.name if config else None,
                   upstream[0].entities, upstream[0].location)


def _unseen(rule: Rule, match: Any) -> list[Any]:
    if rule.undecided_by is None or not isinstance(match, dict):
        return []
    nodes = match.get(rule.undecided_by)
    return list(nodes) if isinstance(nodes, list | tuple) else []


UNDECIDED_NAMED = 5  # nodes named in an undecided info (the ones that could be most)


def _ranked(undecided: list[tuple[Any, list[Any]]]) -> tuple[list[Any], dict[str, int]]:
    """The items of the matches' lists, each once by name, the most often named first,
    and how many matches name each."""
    # counted by name: two instances of one name (each under its own launch condition)
    # are one name that could be the missing side, counted once per match
    counts: dict[str, int] = {}
    first_of: dict[str, Any] = {}
    for _match, items in undecided:
        for name in dict.fromkeys(label(n).removeprefix("node ") for n in items):
            counts[name] = counts.get(name, 0) + 1
        for item in items:
            first_of.setdefault(label(item).removeprefix("node "), item)
    names = sorted(counts, key=lambda n: (-counts[n], n))
    return [first_of[n] for n in names], counts


def _named(ranked: list[Any], counts: dict[str, int]) -> str:
    names = [label(item).removeprefix("node ") for item in ranked]
    more = f" and {len(names) - UNDECIDED_NAMED} more" if len(names) > UNDECIDED_NAMED \
        else ""
    return ", ".join(f"{n} ({counts[n]})" for n in names[:UNDECIDED_NAMED]) + more


UNDECIDED_CONDITIONS = ("what they rest on exists only under a condition not decided for "
                        "this configuration (its value is not known statically), so they "
                        "may not hold")


def _undecided_finding(rule: Rule, undecided: list[tuple[Any, list[Any]]],
                       config: Configuration | None) -> Finding:
    """One info for the matches of a rule that it cannot decide: how many, which nodes
    could be the missing side (of partial or unknown interface, ...) and under which
    conditions not decided what they rest on exists (``undecided()``'s)."""
    ranked, counts = _ranked(undecided)
    nodes = [item for item in ranked if not isinstance(item, Condition)]
    conditions = [item for item in ranked if isinstance(item, Condition)]
    first = ("; ".join(label(e) for e in entities(undecided[0][0])[:1])
             or "; ".join(str(plain(p)) for p in placed(undecided[0][0])[:1])
             or label(undecided[0][1][0]))
    why = rule.undecided_why or (
        "these could be the missing side unseen (nodes of partial or unknown interface, "
        "names with '?', dynamic_reconfigure servers, launch parameters not known "
        "statically, nodes started beside a launch file that starts none)")
    reasons = ([f"{why}: {_named(nodes, counts)}"] if nodes else []) + (
        [f"{UNDECIDED_CONDITIONS}: {_named(conditions, counts)}"] if conditions else [])
    where = best_location(entities(undecided[0][0]))
    if not where.file:
        where = place_of(undecided[0][0])
    message = (f"{len(undecided)} possible finding(s) not reported (first: {first}): "
               f"{'; '.join(reasons)}")
    # what the first matches under a condition name (a type mismatch's two links)
    conditional = [e for match, items in undecided
                   if any(isinstance(i, Condition) for i in items)
                   for e in entities(match)][:UNDECIDED_NAMED]
    return Finding(rule.id + UNDECIDED, "info", f"{rule.title}: not decided",
                   message, config.name if config else None,
                   entity_ids([*nodes[:UNDECIDED_NAMED], *conditional]), where)


def _limit_finding(rule: Rule, err: QueryError, config: Configuration | None) -> Finding:
    """A rule that hit a limit: said as such, with the rule's findings unknown here; a
    warning, so that ``--fail-on error`` does not fail on it alone."""
    first = str(err).splitlines()[0]
    return Finding(QUERY_LIMIT, "warning", f"Query {rule.id} stopped at a limit",
                   f"{rule.origin}: {first}; its findings in this configuration are not "
                   "known", config.name if config else None, (), NOWHERE)


def _error_finding(rule: Rule, err: QueryError, config: Configuration | None) -> Finding:
    return Finding(QUERY_ERROR, "error", f"Query {rule.id} failed",
                   f"{rule.origin}: {err}", config.name if config else None, (), NOWHERE)


def run_catalogue(model: Model, project: Any = None,
                  catalogue: list[Rule] | None = None,
                  seconds: dict[str, float] | None = None) -> list[Finding]:
    """Every rule's findings, suppressions applied, sorted by severity then place;
    ``seconds`` gets each rule's time (over every configuration)."""
    from .. import runcache

    rules = list(load_catalogue() if catalogue is None else catalogue)
    if project is not None:
        rules.extend(project_rules(project))
    roots = list(getattr(project, "workspace", None) or ())
    # the findings of a model a cached run gave (or read back) are kept with it
    return runcache.findings(model, repr((rules, roots)),
                             lambda: _run_catalogue(model, rules, roots, seconds))


def _run_catalogue(model: Model, rules: list[Rule], roots: list[str],
                   seconds: dict[str, float] | None) -> list[Finding]:
    suppressions = Suppressions(roots)
    found: list[Finding] = []
    for rule in rules:
        start = time.perf_counter()
        for finding, places in _run(rule, model):
            if suppressions.applies(rule.id, places):
                continue
            found.append(finding)
        if seconds is not None:
            seconds[rule.id] = seconds.get(rule.id, 0.0) + time.perf_counter() - start
    found = merge(found)
    found.sort(key=lambda f: (-SEVERITY_RANK[f.severity], f.rule, f.configuration or "",
                              f.location.file or "", f.location.line))
    return found


def merge(findings: Iterable[Finding]) -> list[Finding]:
    """One problem, one finding: matches that say the same thing about the same entities
    are one finding, wherever they are found: at two call sites (a node subscribing to
    one topic twice; the second place is in ``also``) or in several configurations
    (``configurations`` lists them). Instances that share a name (``node:/requester``,
    ``node:/requester#2``: one executable started four times) count as the same entity
    when the match says the same thing at the same place about each: one finding that
    involves them all."""
    merged: dict[tuple[Any, ...], Finding] = {}
    # the same words at the same place about instances of one name -> the finding's key
    alias: dict[tuple[Any, ...], tuple[Any, ...]] = {}
    for finding in findings:
        said = (finding.rule, finding.severity, finding.title, finding.message)
        key = (*said, finding.entities)
        loose = (*said, tuple(REPEAT.sub("", e) for e in finding.entities),
                 finding.location)
        if key not in merged and loose in alias:
            key = alias[loose]
        alias.setdefault(loose, key)
        known = merged.get(key)
        if known is None:
            merged[key] = finding
            continue
        configs = tuple(dict.fromkeys((*known.configurations, *finding.configurations)))
        places = tuple(p for p in dict.fromkeys((*known.also, finding.location,
                                                 *finding.also))
                       if p != known.location)
        merged[key] = replace(known, configurations=configs, also=places,
                              entities=tuple(dict.fromkeys((*known.entities,
                                                            *finding.entities))))
    return list(merged.values())



def explain(rule: Rule) -> str:
    return f"{rule.id} ({rule.severity}): {rule.title}\n\n{rule.description.strip()}\n\n" \
           f"Query:\n{rule.query.strip()}\n"


__all__ = ["ABSORBED_CODES", "Rule", "absorbed", "explain", "load_catalogue", "location_of",
           "merge", "project_rules", "run_catalogue", "run_rule"]
