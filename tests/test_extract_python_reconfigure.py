"""rospy's dynamic_reconfigure server and client (survey T: naoqi_bridge's camera.py and
microphone.py build ``Server(NaoqiCameraConfig, self.reconfigure)``). The class was
PY_CLASS_UNSEEN and the nodes PY_NODE_PARTIAL, with none of what the server does:
read each parameter of the config (the package's cfg/*.cfg) in ``~``, publish
``~parameter_descriptions`` and ``~parameter_updates`` (latched, queue 10) and serve
``~set_parameters``, as roscpp's server is already modelled."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

CFG = (
    "#!/usr/bin/env python\n"
    "PACKAGE = 'cam'\n"
    "from dynamic_reconfigure.parameter_generator_catkin import *\n"
    "gen = ParameterGenerator()\n"
    "gen.add('rate', int_t, 0, 'frame rate', 15, 1, 30)\n"
    "gen.add('frame', str_t, 0, 'frame id', 'camera')\n"
    "exit(gen.generate(PACKAGE, 'cam', 'Cam'))\n"
)

NODE = (
    "#!/usr/bin/env python\n"
    "import rospy\n"
    "from dynamic_reconfigure.server import Server\n"
    "import dynamic_reconfigure.client\n"
    "from cam.cfg import CamConfig\n"
    "from other.cfg import OtherConfig\n"
    "\n"
    "def cb(config, level):\n"
    "    return config\n"
    "\n"
    "rospy.init_node('cam')\n"
    "srv = Server(CamConfig, cb)\n"
    "arm = Server(CamConfig, cb, namespace='arm')\n"
    "other = Server(OtherConfig, cb, '/abs')\n"
    "client = dynamic_reconfigure.client.Client('/driver', timeout=5)\n"
)


def test_rospy_reconfigure_server_reads_its_config_and_serves(write_tree) -> None:
    folder = write_tree({"cam/package.xml": package_xml("cam"),
                         "cam/cfg/Cam.cfg": CFG,
                         "cam/nodes/cam.py": NODE})
    result = extract_python([str(folder / "cam" / "nodes" / "cam.py")],
                            scan([str(folder)]), package="cam")
    # the parameters of OtherConfig are not known: a read of '?' under its namespace
    assert [(d.code, d.location.line) for d in result.diagnostics] == [
        ("PY_DYNAMIC_NAME", 14)]
    got = [(c.kind, c.name, c.type, c.queue_size, c.latch, c.default, c.callback,
            c.location.line) for c in result.calls]
    topics = [
        ("publish", "parameter_descriptions", "dynamic_reconfigure/ConfigDescription", 10,
         True, None, None),
        ("publish", "parameter_updates", "dynamic_reconfigure/Config", 10, True, None, None)]
    assert got == [
        ("read", "~rate", "int", None, False, 15, None, 12),
        ("read", "~frame", "str", None, False, "camera", None, 12),
        *[(k, "~" + n, *rest, 12) for k, n, *rest in topics],
        ("server", "~set_parameters", "dynamic_reconfigure/Reconfigure", None, False, None,
         "cb", 12),
        ("read", "~arm/rate", "int", None, False, 15, None, 13),
        ("read", "~arm/frame", "str", None, False, "camera", None, 13),
        *[(k, "~arm/" + n, *rest, 13) for k, n, *rest in topics],
        ("server", "~arm/set_parameters", "dynamic_reconfigure/Reconfigure", None, False,
         None, "cb", 13),
        # a config whose package is not found: its parameters are not known
        ("read", "/abs/?", None, None, False, None, None, 14),
        *[(k, "/abs/" + n, *rest, 14) for k, n, *rest in topics],
        ("server", "/abs/set_parameters", "dynamic_reconfigure/Reconfigure", None, False,
         None, "cb", 14),
        ("client", "/driver/set_parameters", "dynamic_reconfigure/Reconfigure", None, False,
         None, None, 15),
        ("subscribe", "/driver/parameter_descriptions",
         "dynamic_reconfigure/ConfigDescription", None, False, None, None, 15),
        ("subscribe", "/driver/parameter_updates", "dynamic_reconfigure/Config", None, False,
         None, None, 15),
    ]
