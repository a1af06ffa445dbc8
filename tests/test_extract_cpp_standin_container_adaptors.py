"""The container adaptors (``std::priority_queue``, ``std::queue``, ``std::stack``) have
their member types (``container_type``, ``value_type``, ...) and the protected container
``c`` (and the priority queue's ``comp``) a derived class reads: robocup-pkg's path_finder
derives ``AStarQueue`` from ``std::priority_queue`` and walks ``this->c`` through
``container_type::const_iterator``. Without them its ``AStarSearch`` class was an error,
so ``shared_ptr<AStarSearch>`` did not convert to its base's pointer in ``main``, a C++
error beside the node's ROS calls that made it partial (bench/README, helper surveyG)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros1_main

CASES = {
    "priority_queue_container": (
        "#include <queue>\n#include <deque>\n#include <memory>\n"
        "template<typename T, typename Container = std::deque<T>,\n"
        "         typename Compare = std::less<typename Container::value_type>>\n"
        "class Frontier : public std::priority_queue<T, Container, Compare> {\n"
        " public:\n"
        "  explicit Frontier(const Compare& comp = Compare(), Container&& ctnr = Container())\n"
        "      : std::priority_queue<T, Container, Compare>(comp, ctnr) {}\n"
        "  typedef typename std::priority_queue<T, Container, Compare>::container_type\n"
        "      ::const_iterator const_iterator;\n"
        "  const_iterator find(const T& val) const {\n"
        "    auto first = this->c.cbegin();\n"
        "    for (; first != this->c.cend(); ++first) if (*first == val) return first;\n"
        "    return this->c.cend();\n"
        "  }\n"
        "  bool before(const T& a, const T& b) const { return this->comp(a, b); }\n"
        "};\n"
        "struct Search { virtual ~Search() {} };\n"
        "struct AStar : public Search { Frontier<int> open; };\n"
        "void use(const std::shared_ptr<Search>& search) {}\n",
        "  std::shared_ptr<AStar> astar(new AStar());\n"
        "  use(astar);\n"
        "  Frontier<int>::const_iterator at = astar->open.find(3);\n"),
    "stack_and_queue_container": (
        "#include <queue>\n#include <stack>\n#include <vector>\n"
        "struct History : public std::stack<int, std::vector<int>> {\n"
        "  int oldest() const { return c.front(); }\n"
        "};\n"
        "struct Jobs : public std::queue<int> {\n"
        "  std::queue<int>::size_type count() const { return c.size(); }\n"
        "};\n",
        "  History history;\n  history.push(1);\n  int first = history.oldest();\n"
        "  Jobs jobs;\n  jobs.push(2);\n  std::queue<int>::value_type n = jobs.count();\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_a_derived_container_adaptor_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros1_main(include, body))
