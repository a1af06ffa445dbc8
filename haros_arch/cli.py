"""The ``haros-arch`` command line: parse arguments, call the library, pick a reporter.

Exit codes: 0 clean, 1 diagnostics or findings at or above ``--fail-on``, 2 unusable
invocation (bad project file, missing workspace), 3 an internal error (a bug of ours),
130 stopped by Ctrl-C, 143 by SIGTERM (``processes.stop_signals``).
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from rich.console import Console
from rich.markup import escape

from . import __version__
from .model.diagnostic import SEVERITY_RANK
from .processes import stop_signals

# the rest is imported where a command needs it: ``--help`` and ``explain`` start fast
if TYPE_CHECKING:
    from .api import Analysis
    from .launch.model import LaunchModel
    from .pipeline import Options
    from .workspace import Workspace

EXIT_OK, EXIT_FINDINGS, EXIT_USAGE, EXIT_INTERNAL = 0, 1, 2, 3



def make_console(**options: Any) -> Console:
    """A console for our output: lines not wrapped, and no ``:name:`` emoji codes (a
    reason's ``view_controller.cpp:100:`` is a file and line, not a hundred-points
    sign)."""
    return Console(soft_wrap=True, emoji=False, **options)

def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="haros-arch",
        description="Recover and check the ROS Computation Graph of a workspace, statically.")
    parser.add_argument("--version", action="version", version=f"haros-arch {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)

    extract = sub.add_parser("extract", help="write the JSON model of a project")
    extract.add_argument("project", help=PROJECT_HELP)
    extract.add_argument("-o", "--output", help="write the JSON here (default: stdout)")
    extract.add_argument("-q", "--quiet", action="store_true", help="no summary")
    extract.add_argument("-v", "--verbose", action="store_true",
                         help="list every node instance and resource (default: counts per "
                              "kind and the nodes whose interface is not fully known) and "
                              "info-level diagnostics one by one (default: counted per code)")
    _run_options(extract)

    check = sub.add_parser("check", help="run the query catalogue and report findings and "
                           "diagnostics; exit 1 at --fail-on or above")
    check.add_argument("project", help=PROJECT_HELP)
    check.add_argument("--format", choices=("text", "json", "sarif", "junit"), default="text")
    check.add_argument("--fail-on", choices=(*SEVERITY_RANK, "never"), default="error")
    check.add_argument("-o", "--output", help="write the report here (default: stdout)")
    check.add_argument("-v", "--verbose", action="store_true",
                       help="list every finding of a rule (default: the first few) and "
                            "info-level diagnostics one by one (default: counted per code)")
    _run_options(check)

    query = sub.add_parser("query", help="evaluate a query and print its matches")
    query.add_argument("project", nargs="?", help=PROJECT_HELP)
    query.add_argument("expression", help="the query (pyflwor path or FLWR syntax)")
    query.add_argument("--model", help="query this saved JSON model instead of extracting")
    query.add_argument("--config", help="run in this configuration's scope")
    query.add_argument("--format", choices=("text", "json"), default="text")
    _choice_options(query)

    capture = sub.add_parser("capture", help="read a running system's graph: a ROS 1 master "
                                             "(XML-RPC), ROS 2 DDS discovery, or a bag")
    capture.add_argument("--master", default=os.environ.get("ROS_MASTER_URI",
                                                            "http://localhost:11311"))
    source = capture.add_mutually_exclusive_group()
    source.add_argument("--ros2", action="store_true",
                        help="join the DDS domain and read ROS 2 discovery (needs the "
                             "'live' extra)")
    source.add_argument("--bag", metavar="FILE",
                        help="read a recorded ROS 1 .bag or ROS 2 bag (folder, .db3 or "
                             ".mcap; needs the 'live' extra)")
    capture.add_argument("--domain", type=int, default=_domain_id(),
                         help="DDS domain id for --ros2 (default: $ROS_DOMAIN_ID or 0)")
    capture.add_argument("--seconds", type=float, default=3.0,
                         help="how long --ros2 listens (default 3)")
    capture.add_argument("-o", "--output", help="write the JSON here (default: stdout)")

    compare = sub.add_parser("compare", help="precision and recall of a model against a "
                                             "capture of the running system")
    compare.add_argument("model", help="JSON model from 'haros-arch extract'")
    compare.add_argument("live", help="JSON from 'haros-arch capture'")
    compare.add_argument("--config", help="configuration name (default: the first)")
    compare.add_argument("--format", choices=("text", "json"), default="text")
    compare.add_argument("--both", action="store_true",
                         help="also list what is both in the model and live")

    report = sub.add_parser("report", help="write the interactive HTML report (one file)")
    report.add_argument("project", nargs="?", help=PROJECT_HELP)
    report.add_argument("--model", help="render this saved JSON model instead of extracting")
    report.add_argument("--workspace", help="folder the model's file paths are relative to")
    report.add_argument("-o", "--output", required=True, help="the HTML file to write")
    report.add_argument("--live", metavar="LIVE",
                        help="show this capture ('haros-arch capture') beside each graph")
    _run_options(report)

    launch = sub.add_parser("launch", help="nodes and parameters a ROS 1 or ROS 2 launch "
                            "file would start (like roslaunch --nodes --dump-params)")
    launch.add_argument("file", nargs="+", metavar="FILE", help="a path, or PKG PATH/IN/PKG")
    launch.add_argument("--arg", action="append", default=[], metavar="NAME:=VALUE")
    launch.add_argument("--workspace", default=".", help="workspace folder (default: .)")
    launch.add_argument("--format", choices=("text", "json", "xml", "yaml", "python"),
                        default="text", help="text or json; with --flatten: xml (default), "
                        "or yaml / python for a ROS 2 file")
    launch.add_argument("--flatten", action="store_true",
                        help="write one launch file with every include inlined and every "
                             "argument and decided condition applied (ROS 1: roslaunch "
                             "XML; ROS 2: XML, YAML or Python)")
    launch.add_argument("--tree", action="store_true",
                        help="show how the files make the nodes: includes with their "
                             "arguments, groups, remaps, conditions")

    models = sub.add_parser("models", help="interface models of packages without source")
    models_sub = models.add_subparsers(dest="models_command", required=True)
    build = models_sub.add_parser("build", help="run the extractor on the pinned sources "
                                  "of a list of packages and write their model files")
    build.add_argument("list", help="the list (YAML: repository, commit, distro, packages)")
    build.add_argument("-o", "--output", default="models",
                       help="write OUTPUT/<distro>/<package>.json (default: ./models)")
    build.add_argument("--sources", default="sources",
                       help="folder holding each entry's tree as <owner>+<name>@<commit12> "
                            "(scripts/models-fetch fills it; default: ./sources)")
    build.add_argument("--overrides", help="folder of <distro>/<package>.yaml override "
                                           "files (default: the shipped ones)")
    build.add_argument("--only", action="append", default=[], metavar="PACKAGE",
                       help="model only this package (repeatable)")
    build.add_argument("--jobs", type=int, metavar="N",
                       help="local worker processes (default: one per core)")
    build.add_argument("--scheduler", metavar="ADDRESS",
                       help="run on this Dask distributed scheduler (needs the 'dask' extra)")
    build.add_argument("--no-cache", action="store_true", help="parse every source again")

    defs = models_sub.add_parser(
        "interfaces", help="read the message, service and action definitions of the "
        "pinned interface packages and write the catalogue the C++ extraction uses")
    defs.add_argument("list", nargs="?", help="the list (default: the shipped "
                      "haros_arch/models/interfaces.yaml)")
    defs.add_argument("--sources", default="sources",
                      help="folder holding each entry's tree (scripts/models-fetch fills "
                           "it; default: ./sources)")
    defs.add_argument("-o", "--output", default="interfaces",
                      help="write OUTPUT/<distro>.json (default: ./interfaces)")

    metas = models_sub.add_parser(
        "metapackages", help="read the metapackages of the pinned trees of the models' "
        "lists and write the table of what each brings")
    metas.add_argument("lists", nargs="*", help="the lists (default: the shipped "
                       "sources.yaml and interfaces.yaml)")
    metas.add_argument("--sources", default="sources",
                       help="folder holding each entry's tree (default: ./sources)")
    metas.add_argument("-o", "--output", default="metapackages.json",
                       help="the table to write (default: ./metapackages.json)")

    diff = sub.add_parser("diff", help="what a change does to the architecture: two saved "
                          "models, or two git revisions (--rev BASE..HEAD)")
    diff.add_argument("sides", nargs="*", metavar="OLD NEW | PATH",
                      help="two saved models (extract -o); with --rev, the project file or "
                           "workspace folder relative to the repository root (default: .)")
    diff.add_argument("--rev", metavar="BASE..HEAD",
                      help="analyse both revisions from git objects (the working tree is "
                           "not touched)")
    diff.add_argument("--repo", default=".", help="the git repository (default: .)")
    diff.add_argument("--format", choices=("text", "json", "markdown"), default="text")
    diff.add_argument("--fail-on", choices=("new-error", "new-warning", "never"),
                      default="never", help="exit 1 when a new finding at or above this "
                                            "severity appears (default: never)")
    diff.add_argument("-o", "--output", help="write the diff here (default: stdout)")
    _run_options(diff)

    init = sub.add_parser("init", help="write a project file for a workspace or launch "
                          "file: the configurations check would choose, to edit")
    init.add_argument("path", help="workspace or package folder, or a launch file")
    init.add_argument("-o", "--output", help="write it here (default: stdout)")
    _choice_options(init)

    explain = sub.add_parser("explain", help="explain a diagnostic code or a rule id (or "
                             "list them all)")
    explain.add_argument("code", nargs="?")
    return parser


PROJECT_HELP = ("project file (YAML), or a workspace / package folder or a launch file "
                "(configurations chosen as 'init' would)")


def _choice_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--launch", action="append", default=[], metavar="FILE",
                        help="without a project file: analyse this launch file as a "
                             "configuration (repeatable) instead of choosing")
    parser.add_argument("--arg", action="append", default=[], metavar="NAME:=VALUE",
                        help="a launch argument for every configuration (repeatable)")


def _run_options(parser: argparse.ArgumentParser) -> None:
    _choice_options(parser)
    parser.add_argument("--no-cache", action="store_true",
                        help="parse every source again (a cold run); the cache is not read "
                             "or written")
    parser.add_argument("--jobs", type=int, metavar="N",
                        help="parse C++ sources in N worker processes (default: one per core)")


def _options(args: argparse.Namespace) -> Options:
    from .pipeline import Options

    jobs = getattr(args, "jobs", None)
    return Options(cache_dir=None if getattr(args, "no_cache", False) else Options.cache_dir,
                   jobs=max(1, jobs) if jobs is not None else None)


def _analyse(path: str, console: Console, options: Options | None = None
             ) -> Analysis | None:
    """The analysis of ``path``, its notes and errors printed on ``console``."""
    from .api import analyse_path
    from .project import ProjectError

    try:
        analysis = analyse_path(path, options)
    except ProjectError as err:
        console.print(f"haros-arch: {escape(str(err))}", highlight=False)
        return None
    for note in analysis.notes:
        console.print(f"haros-arch: {escape(note)}", highlight=False)
    for spec in analysis.project.configurations if analysis.notes else ():
        console.print(f"  configuration {escape(spec.name)}: {escape(', '.join(spec.launch))}",
                      highlight=False)
    if analysis.model is None:
        console.print(f"haros-arch: {escape(analysis.error or path)}", highlight=False)
        return None
    return analysis


_RECORDING = [True]  # this command may write to the cache folder (not ``--no-cache``)


def _wrote(output: str) -> None:
    """An output file written: no input of a later run while it is as written (said in
    the cache folder, which a ``--no-cache`` command leaves alone)."""
    if _RECORDING[0]:
        from .runcache import record_output

        record_output(output)


def _write(text: str, output: str | None, result: bool = True) -> None:
    """``text`` into ``output`` (else stdout); ``result``: a command's result, no input
    of a later run (``_wrote``), as a project file ``init`` writes is."""
    if output:
        with open(output, "w", encoding="utf-8") as handle:
            handle.write(text)
        if result:
            _wrote(output)
    else:
        sys.stdout.write(text)


def cmd_extract(args: argparse.Namespace, out: Console, err: Console) -> int:
    from . import runcache
    from .report.text import summary_lines

    analysis = _analyse(args.project, err, _options(args))
    if analysis is None or analysis.model is None:
        return EXIT_USAGE
    from .report.json import document_text

    model = analysis.model
    _write(document_text(model, analysis.project), args.output)
    if not args.quiet:
        summary = out if args.output else err
        for line in runcache.summary(model, args.verbose,
                                     lambda: summary_lines(model, args.verbose)):
            summary.print(line, highlight=False)
        if args.output:
            summary.print(f"wrote {args.output}", highlight=False)
    return EXIT_OK


def cmd_check(args: argparse.Namespace, out: Console, err: Console) -> int:
    """Diagnostics and catalogue findings, in text, JSON, SARIF or JUnit."""
    from .query.command import check

    analysis = _analyse(args.project, err, _options(args))
    if analysis is None or analysis.model is None:
        return EXIT_USAGE
    checked = check(analysis.model, analysis.project)
    fmt = getattr(args, "format", "text")
    verbose = getattr(args, "verbose", False)
    if fmt == "json":
        from .report.json import check_json

        _write(check_json(checked), args.output)
    elif fmt == "sarif":
        from .report.sarif import dumps as sarif

        rules = {r.id: (r.title, r.description.strip()) for r in checked.rules}
        workspace = analysis.project.workspace
        _write(sarif(checked.findings, checked.diagnostics, rules,
                     workspace[0] if workspace else None), args.output)
    elif fmt == "junit":
        from .report.junit import to_junit

        _write(to_junit(checked.findings, checked.diagnostics,
                        [r.id for r in checked.rules]), args.output)
    else:
        from .report.results import print_check, print_seconds

        console, handle = out, None
        if args.output:
            handle = open(args.output, "w", encoding="utf-8")  # noqa: SIM115
            console = make_console(file=handle, no_color=True)
        try:
            print_check(checked, console, getattr(args, "verbose", True))
            if verbose:
                print_seconds(checked.seconds, console)
        finally:
            if handle:
                handle.close()
                _wrote(args.output)
    return checked.exit_code(args.fail_on)


def cmd_query(args: argparse.Namespace, out: Console, err: Console) -> int:
    """Evaluate one expression and print its matches with their locations."""
    from .query import QueryError, compile
    from .query.command import NoConfiguration, query

    try:
        compiled = compile(args.expression)
    except QueryError as error:
        err.print(escape(str(error)), highlight=False)
        return EXIT_USAGE
    if args.model:
        from .model.load import ModelDataError, from_data

        try:
            with open(args.model, encoding="utf-8") as handle:
                model = from_data(json.load(handle))
        except (OSError, ValueError, RecursionError, ModelDataError) as error:
            err.print(f"haros-arch: cannot read model {args.model}: {error}", highlight=False)
            return EXIT_USAGE
    elif args.project:
        analysis = _analyse(args.project, err)
        if analysis is None or analysis.model is None:
            return EXIT_USAGE
        model = analysis.model
    else:
        err.print("haros-arch: query needs a PROJECT file or --model FILE", highlight=False)
        return EXIT_USAGE
    try:
        matches = query(model, compiled, args.config)
    except NoConfiguration as error:
        err.print(f"haros-arch: {error}", highlight=False)
        return EXIT_USAGE
    except QueryError as error:
        err.print(escape(str(error)), highlight=False)
        return EXIT_USAGE
    if args.format == "json":
        from .report.json import matches_json

        out.print(matches_json(matches), highlight=False, markup=False, soft_wrap=True)
        return EXIT_OK
    from .report.results import print_matches

    print_matches(matches, out)
    return EXIT_OK


def cmd_explain(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .diagnostics import CATALOGUE
    from .query.catalogue import QUERY_LIMIT, UNDECIDED, UPSTREAM, load_catalogue

    rules = {rule.id: rule for rule in load_catalogue()}
    if args.code == QUERY_LIMIT:
        out.print(f"[bold]{QUERY_LIMIT}[/bold] (warning)\n  A rule used more than its step "
                  "budget in a configuration and was stopped; its findings there are not "
                  "known. It never fails --fail-on error by itself.", highlight=False)
        return EXIT_OK
    counted = {  # a rule's info that counts matches not reported one by one
        UNDECIDED: "that a node of partial or unknown interface (or one using a name not "
                   "known statically, or serving dynamic_reconfigure) could contradict, "
                   "counted in one finding per configuration with the nodes in the way; "
                   "they are not reported as findings.",
        UPSTREAM: "whose every place is in installed packages' own files (launch and "
                  "parameter files read from their models, the nodes those start), "
                  "counted in one finding per configuration: true of any system that "
                  "includes those files, and not the workspace's to change."}
    for suffix, what in counted.items():
        if args.code and args.code.endswith(suffix) and args.code[:-len(suffix)] in rules:
            base = args.code[:-len(suffix)]
            out.print(f"[bold]{escape(args.code)}[/bold] (info): the matches of "
                      f"{escape(base)} {what}", highlight=False)
            args.code = base
    if args.code and args.code not in CATALOGUE and args.code not in rules:
        err.print(f"haros-arch: {escape(args.code)} is neither a diagnostic code nor a "
                  "rule id ('haros-arch explain' lists them)", highlight=False)
        return EXIT_USAGE
    codes = [args.code] if args.code in CATALOGUE else [] if args.code else sorted(CATALOGUE)
    ids = [args.code] if args.code in rules else [] if args.code else sorted(rules)
    if not args.code:
        out.print("[bold]Diagnostic codes[/bold] (problems reading the workspace)",
                  highlight=False)
    for code in codes:
        entry = CATALOGUE[code]
        out.print(f"[bold]{code}[/bold] ({entry.severity})\n  {escape(entry.explanation)}",
                  highlight=False)
    if not args.code:
        out.print("\n[bold]Rules[/bold] (the query catalogue's findings)", highlight=False)
    for rule_id in ids:
        rule = rules[rule_id]
        out.print(f"[bold]{rule_id}[/bold] ({rule.severity}): {escape(rule.title)}\n  "
                  f"{escape(' '.join(rule.description.split()))}", highlight=False)
    return EXIT_OK


def cmd_init(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .autoproject import is_project_file, open_choice, project_text
    from .project import ProjectError

    try:
        choice = open_choice(args.path)
    except ProjectError as error:
        err.print(f"haros-arch: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    if is_project_file(args.path):
        err.print(f"haros-arch: {escape(args.path)} is already a project file",
                  highlight=False)
        return EXIT_USAGE
    for note in choice.notes:
        err.print(f"haros-arch: {escape(note)}", highlight=False)
    # the workspace is written relative to the file's folder (stdout: the current one)
    target = os.path.abspath(args.output or "haros-arch.yaml")
    choice.project.path = target
    _write(project_text(choice), args.output, result=False)
    if args.output:
        err.print(f"wrote {escape(args.output)}", highlight=False)
    return EXIT_OK


def cmd_diff(args: argparse.Namespace, out: Console, err: Console) -> int:
    from . import diff

    try:
        if args.rev:
            if len(args.sides) > 1:
                err.print("haros-arch: diff --rev takes at most one PATH", highlight=False)
                return EXIT_USAGE
            result, notes = diff.compare_revisions(
                args.rev, args.sides[0] if args.sides else ".", args.repo, _options(args))
            for note in notes:
                err.print(f"haros-arch: {escape(note)}", highlight=False)
        elif len(args.sides) == 2:
            (old, old_found), (new, new_found) = (diff.load_saved(p) for p in args.sides)
            result = diff.compare(old, new, old_found, new_found, *args.sides)
        else:
            err.print("haros-arch: diff takes OLD NEW (saved models) or --rev BASE..HEAD "
                      "[PATH]", highlight=False)
            return EXIT_USAGE
    except diff.DiffError as error:
        err.print(f"haros-arch: diff: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    if args.format == "text" and not args.output:
        diff.print_text(result, out)
    else:
        render = {"text": diff.to_text, "json": diff.to_json, "markdown": diff.to_markdown}
        _write(render[args.format](result), args.output)
    if args.output:
        err.print(escape(diff.summary(result)), highlight=False)
    return EXIT_FINDINGS if result.fails(args.fail_on) else EXIT_OK


def _domain_id() -> int:
    value = os.environ.get("ROS_DOMAIN_ID", "")
    return int(value) if value.isdigit() and len(value) < 4 else 0


def cmd_capture(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .live import CaptureError, capture, capture_bag, capture_ros2

    where = (args.bag if args.bag else f"DDS domain {args.domain}" if args.ros2
             else args.master)
    if args.ros2 and not 0 < args.seconds <= 600:
        err.print("haros-arch: --seconds must be over 0 and at most 600", highlight=False)
        return EXIT_USAGE
    try:
        data = (capture_bag(args.bag) if args.bag
                else capture_ros2(args.domain, args.seconds) if args.ros2
                else capture(args.master))
    except CaptureError as error:
        err.print(f"haros-arch: cannot capture from {escape(where)}: "
                  f"{escape(str(error))}", highlight=False)
        return EXIT_USAGE
    from .model.serialise import json_text
    _write(json_text(data, indent=2) + "\n", args.output)
    return EXIT_OK


def cmd_compare(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .live.compare import CompareError, compare

    try:
        with open(args.model, encoding="utf-8") as handle:
            model = json.load(handle)
        with open(args.live, encoding="utf-8") as handle:
            live = json.load(handle)
        result = compare(model, live, args.config)
    except (OSError, ValueError, KeyError, TypeError, AttributeError, RecursionError,
            CompareError) as error:
        err.print(f"haros-arch: cannot compare: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    if args.format == "json":
        from .model.serialise import json_text
        _write(json_text(result.to_data(), indent=2) + "\n", None)
        return EXIT_OK
    from .report.results import print_comparison

    print_comparison(result, out, both=args.both)
    return EXIT_OK


def cmd_report(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .autoproject import open_choice
    from .project import ProjectError
    from .viz import ReportError, write_report
    from .viz.command import model_data, project_findings, read_model, report_page, workspace_root
    from .viz.html import write_page

    if not args.project and not args.model:
        err.print("haros-arch: report needs a PROJECT file or --model FILE", highlight=False)
        return EXIT_USAGE
    try:
        # the cache folder's kept choice, as the analysis below takes it
        project = (open_choice(args.project, _options(args).cache_dir).project
                   if args.project else None)
        findings: list = []
        if args.model:
            data = read_model(args.model)
        else:
            analysis = _analyse(args.project, err, _options(args))
            if analysis is None or analysis.model is None:
                return EXIT_USAGE
            project = analysis.project
            findings = project_findings(analysis.model, project)
            if not args.live:  # an unchanged run's page is kept with it
                write_page(report_page(analysis.model, findings,
                                       workspace_root(project, args.workspace), project),
                           args.output)
                _wrote(args.output)
                out.print(f"wrote {args.output}", highlight=False)
                return EXIT_OK
            data = model_data(analysis.model)
        live = _live_comparison(data, args.live) if args.live else None
        write_report(data, findings, workspace_root(project, args.workspace), args.output,
                     live)
        _wrote(args.output)
    except (ProjectError, ReportError) as error:
        err.print(f"haros-arch: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    out.print(f"wrote {args.output}", highlight=False)
    return EXIT_OK


def _live_comparison(model: dict[str, Any], path: str) -> dict[str, Any]:
    """Each configuration of ``model`` compared with the capture in ``path``."""
    from .live.compare import CompareError, compare_all
    from .viz import ReportError

    try:
        with open(path, encoding="utf-8") as handle:
            return compare_all(model, json.load(handle))
    except (OSError, ValueError, KeyError, TypeError, AttributeError, RecursionError,
            CompareError) as error:
        raise ReportError(f"cannot compare with {path}: {error}") from None


def cmd_launch(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .launch import load as load_launch
    from .launch.ros1.dump import as_data, as_text
    from .report.text import print_diagnostics
    from .workspace import scan

    if not os.path.isdir(args.workspace) or len(args.file) > 2 or any(
            ":=" not in a for a in args.arg):
        err.print("haros-arch: launch needs FILE or PKG PATH, NAME:=VALUE arguments and "
                  "an existing --workspace", highlight=False)
        return EXIT_USAGE
    workspace = scan([args.workspace], dict(os.environ))
    path = args.file[0]
    if len(args.file) == 2:
        folder = workspace.find(args.file[0])
        if folder is None:
            err.print(f"haros-arch: package {args.file[0]} not found", highlight=False)
            return EXIT_USAGE
        path = os.path.join(folder, args.file[1])
    given = dict(a.split(":=", 1) for a in args.arg)
    model = load_launch(path, workspace, given, dict(os.environ))
    if args.flatten:
        return _flatten(path, workspace, model, args.format, out, err)
    if args.format not in ("text", "json"):
        err.print(f"haros-arch: --format {args.format} is for --flatten", highlight=False)
        return EXIT_USAGE
    if args.format == "json":
        from .model.serialise import json_text
        out.print(json_text(as_data(model), indent=2), highlight=False, markup=False)
    elif args.tree:
        from .launch.tree_view import as_rich

        if not out.is_terminal:  # a file or a pipe: whole lines, not cut at 80 columns
            out.width = 1_000
        out.print(as_rich(model.tree), highlight=False, crop=False)
        print_diagnostics(model.diagnostics, err)
    else:
        out.print(as_text(model), highlight=False, markup=False)
        print_diagnostics(model.diagnostics, err)
    return EXIT_OK


def _flatten(path: str, workspace: Workspace, model: LaunchModel, fmt: str, out: Console,
             err: Console) -> int:
    from .launch.dialect import ros_version
    from .launch.ros1.flatten import flatten as flatten_ros1
    from .launch.ros2.flatten import flatten as flatten_ros2
    from .report.text import print_diagnostics

    fmt = "xml" if fmt == "text" else fmt
    if ros_version(path, workspace) == 2 and fmt in ("xml", "yaml", "python"):
        text, notes = flatten_ros2(model, fmt)
    elif fmt == "xml":
        text, notes = flatten_ros1(model)
    else:
        err.print(f"haros-arch: --flatten writes a ROS 1 launch file as xml only, not "
                  f"{fmt}", highlight=False)
        return EXIT_USAGE
    out.print(text, highlight=False, markup=False, end="")
    for line in notes:
        err.print(f"note: {escape(line)}", highlight=False)
    print_diagnostics(model.diagnostics, err)
    return EXIT_OK


def cmd_models(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .models import generate

    if args.models_command == "interfaces":
        return _models_interfaces(args, out, err)
    if args.models_command == "metapackages":
        return _models_metapackages(args, out, err)

    try:
        entries = generate.read_list(args.list)
    except generate.ListError as error:
        err.print(f"haros-arch: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    if args.scheduler:
        try:
            import distributed  # noqa: F401
        except ImportError:
            err.print("haros-arch: --scheduler needs dask.distributed "
                      "(pip install 'haros-arch[dask]')", highlight=False)
            return EXIT_USAGE
    work = generate.tasks(entries, args.sources, args.overrides or generate.OVERRIDES,
                          args.only, None if args.no_cache else generate.AUTO_CACHE)
    outcomes = generate.run(work, jobs=args.jobs, scheduler=args.scheduler)
    generate.report(outcomes, lambda line: out.print(escape(line), highlight=False))
    written = generate.write(outcomes, args.output)
    out.print(f"wrote {len(written)} model files under {escape(args.output)}", highlight=False)
    return EXIT_OK if all(o.text is not None for o in outcomes) else EXIT_FINDINGS


def _models_interfaces(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .models import definitions, generate

    try:
        entries = generate.read_list(args.list or definitions.LIST)
        documents = definitions.collect(entries, args.sources)
    except (generate.ListError, definitions.MissingTree) as error:
        err.print(f"haros-arch: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    for path in definitions.write(documents, args.output):
        distro = os.path.basename(path)[: -len(".json")]
        count = len(documents[distro]["definitions"])  # type: ignore[arg-type]
        out.print(f"wrote {escape(path)}: {count} definitions", highlight=False)
    return EXIT_OK


def _models_metapackages(args: argparse.Namespace, out: Console, err: Console) -> int:
    from .models import generate, metapackages

    try:
        entries = [e for path in (args.lists or metapackages.LISTS)
                   for e in generate.read_list(path)]
    except generate.ListError as error:
        err.print(f"haros-arch: {escape(str(error))}", highlight=False)
        return EXIT_USAGE
    table = metapackages.collect(entries, args.sources)
    metapackages.write(table, args.output)
    found = table["metapackages"]
    assert isinstance(found, dict)
    for distro, metas in found.items():
        out.print(f"{distro}: {len(metas)} metapackages", highlight=False)
    out.print(f"wrote {escape(args.output)}", highlight=False)
    return EXIT_OK


# the commands whose ``--output`` is a file (``models``' is a folder it makes)
_FILE_OUTPUTS = frozenset({"extract", "check", "capture", "report", "diff", "init"})


def _output_refused(args: argparse.Namespace) -> str | None:
    """Why the file ``--output`` names cannot be written, else None; its folder is made
    when missing (``-o out/model.json`` in a fresh checkout, as CI writes it)."""
    output = getattr(args, "output", None)
    if args.command not in _FILE_OUTPUTS or not output:
        return None
    if os.path.isdir(output):
        return "it is a folder"
    folder = os.path.dirname(os.path.abspath(output))
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as error:
        return f"cannot make its folder {folder}: {error.strerror or error}"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"its folder {folder} is not writable"
    return None


def main(argv: Sequence[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    from .autoproject import select
    from .runcache import background

    if any(":=" not in a for a in getattr(args, "arg", [])) and args.command != "launch":
        print("haros-arch: --arg takes NAME:=VALUE", file=sys.stderr)
        return EXIT_USAGE
    if args.command != "launch":
        select(getattr(args, "launch", []),
               dict(a.split(":=", 1) for a in getattr(args, "arg", [])))
    _RECORDING[0] = not getattr(args, "no_cache", False)
    out = make_console()
    err = make_console(stderr=True)
    refused = _output_refused(args)
    if refused is not None:  # said before the run, not after minutes of it
        err.print(f"haros-arch: cannot write {escape(args.output)}: {escape(refused)}",
                  highlight=False)
        return EXIT_USAGE
    handlers = {"extract": cmd_extract, "check": cmd_check, "explain": cmd_explain,
                "capture": cmd_capture, "compare": cmd_compare, "report": cmd_report,
                "launch": cmd_launch, "query": cmd_query, "init": cmd_init,
                "models": cmd_models, "diff": cmd_diff}
    try:
        # stopped, the run still removes its temporary folders; a run's model is kept
        # in the cache while the command goes on (``runcache.background``)
        with stop_signals(), background():
            return handlers[args.command](args, out, err)
    except KeyboardInterrupt:
        return 130
    except Exception as error:  # a bug of ours: one clear line, no traceback
        err.print(f"haros-arch: internal error: {type(error).__name__}: "
                  f"{escape(str(error))} (please report it; set HAROS_ARCH_DEBUG=1 for "
                  "the traceback)", highlight=False)
        if os.environ.get("HAROS_ARCH_DEBUG"):
            raise
        return EXIT_INTERNAL


if __name__ == "__main__":
    sys.exit(main())
