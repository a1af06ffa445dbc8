"""Stand-in gaps seen on real code (bench/README, survey Z39 and helper followups6):
``boost::circular_buffer`` (spencer_people_tracking's nnt_node),
``boost::ptr_vector``, diagnostic_updater's ``TopicDiagnostic`` / ``DiagnosedPublisher``
and ``DiagnosticStatusWrapper::OK``, and ``boost::filesystem::path::make_preferred``
(ros_canopen's ros_chain.cpp): each left a C++ error in a function that calls the ROS
API, so the call after it could be missed and the node was partial."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros1_main

CASES = {
    "circular_buffer": (
        "#include <boost/circular_buffer.hpp>\n",
        "  boost::circular_buffer<double> last(10);\n"
        "  last.push_back(1.0);\n"
        "  if (last.full() && last.front() < last.back()) last.pop_front();\n"),
    "ptr_vector": (
        "#include <boost/ptr_container/ptr_vector.hpp>\n",
        "  boost::ptr_vector<std::string> names;\n"
        "  names.push_back(new std::string(\"a\"));\n"
        "  for (boost::ptr_vector<std::string>::iterator i = names.begin();"
        " i != names.end(); ++i) ROS_INFO(\"%s\", i->c_str());\n"),
    "topic_diagnostic": (
        "#include <diagnostic_updater/diagnostic_updater.h>\n"
        "#include <diagnostic_updater/publisher.h>\n",
        "  diagnostic_updater::Updater updater;\n"
        "  double min_freq = 5.0, max_freq = 10.0;\n"
        "  diagnostic_updater::TopicDiagnostic diag(\"scan\", updater,\n"
        "      diagnostic_updater::FrequencyStatusParam(&min_freq, &max_freq, 0.1, 10),\n"
        "      diagnostic_updater::TimeStampStatusParam(-1, 1.3));\n"
        "  diag.tick(ros::Time::now());\n"
        "  diagnostic_updater::DiagnosticStatusWrapper stat;\n"
        "  stat.summary(diagnostic_updater::DiagnosticStatusWrapper::OK, \"ok\");\n"
        "  stat.summary(stat.WARN, \"slow\");\n"),
    "make_preferred": (
        "#include <boost/filesystem.hpp>\n",
        "  boost::filesystem::path p(\"a/b\");\n"
        "  std::string text = p.make_preferred().string();\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    # (the Updater's own /diagnostics publisher and reads beside it)
    assert_call_found(tmp_path, ros1_main(include, body))
