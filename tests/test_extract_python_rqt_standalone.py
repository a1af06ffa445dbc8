"""An rqt plugin's own program: qt_gui's ``Main().main(standalone='pkg.module.Class')``
(rqt_gui's ``Main``) builds that plugin class alone. bwi_common's level_selector script
runs multi_level_map_utils' LevelSelectorPlugin so, which subscribes ``map_metadata`` and
``level_mux/current_level`` and calls ``level_mux/change_current_level``: the node was
complete with no call at all. A plugin class in a package not read is said unseen."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.python import extract_python
from haros_arch.workspace import scan

SELECTOR = {
    "src/maps/package.xml": package_xml("maps").replace(
        "</package>", "<exec_depend>rqt_gui</exec_depend><exec_depend>other_gui"
        "</exec_depend></package>"),
    "src/maps/src/maps/__init__.py": "",
    "src/maps/src/maps/plugins.py": (
        "import rospy\n"
        "from std_msgs.msg import String\n"
        "from std_srvs.srv import Empty\n"
        "from qt_gui.plugin import Plugin\n"
        "class Selector(Plugin):\n"
        "    def __init__(self, context):\n"
        "        super(Selector, self).__init__(context)\n"
        "        self.sub = rospy.Subscriber('map_metadata', String, self.got)\n"
        "        self.proxy = rospy.ServiceProxy('mux/change_level', Empty)\n"
        "    def got(self, msg):\n"
        "        self.status = rospy.Subscriber('mux/current_level', String, self.level)\n"
        "    def level(self, msg):\n"
        "        pass\n"),
    "src/maps/nodes/selector": (
        "#!/usr/bin/env python\n"
        "import sys\n"
        "from rqt_gui.main import Main\n"
        "plugin = 'maps.plugins.Selector'\n"
        "main = Main(filename=plugin)\n"
        "sys.exit(main.main(standalone=plugin))\n"),
    "src/maps/nodes/other": (
        "#!/usr/bin/env python\n"
        "import sys\n"
        "from rqt_gui.main import Main\n"
        "sys.exit(Main().main(sys.argv, 'other_gui.widget.Other'))\n"),
}


def test_a_standalone_rqt_plugin_is_the_program_s_code(write_tree) -> None:
    root = write_tree(SELECTOR)
    ws = scan([str(root / "src")], {})
    node = root / "src" / "maps" / "nodes" / "selector"
    result = extract_python([str(node)], ws, package="maps")
    assert sorted((c.kind, c.name, c.location.line) for c in result.calls) == [
        ("client", "mux/change_level", 9),
        ("subscribe", "map_metadata", 8),
        ("subscribe", "mux/current_level", 11),
    ]
    other = extract_python([str(root / "src" / "maps" / "nodes" / "other")], ws,
                           package="maps")
    assert other.calls == []
    assert [d.message for d in other.diagnostics if d.code == "PY_CLASS_UNSEEN"
            and "other_gui" in d.message] != []
