"""Boost.Heap: tauv's state_estimation_cpp keeps its sensor messages in two
``boost::heap::priority_queue<boost::shared_ptr<SensorMsg>, boost::heap::compare<
std::greater_equal<...>>>`` members and ``reserve``s them in the constructor that also
subscribes; the header was missing, the members errors, and the node partial
(``CPP_ERROR_NEAR_CALL``: no member named 'delayed_queue'). The stand-in has the
priority queue and the mutable heaps (each ``boost/heap/...`` header)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros1_main

HEADS = {
    "priority_queue": (
        "#include <boost/heap/priority_queue.hpp>\n#include <boost/shared_ptr.hpp>\n"
        "struct Msg { double time; };\n"
        "typedef boost::shared_ptr<Msg> MsgPtr;\n"
        "struct Estimator {\n"
        "  boost::heap::priority_queue<MsgPtr, boost::heap::compare<std::greater_equal<"
        "MsgPtr>>> queue;\n"
        "  Estimator() { queue.reserve(10); }\n"
        "};\n"),
    "fibonacci_heap": (
        "#include <boost/heap/fibonacci_heap.hpp>\n"
        "struct Node { int cost; };\n"
        "struct Planner {\n"
        "  typedef boost::heap::fibonacci_heap<Node, boost::heap::compare<std::less<int>>> "
        "Heap;\n"
        "  Heap open;\n"
        "  Heap::handle_type handle;\n"
        "};\n"),
}

BODIES = {
    "priority_queue": (
        "  Estimator estimator;\n"
        "  estimator.queue.push(MsgPtr(new Msg()));\n"
        "  while (!estimator.queue.empty()) {\n"
        "    double t = estimator.queue.top()->time;\n"
        "    estimator.queue.pop();\n"
        "  }\n"),
    "fibonacci_heap": (
        "  Planner planner;\n"
        "  planner.handle = planner.open.push(Node());\n"
        "  planner.open.update(planner.handle, Node());\n"
        "  int best = planner.open.top().cost;\n"),
}


@pytest.mark.parametrize("case", sorted(HEADS))
def test_a_call_after_a_boost_heap_is_found(tmp_path, case: str) -> None:
    assert_call_found(tmp_path, ros1_main(HEADS[case], BODIES[case]))
