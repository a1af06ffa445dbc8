"""OpenCV 2.x's ``cv::vector`` (its core header's ``using std::vector;``): IGVC2015's
sb_vision writes ``cv::vector<cv::Mat> channels;`` in a header and, beside ``using
namespace cv; using namespace ros; using namespace std;``, ``vector<Point2f> points;``
in the main that makes its ROS calls. The stand-in had no ``cv::vector``: the parse
declared one of its own, a template apart from std's, and every bare ``vector`` became
ambiguous, an error in main that made the node partial. OpenCV 3 and 4 code, which has
no ``cv::vector``, reads the same."""

from __future__ import annotations

from standin_gap_checks import assert_call_found, ros1_main

HEAD = """
#include <opencv2/opencv.hpp>
#include <vector>
struct Filter {
  cv::vector<cv::Mat> channels;
};
using namespace cv;
using namespace ros;
using namespace std;
"""

BODY = """
  vector<Point2f> points;
  points.push_back(Point2f(0, 1));
  Filter filter;
  filter.channels.push_back(Mat());
  cv::vector<int> sizes(2, 0);
"""


def test_opencv2_vector_is_std_vector(tmp_path) -> None:
    assert_call_found(tmp_path, ros1_main(HEAD, BODY))
