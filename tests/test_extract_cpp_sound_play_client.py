"""ROS 1 sound_play's C++ client, installed (not in the workspace; survey R): a
``SoundClient(nh, topic)`` advertises sound_play/SoundRequest on the topic given, relative
to the handle; ``SoundClient()`` on ``robotsound`` of a ``ros::NodeHandle()``, the node's
namespace (audio_common's sound_play.h). Without a stand-in the class was unknown and each
construction made the node partial (``CPP_CLASS_UNSEEN``): 40 of JUSTINA's 43 partial C++
nodes (its JustinaHRI library builds one) and bender's sound and speech nodes, whose
sound_play node's ``robotsound`` stayed undecided."""

from __future__ import annotations

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

PACKAGE = ('<?xml version="1.0"?>\n<package format="2"><name>speech</name>'
           "<version>0.1.0</version><description>d</description>"
           '<maintainer email="a@b.c">m</maintainer><license>MIT</license>'
           "<depend>roscpp</depend><depend>sound_play</depend>"
           "<depend>std_srvs</depend></package>\n")

SOURCE = """#include <ros/ros.h>
#include <sound_play/sound_play.h>
#include <std_srvs/Empty.h>
class Speaker {
 public:
  Speaker() : nh_("~") {
    hri_ = new sound_play::SoundClient(nh_, "hri/robotsound");
  }
  void greet() {
    sc_.say("hello");
    hri_->playWave("/tmp/a.wav");
    sound_play::Sound s = sc_.voiceSound("bye");
    s.play();
  }
  ros::NodeHandle nh_;
  sound_play::SoundClient sc_;
  sound_play::SoundClient* hri_;
};
bool stop(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  sound_play::SoundClient sc;
  sc.stopAll();
  return true;
}
int main(int argc, char** argv) {
  ros::init(argc, argv, "speaker");
  ros::NodeHandle nh;
  Speaker speaker;
  speaker.greet();
  ros::ServiceServer server = nh.advertiseService("stop", stop);
  ros::spin();
}
"""


def test_a_sound_client_advertises_its_topic(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(PACKAGE)
    (tmp_path / "speaker.cpp").write_text(SOURCE)
    result = extract_cpp([str(tmp_path / "speaker.cpp")], scan([str(tmp_path)]),
                         cache_dir=None, distro="noetic")
    assert not [d.code for d in result.diagnostics if d.code in (
        "CPP_CLASS_UNSEEN", "CPP_NODE_TO_UNKNOWN", "CPP_ERROR_NEAR_CALL",
        "CPP_INCLUDE_MISSING", "CPP_PARSE_ERROR")]
    calls = sorted({(c.kind, c.name, c.type) for c in result.calls})
    assert calls == [
        ("publish", "robotsound", "sound_play/SoundRequest"),
        ("publish", "~hri/robotsound", "sound_play/SoundRequest"),
        ("server", "stop", "std_srvs/Empty"),
    ]
