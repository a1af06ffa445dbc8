"""``rclcpp::NodeOptions::append_parameter_override(name, value)`` sets a parameter of the
node built with those options before any launch value: topic_tools' relay, throttle,
drop, mux, demux and delay set their topics so from their command-line arguments in
``main``. It is a write of the parameter, so a read of it is not "never set"."""

from __future__ import annotations

import os

from haros_arch.extract.cpp import extract_cpp
from haros_arch.pipeline import analyse
from haros_arch.project import load
from haros_arch.query import run_catalogue
from haros_arch.workspace import scan

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(os.path.dirname(HERE), "fixtures", "cpp", "parameter_overrides")


def test_a_parameter_override_is_a_write_under_its_conditions() -> None:
    found = extract_cpp([os.path.join(ROOT, "src", "relayer", "src", "relay.cpp")],
                        scan([ROOT]), cache_dir=None)
    writes = [(c.name, c.location.line, [k.text for k in c.conditions])
              for c in found.calls if c.kind == "write"]
    assert writes == [
        ("input_topic", 29, ["args.size() >= 2"]),
        ("output_topic", 31, ["args.size() >= 2", "args.size() >= 3"]),
        ("qos_depth", 35, []),  # chained on the options object
        ("lazy", 35, []),
    ]
    # the program's arguments decide those conditions, and give the first two values
    assert all(k.program_args for c in found.calls if c.kind == "write"
               for k in c.conditions)
    assert [c.program_arg for c in found.calls if c.kind == "write"] == [1, 2, None, None]


def test_a_read_of_an_overridden_parameter_is_not_never_set() -> None:
    model = analyse(load(os.path.join(ROOT, "project.yaml")), {})
    unset = [f.entities for f in run_catalogue(model) if f.rule == "parameter-read-not-set"]
    assert unset == []
    (relay,) = [c for c in model.configurations if c.name == "relay"]
    inputs = [p for p in relay.parameters if p.name == "/camera_info_relay/input_topic"]
    assert inputs and inputs[0].is_set


def test_the_instance_s_arguments_name_what_the_overrides_set() -> None:
    model = analyse(load(os.path.join(ROOT, "project.yaml")), {})
    (relay,) = [c for c in model.configurations if c.name == "relay"]
    (instance,) = relay.nodes
    # arguments=["/camera/camera_info", "camera_info"]: input_topic and output_topic,
    # which name the subscription and the publisher (in the node's namespace)
    assert sorted((link.kind, link.resource.name) for link in instance.links
                  if link.kind in ("publish", "subscribe")) == [
        ("publish", "/camera_info"), ("subscribe", "/camera/camera_info")]


def test_conditions_over_what_rclcpp_leaves_name_its_local() -> None:
    found = extract_cpp([os.path.join(ROOT, "src", "relayer", "src", "throttle.cpp")],
                        scan([ROOT]), cache_dir=None)
    outputs = [c for c in found.calls if c.kind == "write" and c.name == "output_topic"]
    assert [c.program_arg for c in outputs] == [4, 5]
    assert {(k.text, k.args_left) for c in outputs for k in c.conditions} >= {
        ('args.at(1) == "messages"', "args"), ("args.size() >= 6", "args")}


def test_each_instance_takes_its_mode_s_arguments() -> None:
    # throttle's "messages" mode takes its output topic from the fourth argument, its
    # "bytes" mode from the fifth: each instance's words decide which writes happen
    model = analyse(load(os.path.join(ROOT, "project.yaml")), {})
    (config,) = [c for c in model.configurations if c.name == "throttle"]
    links = {n.name: sorted((link.kind, link.resource.name) for link in n.links
                            if link.kind in ("publish", "subscribe", "write"))
             for n in config.nodes}
    assert links["/scan_throttle"] == [
        ("publish", "/scan_slow"), ("subscribe", "/scan"),
        ("write", "/scan_throttle/input_topic"), ("write", "/scan_throttle/msgs_per_sec"),
        ("write", "/scan_throttle/output_topic")]
    # rclcpp leaves out the --ros-args section
    assert links["/image_throttle"] == [
        ("publish", "/image_slow"), ("subscribe", "/image"),
        ("write", "/image_throttle/bytes_per_sec"), ("write", "/image_throttle/input_topic"),
        ("write", "/image_throttle/output_topic"), ("write", "/image_throttle/window")]
    # too few for the output topic: its default, the input topic's value and "_throttle"
    assert links["/odom_throttle"] == [
        ("publish", "/odom_throttle"), ("subscribe", "/odom"),
        ("write", "/odom_throttle/input_topic"), ("write", "/odom_throttle/msgs_per_sec")]
    assert not [link for n in config.nodes for link in n.links if link.conditions]


def test_a_default_that_holds_another_parameter_s_value_names_it() -> None:
    # declare_parameter("output_topic", input + "_throttle"), input the value of
    # declare_parameter("input_topic"): the publisher's name is output_topic's value,
    # else "?_throttle" with input_topic's value in place of the "?"
    found = extract_cpp([os.path.join(ROOT, "src", "relayer", "src", "throttle.cpp")],
                        scan([ROOT]), cache_dir=None)
    (publisher,) = [c for c in found.calls if c.kind == "publish"]
    assert (publisher.name_param, publisher.name_default, publisher.default_param) == (
        "output_topic", "?_throttle", "input_topic")
    (subscriber,) = [c for c in found.calls if c.kind == "subscribe"]
    assert (subscriber.name_param, subscriber.name_default, subscriber.default_param) == (
        "input_topic", None, None)
