"""What the experiment scripts share: provenance of a run (command, machine, commit, binary),
shell helpers and Markdown tables. Import with the experiments folder on sys.path."""
import datetime
import hashlib
import os
import platform
import shlex
import statistics
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
# The binary the studies run ($FRONTPACK, else the default build), and the lock that keeps timed
# runs of different studies from overlapping (`flock LOCK frontpack ...`).
FRONTPACK = os.environ.get("FRONTPACK", str(REPO / "build" / "cli" / "frontpack"))
LOCK = "/tmp/frontpack-bench.lock"


def sh(*cmd):
    """stdout of cmd run in the repository, stripped; "?" if it cannot run."""
    try:
        return subprocess.run(cmd, capture_output=True, text=True, cwd=REPO).stdout.strip()
    except OSError:
        return "?"


def provenance_lines(frontpack, argv, version=None):
    """The header every RESULTS.md starts with: exact command, machine, date, commit, binary
    (`version`: what it says of itself, default `frontpack --version`; the module: its __version__)."""
    model = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    memkb = next(int(l.split()[1]) for l in open("/proc/meminfo") if l.startswith("MemTotal"))
    commit = sh("git", "rev-parse", "--short", "HEAD")
    tracked = sh("git", "status", "--porcelain", "--untracked-files=no")
    untracked = sh("git", "status", "--porcelain")
    state = "clean" if not untracked else ("dirty: modified tracked files" if tracked else
                                            "tracked files clean, untracked files present")
    binary = Path(frontpack)
    digest = hashlib.sha256(binary.read_bytes()).hexdigest()[:16] if binary.exists() else "?"
    env = f"FRONTPACK={shlex.quote(os.environ['FRONTPACK'])} " if "FRONTPACK" in os.environ else ""
    command = env + " ".join(shlex.quote(a) for a in [sys.executable] + list(argv))
    return [
        f"Command: `{command}` (run from `{os.getcwd()}`)",
        "",
        f"* machine: {sh('nproc')} CPUs (`nproc`), {model}, Linux {platform.release()}, {memkb / 2**20:.1f} GiB memory",
        f"* date: {datetime.datetime.now().astimezone().strftime('%Y-%m-%d %H:%M %Z')}",
        f"* repository commit: `{commit}` ({state})",
        f"* binary: `{frontpack}` ({version or sh(frontpack, '--version')}, sha256 {digest}…)",
    ]


def mean(rows, k):
    return statistics.fmean(r[k] for r in rows)


def sd(rows, k):
    return statistics.stdev(r[k] for r in rows) if len(rows) > 1 else 0.0


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)
