"""Interface models: the interface of nodes whose source the workspace does not have.

``format`` (the versioned file, ``haros-arch-model/2``), ``library`` (the user's files,
then the shipped ``data/<distro>/<package>.json``), ``attach`` (a configuration's nodes
without source take their model), ``commands`` (``rostopic pub`` and ``ros2 topic pub``
nodes made from their arguments) and ``generate`` (``haros-arch models build LIST``: our
extractor run on the pinned public sources of a list of packages).
"""
