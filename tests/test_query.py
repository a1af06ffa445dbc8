"""The query language's safety and the planner: escapes fail cleanly in bounded time,
the model is never changed, and hash joins give what nested loops give."""

from __future__ import annotations

import copy
import time

import pytest
import yaml
from conftest import ROOT

from haros_arch import query
from haros_arch.model.load import from_data
from haros_arch.query.results import plain


@pytest.fixture
def model():
    return from_data(yaml.safe_load((ROOT / "fixtures/queries/paper.yaml").read_text()))


def big_model(links: int):
    """``links`` links: half publishers, half subscribers, on links/4 topics."""
    topics = max(1, links // 4)
    data = {"configurations": [{"name": "c", "links": [
        {"kind": "publish" if i % 2 == 0 else "subscribe", "node": f"/n{i % 97}",
         "name": f"/t{(i // 2) % topics}",
         "type": "std_msgs/String" if i % 10 else "std_msgs/Int32"}
        for i in range(links)]}]}
    return from_data(data)


ESCAPES = [
    ("len.__self__", query.QuerySyntaxError),
    ("configs[len.__self__]", query.QuerySyntaxError),
    ("configs[self.__class__.__mro__]", query.QuerySyntaxError),
    ("configs[self._sa_instance_state]", query.QuerySyntaxError),
    ("configs[getattr(self, '__class__')]", query.QueryNameError),
    ("configs[__import__('os').system('true')]", query.QuerySyntaxError),
    ("configs[open('/tmp/haros-arch-escape', 'w')]", query.QueryNameError),
    ("configs[eval('1')]", query.QueryNameError),
    ("configs[self.name.format(self)]", query.QueryNameError),
    ("configs[len.name]", query.QueryNameError),
    ("configs[self.nodes.append(1)]", query.QueryNameError),
    ("configs/nodes[self.links.clear()]", query.QueryNameError),
    ("configs/nodes[self.location.__setattr__('line', 0)]", query.QuerySyntaxError),
    ("configs/nodes[self.name.join(['a'])]", query.QueryNameError),
]


@pytest.mark.parametrize(("text", "error"), ESCAPES)
def test_escape_attempts_fail_with_a_clear_error(model, text, error, tmp_path):
    before = copy.deepcopy(plain(query.search("configs/links", query.model_scope(model))))
    with pytest.raises(error) as caught:
        query.compile(text).run(query.model_scope(model))
    assert "^" in str(caught.value)
    assert plain(query.search("configs/links", query.model_scope(model))) == before
    assert not (tmp_path / "haros-arch-escape").exists()


def test_results_hold_only_model_values_and_plain_data(model):
    (value,) = query.search("return len", query.model_scope(model))
    # a whitelisted function is an opaque value: it has no fields to climb
    with pytest.raises(query.QueryNameError):
        query.search("for f in <configs> let g = len return g.impl",
                     query.model_scope(model))
    assert repr(value) == "<function len>"


def test_queries_do_not_change_the_model(model):
    snapshot = plain([model.configs[0].nodes, model.configs[0].links,
                      [n.remaps for n in model.configs[0].nodes]])
    for text in ("configs/nodes[self.remaps]", "configs/args",
                 "for n in <configs/nodes> let r = n.remaps return r",
                 "configs/nodes[self.name.split('/')]"):
        query.search(text, query.model_scope(model))
    assert plain([model.configs[0].nodes, model.configs[0].links,
                  [n.remaps for n in model.configs[0].nodes]]) == snapshot
    assert not any(hasattr(n, "_objquery__i") for n in model.configs[0].nodes)


def test_cpu_bomb_hits_the_step_budget_quickly():
    big = big_model(2000)
    text = "for a in <configs/links>, b in <configs/links>, c in <configs/links> return a"
    start = time.monotonic()
    with pytest.raises(query.QueryLimitError) as caught:
        query.compile(text).run(query.model_scope(big), max_steps=200_000)
    assert "steps" in str(caught.value)
    assert time.monotonic() - start < 30  # bounded; the budget, not the clock, stops it


def test_time_limit_stops_a_long_query():
    big = big_model(2000)
    text = "for a in <configs/links>, b in <configs/links> where a.name != b.name return a"
    with pytest.raises(query.QueryLimitError) as caught:
        query.compile(text).run(query.model_scope(big), max_seconds=0.05)
    assert "longer than" in str(caught.value)


def test_memory_bombs_are_refused(model):
    grow = "'x'" + " + 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx'" * 10
    assert query.search(f"return len({grow})", query.model_scope(model)) == [321]
    with pytest.raises(query.QueryTypeError):  # no string repetition
        query.search("return 'x' * 100000000", query.model_scope(model))
    with pytest.raises(query.QueryLimitError):  # no unbounded numbers
        query.search("return " + " * ".join(["99999999999999999999"] * 300),
                     query.model_scope(model))
    with pytest.raises(query.QueryLimitError):  # query text size
        query.compile("configs" + "/nodes" * 5000)


def test_runaway_nesting_is_refused_before_it_runs():
    for text in ("configs[" + "(" * 500 + "1" + ")" * 500 + "]",
                 "return " + " + ".join(["1"] * 3000),
                 "return " + "-" * 2000 + "1"):
        with pytest.raises(query.QueryError) as caught:
            query.compile(text)
        assert isinstance(caught.value, query.QueryLimitError | query.QuerySyntaxError)


def test_syntax_errors_show_the_query_with_a_caret_under_the_problem():
    with pytest.raises(query.QuerySyntaxError) as caught:
        query.compile("for p in <nodes/publishers>\nwhere p.type = 'x'\nreturn p")
    lines = str(caught.value).splitlines()
    assert lines[0].startswith("query syntax error at line 2, column 14: unexpected '='")
    assert lines[1].strip() == "where p.type = 'x'"
    assert lines[2].index("^") == lines[1].index("=")


@pytest.mark.parametrize("links", [40, 400])
def test_hash_join_gives_what_nested_loops_give(links):
    big = big_model(links)
    scope = query.model_scope(big)
    joined = ("for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
              "where p.topic_name == s.topic_name and p.type != s.type return p, s")
    # the same condition hidden from the planner: no '==' conjunct to join on
    looped = ("for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
              "where not (p.topic_name != s.topic_name) and p.type != s.type return p, s")
    assert plain(query.search(joined, scope)) == plain(query.search(looped, scope))
    assert query.search(joined, scope)  # the model has mismatches to find


def test_planner_joins_and_pushes_filters_down():
    from haros_arch.query.planner import plan

    tree = query.compile("for p in <a>, s in <b> let x = <c> where p.k == 1 and "
                         "s.t == p.t and len(x) > 0 and s.u return p").tree
    the_plan = plan(tree)  # type: ignore[arg-type]
    first, second = the_plan.levels
    assert [type(f).__name__ for f in first.filters] == ["Compare"]
    assert second.join is not None and second.probe is not None
    assert len(second.filters) == 1 and len(the_plan.residual) == 1


def test_the_type_mismatch_query_is_fast_on_10000_links():
    big = big_model(10_000)
    text = ("for p in <configs/nodes/publishers>, s in <configs/nodes/subscribers> "
            "where p.topic_name == s.topic_name and p.type != s.type return p, s")
    compiled = query.compile(text)
    # a tight budget proves the join: nested loops would need 25,000,000 bindings
    assert compiled.run(query.model_scope(big), max_steps=200_000)


def test_a_sub_expression_without_bound_variables_is_evaluated_once():
    big = big_model(4000)
    # the inner path reads no variable of the outer filter: filtered once, not 4000 times
    text = "configs/links[len(<configs/links[self.type == 'std_msgs/Int32']>) > 0]"
    compiled = query.compile(text)
    assert len(compiled.run(query.model_scope(big), max_steps=100_000)) == 4000
    # one that reads the outer 'self' is evaluated per item, and still right
    correlated = ("configs/links[some q in <configs/links[self.type == 'std_msgs/Int32']> "
                  "satisfies (q.name == self.name)]")
    small = big_model(400)
    names = {link.name for link in small.configurations[0].links
             if link.type == "std_msgs/Int32"}
    found = query.compile(correlated).run(query.model_scope(small))
    assert {link.name for link in found} == names
    assert all(link.name in names for link in found)


FILTER_SHAPES = [
    # (a filter whose first conjuncts read only self, the same with them after one that
    # reads p: checked item by item, as written)
    ("self.kind == 'subscribe' and self.type == p.type and self.topic_name != p.topic_name",
     "self.type == p.type and self.kind == 'subscribe' and self.topic_name != p.topic_name"),
    ("self.kind == 'subscribe' and p.type == self.type",
     "p.type == self.type and self.kind == 'subscribe'"),
    # an equality whose sides are not strings: compared item by item
    ("self.kind == 'subscribe' and len(self.topic_name) == len(p.topic_name)",
     "len(self.topic_name) == len(p.topic_name) and self.kind == 'subscribe'"),
    ("self.kind == 'subscribe' and self.type == 3",
     "self.type == 3 and self.kind == 'subscribe'"),
    # no equality after them
    ("self.kind == 'subscribe' and self.type != p.type",
     "self.type != p.type and self.kind == 'subscribe'"),
]


@pytest.mark.parametrize(("split", "as_written"), FILTER_SHAPES)
def test_a_filter_over_a_context_list_keeps_what_checking_each_item_keeps(split, as_written):
    scope = query.config_scope(big_model(400).configurations[0])
    template = ("for p in <links[self.kind == 'publish' and self.node.name < '/n20']> "
                "return p, <links[{}]>")
    fast = plain(query.search(template.format(split), scope))
    slow = plain(query.search(template.format(as_written), scope))
    assert fast == slow
    assert any(found for _, found in fast) or "3" in split


def test_a_filter_over_a_context_list_checks_its_conjuncts_over_self_once():
    data = {"configurations": [{"name": "c", "links": [
        {"kind": "publish" if i % 2 == 0 else "subscribe", "node": f"/n{i % 97}",
         "name": f"/t{i // 2}", "type": f"pkg/T{(i // 2) % 200}"} for i in range(8000)]}]}
    scope = query.config_scope(from_data(data).configurations[0])
    # 4,000 publishers, each asking for the subscribers of its type: the filter's first
    # conjunct reads only self (checked once over the 8,000 links), the next compares
    # self's type with p's (looked up by the string): written the other way round it
    # needs 32,000,000 steps
    text = ("for p in <links[self.kind == 'publish']> "
            "let same = <links[self.kind == 'subscribe' and self.type == p.type]> "
            "return len(same)")
    counts = query.compile(text).run(scope, max_steps=400_000)
    assert counts == [20] * 4000
    reordered = text.replace("self.kind == 'subscribe' and self.type == p.type",
                             "self.type == p.type and self.kind == 'subscribe'")
    with pytest.raises(query.QueryLimitError):
        query.compile(reordered).run(scope, max_steps=400_000)


def test_similar_to_finds_what_comparing_every_pair_finds():
    import random

    from haros_arch.query.absence import similar_to, spelling
    from haros_arch.query.functions import edit_distance

    rng = random.Random(7)
    words = ["".join(rng.choice("aB_") for _ in range(rng.randint(0, 9))) for _ in range(300)]
    words.append("x" * 70)  # too long to index: compared one by one
    for word in [*words[:60], "x" * 69]:
        found = similar_to(lambda _n: None, word, words)
        # by name, so that the names a finding lists are in one order in every
        # configuration
        expected = sorted(w for w in words if edit_distance(lambda _n: None, word, w) <= 2
                          or spelling(w) == spelling(word))
        assert found == expected, word


def test_similar_to_takes_the_same_words_spelt_another_way():
    """grid_map_pcl's launch file sets ``configFilePath_``; its node reads
    ``config_file_path``: five edits apart, the same words."""
    from haros_arch.query.absence import similar_to

    names = ["config_file_path", "folder_path", "config-file-path", "configuration"]
    assert similar_to(lambda _n: None, "configFilePath_", names) == [
        "config-file-path", "config_file_path"]


def test_unknown_users_takes_readers_alone_as_its_side(model):
    # 'setters' was taken and meant no side at all (a read with '?' may stand for a
    # declaration, which sets): no rule used it, and it is refused as any other word
    scope = query.model_scope(model)
    text = "for c in configs, t in c.topics return len(unknown_users(c, t{side}))"
    assert query.search(text.format(side=", 'readers'"), scope) == query.search(
        text.format(side=""), scope) == [2, 2, 2]
    for side in ("'setters'", "'writers'"):
        with pytest.raises(query.QueryTypeError, match="can only be 'readers'"):
            query.search(text.format(side=", " + side), scope)


def test_similar_to_takes_a_nested_key_as_one_name_of_the_same_words():
    """YOLOX-ROS' launch file sets ``onnxruntime/use_cuda`` (a key nested in a
    namespace); its node declares ``onnxruntime_use_cuda``. The last segments alone
    (``use_cuda``) are far apart; the last two, spelt as words, are the same. ROS 2's
    dotted ``onnxruntime.use_cuda`` is the same words too."""
    from haros_arch.model.runtime import Parameter
    from haros_arch.query.absence import similar_to

    read = [Parameter(name=n) for n in ("/yolox/onnxruntime_use_cuda", "/yolox/model_path",
                                        "/yolox/onnxruntime.use_cuda", "/yolox/use_gpu")]
    found = similar_to(lambda _n: None, Parameter(name="/yolox/onnxruntime/use_cuda"), read)
    assert [p.name for p in found] == ["/yolox/onnxruntime.use_cuda",
                                       "/yolox/onnxruntime_use_cuda"]
    # and the other way round: the flat key set, the nested one read
    nested = [Parameter(name="/yolox/onnxruntime/use_cuda"), Parameter(name="/yolox/x/y")]
    found = similar_to(lambda _n: None, Parameter(name="/yolox/onnxruntime_use_cuda"), nested)
    assert [p.name for p in found] == ["/yolox/onnxruntime/use_cuda"]
