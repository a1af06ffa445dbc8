"""Findings that say the same thing: one finding (``query.catalogue.merge``)."""

from __future__ import annotations

from haros_arch.model import Location
from haros_arch.model.finding import Finding
from haros_arch.query.catalogue import merge

SUB = Location("tasks", "tasks/dispatch.py", 160, 20)
OTHER = Location("tasks", "tasks/dispatch.py", 170, 20)


def said(entities, location=SUB, configuration="battle"):
    return Finding("subscriber-without-publisher", "warning", "Subscriber with no publisher",
                   "/requester subscribes to /responses but nothing publishes it",
                   configuration, entities, location)


def test_instances_of_one_name_saying_the_same_at_one_place_are_one_finding():
    # one executable started four times under one name (rmf_demos' battle_go.launch.xml)
    found = merge([said(("node:/requester", "topic:/responses")),
                   said(("node:/requester#2", "topic:/responses")),
                   said(("node:/requester", "topic:/responses"), OTHER),
                   said(("node:/requester#2", "topic:/responses"), OTHER),
                   said(("node:/requester#3", "topic:/responses"), configuration="loop")])
    [one] = found
    assert one.entities == ("node:/requester", "topic:/responses", "node:/requester#2",
                            "node:/requester#3")
    assert one.also == (OTHER,)
    assert one.configurations == ("battle", "loop")


def test_instances_of_one_name_at_different_places_stay_apart():
    found = merge([said(("node:/requester", "topic:/responses")),
                   said(("node:/requester#2", "topic:/responses"), OTHER)])
    assert [f.location for f in found] == [SUB, OTHER]
