"""Oracle: load launch files with the real roslaunch and print what it decided, as JSON.

Run with the system Python that has Debian's python3-roslaunch, never with the venv:

    /usr/bin/python3 bench/launch_roslaunch_dump.py '[["file.launch", ["a:=1"]], ...]'

Prints one JSON object per file (a list). Nothing is started: roscore.xml is not
loaded, machines are not assigned, and ``command=`` parameters are not run (their
value is reported as ``{"command": text}``).
"""

import base64
import json
import sys

import rosgraph.names
import roslaunch.config
import roslaunch.loader
import roslaunch.xmlloader


class Command(str):
    pass


def _param_value(original):
    def param_value(self, verbose, name, ptype, value, textfile, binfile, command):
        if command is not None:
            return Command(command)
        return original(self, verbose, name, ptype, value, textfile, binfile, command)
    return param_value


def _json(value):
    if isinstance(value, Command):
        return {"command": str(value)}
    if hasattr(value, "data") and type(value).__name__ == "Binary":
        return {"binary": base64.b64encode(value.data).decode("ascii")}
    if isinstance(value, (list, tuple)):
        return [_json(v) for v in value]
    if isinstance(value, dict):
        return {str(k): _json(v) for k, v in value.items()}
    return value


def dump(path, args):
    config = roslaunch.config.load_config_default(
        [(path, list(args))], None, verbose=False, assign_machines=False)
    nodes = []
    for node in list(config.nodes) + list(config.tests):
        nodes.append({
            "name": (node.namespace + node.name) if node.name else None,
            "namespace": node.namespace, "package": node.package, "type": node.type,
            "args": node.args, "remaps": [list(r) for r in node.remap_args],
            "machine": node.machine_name, "respawn": bool(getattr(node, "respawn", False)),
            "required": bool(getattr(node, "required", False)),
            "test": type(node).__name__ == "Test",
        })
    # as the master stores them: roslaunch sets them as the caller /roslaunch, so a
    # private name left at the top (no node took it) is /roslaunch/name
    params = {rosgraph.names.resolve_name(key, "/roslaunch"): _json(p.value)
              for key, p in config.params.items()}
    return {"nodes": nodes, "params": params, "clear_params": list(config.clear_params)}


def main():
    roslaunch.loader.Loader.param_value = _param_value(roslaunch.loader.Loader.param_value)
    roslaunch.config.load_roscore = lambda *a, **k: None
    out = []
    for path, args in json.loads(sys.argv[1]):
        try:
            out.append(dump(path, args))
        except Exception as err:  # roslaunch refuses the file
            out.append({"error": f"{type(err).__name__}: {err}"})
    json.dump(out, sys.stdout)


if __name__ == "__main__":
    main()
