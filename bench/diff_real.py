"""``haros-arch diff`` on real history: each given commit against its parent.

    python bench/diff_real.py GITDIR PATH COMMIT...
    python bench/diff_real.py --cases [MIRRORS]      # the commits below (default /work/.mirror)

With ``--cases`` it diffs the commits of ``CASES`` (fetched with the ``fetch`` tool:
github:husky/husky, github:ROBOTIS-GIT/turtlebot3) and compares the entries of one
configuration with the change each commit makes to the graph, as read in its source
(the expected entries, written by hand from ``git show``): exact, missing and extra.

GITDIR is a repository (a bare mirror from the ``fetch`` tool works: nothing is checked
out), PATH the workspace folder or project file relative to its root. For each commit it
prints the commit's subject and the launch and source files it changed (to read the
change against), then the diff's summary and entries, and the seconds both sides took.

A fetched mirror may lack large blobs (meshes, bags), and ``git archive`` stops at the
first missing one: then both trees are copied blob by blob without those, committed to
a scratch repository, and the diff runs on that (the same ``--rev`` path).
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time

from haros_arch.diff import DiffError, DiffResult, compare_revisions, to_text
from haros_arch.pipeline import Options

INTERESTING = (".launch", ".launch.py", ".launch.xml", ".py", ".cpp", ".hpp", ".h",
               ".yaml", "CMakeLists.txt", "setup.py")


# (repository, path, commit, environment, configuration, kinds checked (None: all),
#  expected "status kind key" entries of that configuration)
TB3 = {"TURTLEBOT3_MODEL": "burger", "LDS_MODEL": "LDS-01"}
BRINGUP = "turtlebot3_bringup/robot"
CASES: list[tuple[str, str, str, dict[str, str], str, tuple[str, ...] | None, set[str]]] = [
    # the keyboard teleop gets its own namespace and twist_mux a topic for it
    ("husky+husky", ".", "0441e8a", {}, "husky_gazebo/husky_empty_world", None, {
        "renamed node /kb_teleop/teleop_twist_kb",
        "added topic /kb_teleop/cmd_vel",
        "removed link publish /joy_teleop/teleop_twist_kb /joy_teleop/cmd_vel",
        "added link publish /kb_teleop/teleop_twist_kb /kb_teleop/cmd_vel",
        "added link subscribe /twist_mux /kb_teleop/cmd_vel",
        "changed parameter /twist_mux/topics"}),
    # amcl's scan_topic default and the costmaps' laser topic become front/scan
    ("husky+husky", ".", "580c381", {}, "husky_navigation/amcl_demo", None, {
        "changed node /amcl", "added topic /front/scan", "removed topic /scan",
        "added link subscribe /amcl /front/scan", "removed link subscribe /amcl /scan",
        "changed parameter /move_base/global_costmap/obstacles_laser/laser/topic",
        "changed parameter /move_base/local_costmap/obstacles_laser/laser/topic"}),
    # a new argument passed down with the default the included file had: no change
    ("husky+husky", ".", "5d9e9e3", {}, "husky_navigation/gmapping_demo", None, set()),
    ("husky+husky", ".", "34bd305", {}, "husky_gazebo/husky_empty_world", None, {
        "changed parameter /twist_marker_server/link_name"}),
    # if -> unless: the EKF node is launched by default now (its links checked as nodes)
    ("husky+husky", ".", "d7cdd40", {}, "husky_gazebo/husky_empty_world", ("node",), {
        "added node /ekf_localization"}),
    # a namespace argument (empty by default) and frame ids given to turtlebot3_ros's nodes
    ("ROBOTIS-GIT+turtlebot3", ".", "d81e95a", TB3, BRINGUP, None, {
        "added parameter /turtlebot3_node/odometry.frame_id",
        "added parameter /turtlebot3_node/odometry.child_frame_id",
        "changed parameter /diff_drive_controller/odometry.frame_id",
        "changed parameter /diff_drive_controller/odometry.child_frame_id",
        "changed parameter /robot_state_publisher/frame_prefix"}),
    # the frame ids move from the launch file into the code, behind a namespace parameter
    ("ROBOTIS-GIT+turtlebot3", ".", "f1f67ca", TB3, BRINGUP, None, {
        "added link read /diff_drive_controller /diff_drive_controller/namespace",
        "added parameter /diff_drive_controller/namespace",
        "added parameter /turtlebot3_node/namespace",
        "changed parameter /diff_drive_controller/odometry.frame_id",
        "changed parameter /diff_drive_controller/odometry.child_frame_id",
        "removed parameter /turtlebot3_node/odometry.frame_id",
        "removed parameter /turtlebot3_node/odometry.child_frame_id"}),
]


def run_cases(mirrors: str) -> int:
    exact = 0
    for repo, path, commit, env, config, kinds, expected in CASES:
        os.environ.update(env)
        result = _diff(os.path.join(mirrors, repo, "repo"), path, commit)
        if result is None:
            continue
        found = {f"{c.status} {c.kind} {c.key}" for d in result.configurations
                 if d.name == config for c in d.changes if kinds is None or c.kind in kinds}
        exact += found == expected
        print(f"{repo} {commit} [{config}]: {'exact' if found == expected else 'DIFFERS'}"
              f" ({len(found & expected)} of {len(expected)} expected found, "
              f"{len(found - expected)} extra)")
        for line in sorted(expected - found):
            print(f"    missing: {line}")
        for line in sorted(found - expected):
            print(f"    extra:   {line}")
    print(f"{exact} of {len(CASES)} commits: the diff names exactly the change")
    return 0


def _diff(gitdir: str, path: str, commit: str) -> DiffResult | None:
    with tempfile.TemporaryDirectory() as scratch:
        try:
            try:
                result, _ = compare_revisions(f"{commit}^..{commit}", path, gitdir,
                                              Options(jobs=1))
            except DiffError as err:
                if "cannot read" not in str(err):
                    raise
                repo = _scratch_repository(gitdir, commit, scratch)
                result, _ = compare_revisions("HEAD~1..HEAD", path, repo, Options(jobs=1))
        except DiffError as err:
            print(f"  cannot diff {commit}: {err}")
            return None
    return result


def main(argv: list[str]) -> int:
    if argv and argv[0] == "--cases":
        return run_cases(argv[1] if len(argv) > 1 else "/work/.mirror")
    gitdir, path, commits = argv[0], argv[1], argv[2:]
    for commit in commits:
        show = subprocess.run(["git", "--git-dir", gitdir, "show", "--name-status",
                               "--format=%h %s", commit], capture_output=True, text=True,
                              check=True).stdout.splitlines()
        print("=" * 78)
        print(show[0])
        for line in show[1:]:
            if line.strip() and line.rstrip().endswith(INTERESTING):
                print("  changed:", line)
        start = time.perf_counter()
        result = _diff(gitdir, path, commit)
        if result is None:
            continue
        print(to_text(result).rstrip())
        print(f"  ({time.perf_counter() - start:.1f} s for both sides)")
    return 0


def _git(*args: str, data: bytes | None = None) -> bytes:
    return subprocess.run(["git", "-c", "user.name=bench", "-c", "user.email=b@b", *args],
                          input=data, capture_output=True, check=True).stdout


def _copy_tree(gitdir: str, rev: str, dest: str) -> None:
    """The files of ``rev`` the mirror has (under 2 MB), written under ``dest`` (executable
    where git says so)."""
    listing = _git(f"--git-dir={gitdir}", "ls-tree", "-r", "-l", "-z", rev).split(b"\0")
    for entry in filter(None, listing):
        meta, name = entry.split(b"\t", 1)
        mode, kind, sha, size = meta.split()
        if kind != b"blob" or not size.isdigit() or int(size) > 2_000_000:
            continue
        try:
            data = _git(f"--git-dir={gitdir}", "cat-file", "blob", sha.decode())
        except subprocess.CalledProcessError:
            continue  # not in the mirror
        target = os.path.join(dest, name.decode("utf-8", "replace"))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        if mode == b"120000":
            continue  # links are left out (the scratch copy needs none)
        with open(target, "wb") as handle:
            handle.write(data)
        if mode == b"100755":  # a script roslaunch runs from the package's folder
            os.chmod(target, 0o755)


def _scratch_repository(gitdir: str, commit: str, scratch: str) -> str:
    repo = os.path.join(scratch, "repo")
    _git("init", "-q", repo)
    for rev in (f"{commit}^", commit):
        _git("-C", repo, "rm", "-rq", "--ignore-unmatch", ".")
        _copy_tree(gitdir, rev, repo)
        _git("-C", repo, "add", "-A")
        _git("-C", repo, "commit", "-qm", rev, "--allow-empty")
    return repo


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
