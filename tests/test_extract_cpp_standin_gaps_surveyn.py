"""Stand-in gaps seen on real ROS 1 code (bench/README, helper surveyN): each left a C++
error in a function that calls the ROS API, so the call after it could be missed and the
node was partial. diagnostic_updater's ``FunctionDiagnosticTask``, a task a composite
task adds (guardian_sim's guardian_robot_control); OpenCV's ``cv::Mat(size, type, data,
step)`` over a message's pixels (quori_ros' quori_face_node); gazebo_plugins'
``PubMultiQueue::addPub<T>()`` (smb_common's odometry source plugin, a fallback header:
gazebo_plugins is not in the workspace)."""

from __future__ import annotations

import pytest
from standin_gap_checks import assert_call_found, ros1_main

CASES = {
    "function_diagnostic_task": (
        "#include <diagnostic_updater/diagnostic_updater.h>\n"
        "#include <diagnostic_updater/update_functions.h>\n"
        "static void check(diagnostic_updater::DiagnosticStatusWrapper &stat) {}\n",
        "  diagnostic_updater::Updater updater;\n"
        "  diagnostic_updater::FunctionDiagnosticTask task(\"command\", &check);\n"
        "  updater.add(task);\n"
        "  double low = 5.0, high = 10.0;\n"
        "  diagnostic_updater::HeaderlessTopicDiagnostic *freq =\n"
        "      new diagnostic_updater::HeaderlessTopicDiagnostic(\"cmd\", updater,\n"
        "          diagnostic_updater::FrequencyStatusParam(&low, &high, 0.1, 10));\n"
        "  freq->addTask(&task);\n"),
    "mat_over_data": (
        "#include <opencv2/core/core.hpp>\n#include <sensor_msgs/Image.h>\n",
        "  sensor_msgs::Image msg;\n"
        "  const cv::Mat image(cv::Size(msg.width, msg.height), CV_8UC3,\n"
        "                      const_cast<uint8_t *>(msg.data.data()), msg.step);\n"),
    "pub_queue": (
        "#include <gazebo_plugins/PubQueue.h>\n",
        "  PubMultiQueue pmq;\n"
        "  pmq.startServiceThread();\n"
        "  PubQueue<std_msgs::String>::Ptr queue = pmq.addPub<std_msgs::String>();\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_call_after_the_library_s_use_is_found(tmp_path, case: str) -> None:
    include, body = CASES[case]
    assert_call_found(tmp_path, ros1_main(include, body))
