"""``std::async`` returns a future of what its function returns (``std::invoke``'s result:
a member function pointer on an object too), not always ``future<int>``: robocup-pkg's
path_finder stores ``std::async(std::launch::async, &Graph::search, m_graph, ...)`` of a
void method in a ``std::future<void>``, a C++ error in the action callback that then makes
its node partial (bench/README, helper surveyG). A callable whose result the parse cannot
tell still gives a future (of int)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros1_main

HEAD = (
    "#include <future>\n#include <memory>\n#include <chrono>\n"
    "struct Graph {\n"
    "  void search(std::shared_ptr<int>& start, int& path);\n"
    "  bool ready() const;\n"
    "};\n")

CASES = {
    "void_member_function": (
        "  std::shared_ptr<Graph> graph = std::make_shared<Graph>();\n"
        "  std::shared_ptr<int> start;\n  int path = 0;\n"
        "  std::future<void> result = std::async(std::launch::async, &Graph::search, graph,\n"
        "                                        std::ref(start), std::ref(path));\n"
        "  if (result.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready)\n"
        "    result.get();\n"),
    "const_member_function_without_policy": (
        "  Graph graph;\n"
        "  std::future<bool> ok = std::async(&Graph::ready, &graph);\n"
        "  bool ready = ok.get();\n"),
    "lambda_into_shared_future": (
        "  int n = 2;\n"
        "  std::shared_future<int> shared = std::async(std::launch::deferred,\n"
        "                                              [n]() { return n + 1; });\n"
        "  int m = shared.get();\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_std_async_is_found(tmp_path, case: str) -> None:
    assert_call_found(tmp_path, ros1_main(HEAD, CASES[case]))
