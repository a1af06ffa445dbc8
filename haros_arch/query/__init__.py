"""Queries over the model: pyflwor's path and FLWR syntax, our parser, a safe interpreter.

    query = compile("topics[len(self.publishers) > 1]")
    matches = query.run(model_scope(model))          # or config_scope(config, model)

``run_catalogue(model, project)`` runs the shipped catalogue (``queries/``) and the
project's own queries and rules per configuration and returns ``Finding`` values.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..model.model import Model
from ..model.runtime import Configuration
from . import syntax
from .errors import QueryError, QueryLimitError, QueryNameError, QuerySyntaxError, QueryTypeError
from .functions import FUNCTIONS
from .interpreter import DEFAULT_SECONDS, DEFAULT_STEPS, Evaluator
from .parser import parse

__all__ = [
    "CONFIG_NAMES",
    "Query",
    "QueryError",
    "QueryLimitError",
    "QueryNameError",
    "QuerySyntaxError",
    "QueryTypeError",
    "compile",
    "config_scope",
    "model_scope",
    "run_catalogue",
    "search",
]

CONSTANTS: dict[str, Any] = {"True": True, "False": False, "None": None,
                             "true": True, "false": False}
# names only a configuration scope has; a query that uses them runs per configuration
CONFIG_NAMES = frozenset({"config", "c", "topics", "services", "actions", "parameters",
                          "links", "direct_links"})


def model_scope(model: Model) -> dict[str, Any]:
    """HAROS's top-level names: ``configs``, ``packages``, ``nodes`` (source), ``files``."""
    scope: dict[str, Any] = {**CONSTANTS, **FUNCTIONS}
    scope.update({"configs": model.configs, "packages": model.packages,
            "nodes": model.nodes, "files": model.files})
    return scope


def config_scope(config: Configuration, model: Model | None = None) -> dict[str, Any]:
    """HAROS's ``scope: configuration`` names; ``nodes`` are the node instances."""
    scope = model_scope(model) if model is not None else {**CONSTANTS, **FUNCTIONS}
    scope = dict(scope)
    scope.update({"config": config, "c": config, "nodes": config.nodes,
                  "topics": config.topics, "services": config.services,
                  "actions": config.actions, "parameters": config.parameters,
                  "links": config.links, "direct_links": config.direct_links})
    if model is None:
        scope["configs"] = [config]
    return scope


@dataclass(frozen=True)
class Query:
    """A parsed query; ``run`` evaluates it over a scope (a mapping of names)."""

    text: str
    tree: syntax.Expr

    @property
    def names(self) -> set[str]:
        return syntax.free_names(self.tree)

    @property
    def needs_configuration(self) -> bool:
        return bool(self.names & CONFIG_NAMES)

    def run(self, scope: dict[str, Any], max_steps: int = DEFAULT_STEPS,
            max_seconds: float = DEFAULT_SECONDS) -> list[Any]:
        """The matches: a path gives its items, a FLWR its returned values."""
        value = Evaluator(self.text, scope, max_steps, max_seconds).run(self.tree)
        return value if isinstance(value, list) else [value]


def compile(text: str) -> Query:
    """Parse ``text``; raises ``QuerySyntaxError`` / ``QueryLimitError`` with a caret."""
    return Query(text, parse(text))


def search(text: str, scope: dict[str, Any]) -> list[Any]:
    return compile(text).run(scope)


def run_catalogue(model: Model, project: Any = None) -> list[Any]:
    """Findings of the shipped catalogue and the project's queries, per configuration."""
    from .catalogue import run_catalogue as run

    return run(model, project)
