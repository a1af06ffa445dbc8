"""A Python launch file's ``else`` branch is written ``not (X)`` (statement ``if``): it
contradicts ``if X`` and is ``unless X``, so the two branches' nodes never run together
(duplicate-node-names, multiple-publishers)."""

from __future__ import annotations

from haros_arch.model.conditions import Condition, contradict, exclusive


def launch(text: str, statement: str = "if") -> Condition:
    return Condition(text, "launch", statement)


def test_not_of_a_text_contradicts_the_text() -> None:
    test = "os.getenv('ROS_DISTRO') == 'dashing' or os.getenv('ROS_DISTRO') == 'eloquent'"
    assert contradict(launch(test), launch(f"not ({test})"))
    assert contradict(launch(f"not ({test})"), launch(test))
    assert contradict(launch(f"not ({test})"), launch(f"not (not ({test}))"))
    assert exclusive((launch("use_sim"),), (launch("not (use_sim)"),))
    # ``unless not (X)`` holds when X does
    assert not contradict(launch("x"), launch("not (x)", "unless"))
    assert contradict(launch("x", "unless"), launch("not (x)", "unless"))


def test_what_is_not_a_whole_negation_is_its_own_text() -> None:
    assert not contradict(launch("a"), launch("not (a) or (b)"))
    assert not contradict(launch("a) or (b"), launch("not (a) or (b)"))
    assert not contradict(launch("?"), launch("not (?)"))
    assert not contradict(launch("a"), launch("not (b)"))
