"""haros_arch as a library: a path in, the model (and what was chosen) out.

The command line only parses arguments, calls these and ``haros_arch.query.command``,
and hands the results to a reporter in ``haros_arch.report``.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

from .autoproject import open_choice
from .model.model import Model
from .pipeline import Options, analyse
from .project import Project


@dataclass
class Analysis:
    """The project chosen for a path, notes on that choice (no project file) and the
    model; ``model`` is None and ``error`` says why when the workspace is missing."""

    project: Project
    notes: list[str] = field(default_factory=list)
    model: Model | None = None
    error: str | None = None


def analyse_path(path: str, options: Options | None = None) -> Analysis:
    """Analyse a project file, a workspace folder or a launch file (``open_choice``).
    A project file that cannot be read raises ProjectError."""
    from .runcache import one_snapshot

    options = options or Options()
    with one_snapshot():  # the choice and the run's key read one snapshot of the files
        choice = open_choice(path, options.cache_dir)
        project = choice.project
        missing = [w for w in project.workspace if not os.path.isdir(w)]
        if missing:
            return Analysis(project, list(choice.notes),
                            error=f"{path}: workspace folder {missing[0]} does not exist")
        return Analysis(project, list(choice.notes), analyse(project, options=options))
