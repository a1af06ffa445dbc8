"""``haros-arch diff`` on real history: each given commit against its parent.

    python bench/diff_real.py GITDIR PATH COMMIT...

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

from haros_arch.diff import DiffError, compare_revisions, to_text
from haros_arch.pipeline import Options

INTERESTING = (".launch", ".launch.py", ".launch.xml", ".py", ".cpp", ".hpp", ".h",
               ".yaml", "CMakeLists.txt", "setup.py")


def main(argv: list[str]) -> int:
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
        with tempfile.TemporaryDirectory() as scratch:
            try:
                try:
                    result, _ = compare_revisions(f"{commit}^..{commit}", path, gitdir,
                                                  Options(jobs=1))
                except DiffError as err:
                    if "cannot read" not in str(err):
                        raise
                    repo = _scratch_repository(gitdir, commit, scratch)
                    result, _ = compare_revisions("HEAD~1..HEAD", path, repo,
                                                  Options(jobs=1))
            except DiffError as err:
                print(f"  cannot diff: {err}")
                continue
        print(to_text(result).rstrip())
        print(f"  ({time.perf_counter() - start:.1f} s for both sides)")
    return 0


def _git(*args: str, data: bytes | None = None) -> bytes:
    return subprocess.run(["git", "-c", "user.name=bench", "-c", "user.email=b@b", *args],
                          input=data, capture_output=True, check=True).stdout


def _copy_tree(gitdir: str, rev: str, dest: str) -> None:
    """The files of ``rev`` the mirror has (under 2 MB), written under ``dest``."""
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
