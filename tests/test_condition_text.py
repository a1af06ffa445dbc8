"""A condition as a finding's message writes it: its statement and, when it has one,
its text; a ``try`` block, which has none, is ``try``, not ``try ()`` (the report's
conditional-communication infos of ethzasl_xsens_driver read "exists only under try
(), while (...)")."""

from __future__ import annotations

from haros_arch.model.conditions import Condition


def test_a_condition_without_text_is_its_statement() -> None:
    assert str(Condition("x > 1")) == "if (x > 1)"
    assert str(Condition("not rospy.is_shutdown()", statement="while")) == (
        "while (not rospy.is_shutdown())")
    assert str(Condition("", statement="try")) == "try"
