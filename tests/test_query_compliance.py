"""The JSON compliance suite (jmespath style): given a model, a query gives this result or
this kind of error. ``tests/compliance/*.json``; HAROS_ARCH_CASE=<substring> narrows it.

Results are compared in plain form: node instances and resources by id, links as
"kind node name". A case with ``scope`` runs in that configuration's scope (HAROS's
``scope: configuration``); otherwise at the top level (``configs``, ``nodes``, ...).
"""

from __future__ import annotations

import collections
import collections.abc
import json

import pytest
import yaml
from conftest import ROOT, only_case

from haros_arch import query
from haros_arch.model.load import from_data
from haros_arch.query.results import plain

KINDS = {"syntax": query.QuerySyntaxError, "name": query.QueryNameError,
         "type": query.QueryTypeError, "limit": query.QueryLimitError}


def _cases() -> list:
    found = []
    for path in sorted((ROOT / "tests" / "compliance").glob("*.json")):
        suite = json.loads(path.read_text())
        for i, case in enumerate(suite["cases"]):
            ident = f"{path.stem}-{i}"
            if only_case() in (None, ident) or (only_case() or "") in case["query"]:
                found.append(pytest.param(suite["given"], case, id=ident))
    return found


_MODELS: dict[str, object] = {}


def model_of(given: str):
    if given not in _MODELS:
        _MODELS[given] = from_data(yaml.safe_load((ROOT / given).read_text()))
    return _MODELS[given]


def scope_for(model, case) -> dict:
    if "scope" in case:
        return query.config_scope(model.configuration(case["scope"]), model)
    return query.model_scope(model)


@pytest.mark.parametrize(("given", "case"), _cases())
def test_compliance(given, case):
    model = model_of(given)
    if "error" in case:
        with pytest.raises(KINDS[case["error"]]) as caught:
            query.compile(case["query"]).run(scope_for(model, case))
        assert "^" in str(caught.value)  # the caret under the problem
    else:
        assert plain(query.search(case["query"], scope_for(model, case))) == case["result"]


# ---- pyflwor-ext as a second opinion on harmless queries

ORACLE_QUERIES = [
    "configs/nodes[len(self.remaps) > 0]",
    "configs/topics[len(self.types) > 1]",
    "configs/nodes/publishers[self.queue_size == 1] | configs/nodes/subscribers",
    "configs/links - configs/links[self.kind == 'publish']",
    "for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
    "where p.topic_name == s.topic_name and p.type != s.type return p, s",
    "for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
    "where p.type == s.type return 'p': p.topic_name, 's': s.topic_name",
    "configs/topics[some l in <self/links> satisfies (l.queue_size == 0)]",
]


@pytest.fixture(scope="module")
def pyflwor():
    if not hasattr(collections, "MutableSet"):  # pyflwor-ext predates Python 3.10
        collections.MutableSet = collections.abc.MutableSet  # type: ignore[attr-defined]
    return pytest.importorskip("pyflwor")


@pytest.mark.parametrize("text", ORACLE_QUERIES)
def test_pyflwor_agrees_on_harmless_queries(pyflwor, text):
    ours = plain(query.search(text, query.model_scope(model_of("fixtures/queries/paper.yaml"))))
    # a fresh model: pyflwor writes attributes onto the objects it walks
    fresh = from_data(yaml.safe_load((ROOT / "fixtures/queries/paper.yaml").read_text()))
    theirs = pyflwor.execute(text, {"configs": fresh.configs, "len": len})
    assert ours == plain(list(theirs))
