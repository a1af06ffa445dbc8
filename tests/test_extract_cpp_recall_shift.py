"""The grep for the ROS API's call sites (``recall.site_pattern``) takes a method's name
followed by ``(`` or a template's ``<``, not by a shift or a comparison: rosbag's
encrypt prints ``std::cout << options.plugin << ":" << options.param << "\\n";``, a
field named like NodeHandle's ``param``, and was partial for a call "missed" there."""

from __future__ import annotations

from haros_arch.extract.cpp.recall import site_pattern


def test_a_field_named_like_a_method_and_shifted_is_no_call_site() -> None:
    pattern = site_pattern()
    assert pattern.search('std::cout << options.plugin << ":" << options.param << "\\n";') \
        is None
    assert pattern.search("if (options.param <= limit) {}") is None


def test_a_call_and_a_template_call_are_call_sites() -> None:
    pattern = site_pattern()
    assert pattern.search('nh.param("rate", rate, 10.0);') is not None
    assert pattern.search('nh.param<double>("rate", rate, 10.0);') is not None
    assert pattern.search("pub_ = nh.advertise<std_msgs::String>(topic, 1);") is not None
