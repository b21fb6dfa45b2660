#!/usr/bin/env python3
"""A sweep rendered past one process agrees with one local `ivshadow variants` run.

    distributed_test.py IVSHADOW BASE.iv SWEEP.variants WORK_DIR ROUTE

ROUTE is one of
  parallel  `--list` fed to GNU parallel, then `variants-merge`;
  retry     the four shards one after another, one render of a shard killed midway: the
            manifest says failed, a rerun of that shard renders it (and only it) again and the
            merge is complete;
  slurm     a one-node Slurm cluster on localhost started here (munged, slurmctld, slurmd,
            configured in WORK_DIR and torn down afterwards even on failure): the script of
            `--slurm` submits a job array of 4 tasks and the merge job that depends on it.

Each route is checked against the local run: the same CSV rows (name, assignments, status,
shadow method, memory, layers, image; the timing columns filled for the same variants) and the
same pixels in every picture (`ivshadow compare`, largest error 0). A route whose programs are
not installed is skipped (exit code 77, CTest's SKIP_RETURN_CODE) naming what is missing.
"""
import csv
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

SKIP = 77
SIZE = "64x48"
# Columns that must be equal; the timing columns differ from run to run and are only checked
# for being filled for the same variants.
EQUAL = ["variant", "assignments", "status", "shadow_method", "dsm_bytes", "bvh_bytes",
         "dsm_layers_used", "image"]
TIMED = ["frame_ms_median", "dsm_build_ms", "rays_ms", "bvh_build_ms", "peel_ms"]


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(command, expect=None, **kwargs):
    result = subprocess.run(command, capture_output=True, text=True, **kwargs)
    if expect is not None and result.returncode not in expect:
        fail("%s exited %d, expected %s\nstdout: %s\nstderr: %s" %
             (" ".join(command), result.returncode, expect, result.stdout, result.stderr))
    return result


def read_csv(directory):
    with open(os.path.join(directory, "variants.csv"), newline="") as f:
        return list(csv.DictReader(f))


def check_same_as_local(ivshadow, local, other, route):
    expected = read_csv(local)
    got = read_csv(other)
    if len(got) != len(expected):
        fail("%s: %d CSV rows, the local run has %d" % (route, len(got), len(expected)))
    pictures = 0
    for want, row in zip(expected, got):
        for column in EQUAL:
            if want[column] != row[column]:
                fail("%s: variant %s: column %s is %r, the local run has %r" %
                     (route, want["variant"], column, row[column], want[column]))
        for column in TIMED:
            if bool(want[column]) != bool(row[column]):
                fail("%s: variant %s: column %s is %r, the local run has %r" %
                     (route, want["variant"], column, row[column], want[column]))
        if want["status"] != "ok":
            continue
        metrics = os.path.join(other, "compare-%s.json" % want["variant"])
        run([ivshadow, "compare", os.path.join(local, want["image"]),
             os.path.join(other, row["image"]), "--json", metrics], expect=[0])
        with open(metrics) as f:
            largest = json.load(f)["all"]["max_abs_error"]
        os.remove(metrics)
        if largest != 0:
            fail("%s: %s differs from the local run's picture by up to %d steps" %
                 (route, row["image"], largest))
        pictures += 1
    with open(os.path.join(other, "index.html")) as f:
        html = f.read()
    for want in expected:
        if want["status"] != "ok" and "variant %s:" % want["variant"] not in html:
            fail("%s: index.html does not show the error of %s" % (route, want["variant"]))
    print("%s: %d rows as in the local run, %d pictures pixel-identical" %
          (route, len(got), pictures))


def local_run(ivshadow, base, sweep, work):
    local = os.path.join(work, "local")
    shutil.rmtree(local, ignore_errors=True)
    # Exit 2: the one variant with a bad field; the others rendered.
    run([ivshadow, "variants", base, sweep, "-o", local, "--size", SIZE, "--frames", "1",
         "--jobs", "2"], expect=[2])
    rows = read_csv(local)
    if len(rows) < 13 or sum(row["status"] == "ok" for row in rows) < 12:
        fail("the local run rendered fewer than 12 variants: %s" % rows)
    check_hashes(base, local)
    return local


def fnv1a(parts):
    """FNV-1a, 64 bits, over each part followed by the byte 0xff (docs/VARIANTS.md)."""
    value = 14695981039346656037
    for part in parts:
        for byte in part + b"\xff":
            value = ((value ^ byte) * 1099511628211) % (1 << 64)
    return "%016x" % value


def check_hashes(base, directory):
    """The plan's hash of every variant, recomputed here from its documented definition: the
    same on any machine, so shards elsewhere agree on what is done."""
    with open(os.path.join(directory, "manifests", "plan.json")) as f:
        plan = json.load(f)
    with open(base, "rb") as f:
        scene = f.read()
    for variant in plan["variants"]:
        parts = [scene, plan["size"].encode(), str(plan["frames"]).encode(),
                 variant["name"].encode()]
        parts += [a["text"].encode() for a in variant["assignments"]]
        if fnv1a(parts) != variant["hash"]:
            fail("variant %s: the plan's hash %s is not FNV-1a of its inputs (%s)" %
                 (variant["name"], variant["hash"], fnv1a(parts)))


def status_counts(ivshadow, directory):
    out = run([ivshadow, "variants-merge", "--status", directory], expect=[0]).stdout
    return out.splitlines()[0].split(": ", 1)[1]


def route_parallel(ivshadow, base, sweep, work, local):
    if shutil.which("parallel") is None:
        print("SKIP: GNU parallel is not installed (Debian package parallel)")
        return SKIP
    out = os.path.join(work, "parallel")
    shutil.rmtree(out, ignore_errors=True)
    listing = run([ivshadow, "variants", base, sweep, "-o", out, "--size", SIZE, "--frames", "1",
                   "--list"], expect=[0]).stdout.splitlines()
    names = [line.split("\t")[0] for line in listing]
    if names != [row["variant"] for row in read_csv(local)]:
        fail("--list names %s, the local run %s" % (names, read_csv(local)))
    if os.path.exists(out):
        fail("--list wrote %s; it must only print" % out)
    # Each line's second column is a shell command that renders one variant alone.
    commands = "".join(line.split("\t", 1)[1] + "\n" for line in listing)
    result = subprocess.run(["parallel", "--will-cite", "-j", "2"], input=commands, text=True,
                            capture_output=True)
    # parallel exits with the number of failed commands: the one bad variant.
    if result.returncode != 1:
        fail("parallel exited %d (expected 1, the bad variant)\n%s" %
             (result.returncode, result.stderr))
    if os.path.exists(os.path.join(out, "variants.csv")):
        fail("a --only run wrote variants.csv; only variants-merge may")
    run([ivshadow, "variants-merge", out], expect=[2])
    check_same_as_local(ivshadow, local, out, "GNU parallel")
    return 0


def render_children(directory):
    """The pids of `ivshadow render` processes writing into `directory`."""
    pids = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % entry, "rb") as f:
                words = f.read().split(b"\0")
        except OSError:
            continue
        if (len(words) > 4 and words[1] == b"render" and
                any(word.startswith(directory.encode() + b"/") for word in words)):
            pids.append(int(entry))
    return pids


def route_retry(ivshadow, base, sweep, work, local):
    out = os.path.join(work, "retry")
    shutil.rmtree(out, ignore_errors=True)
    shard = [ivshadow, "variants", base, sweep, "-o", out, "--size", SIZE, "--frames", "1"]
    for k in (0, 2, 3):
        run(shard + ["--shard", "%d/4" % k], expect=[0, 2])
    if status_counts(ivshadow, out).endswith("pending %d of 14 variants" % 0):
        fail("three shards of four left nothing pending")
    # Shard 1/4, with one of its renders killed as a crashed node would kill it. Each variant
    # in a render process of its own (IVSHADOW_VARIANTS_WORKERS=0): a killed worker would be
    # started again and its variant retried (tests/variants/VariantsWorkersTest.cpp), where
    # this route needs a variant that stays failed until the shard is run again.
    task = subprocess.Popen(shard + ["--shard", "1/4"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True,
                            env=dict(os.environ, IVSHADOW_VARIANTS_WORKERS="0"))
    killed = None
    deadline = time.time() + 60
    while killed is None and task.poll() is None and time.time() < deadline:
        for pid in render_children(out):
            os.kill(pid, signal.SIGKILL)
            killed = pid
            break
        time.sleep(0.005)
    stdout, stderr = task.communicate()
    if killed is None:
        fail("no render of shard 1/4 was seen to kill")
    if task.returncode != 1 or "killed by a signal" not in stderr:
        fail("shard 1/4 with a killed render exited %d: %s" % (task.returncode, stderr))
    counts = status_counts(ivshadow, out)
    if "failed 2," not in counts:  # the killed one and the bad variant
        fail("--status after the kill says %s" % counts)
    merged = run([ivshadow, "variants-merge", out], expect=[1])
    if "killed by a signal" not in merged.stderr:
        fail("the merge does not list the killed variant: %s" % merged.stderr)
    # The rerun renders the failed variants again (the killed one and the bad one, which
    # fails again: exit 2) and keeps the two that rendered.
    again = run(shard + ["--shard", "1/4"], expect=[2])
    if ("rendered 1 of 2 variants of shard 1/4" not in again.stdout or
            "2 kept from an earlier run" not in again.stdout):
        fail("the rerun of shard 1/4 did not render just the failed variants: %s" % again.stdout)
    counts = status_counts(ivshadow, out)
    if counts != "done 13, failed 1, pending 0 of 14 variants":
        fail("--status after the rerun says %s" % counts)
    run([ivshadow, "variants-merge", out], expect=[2])
    check_same_as_local(ivshadow, local, out, "shards with a killed render retried")
    return 0


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class SlurmCluster:
    """munged, slurmctld and slurmd in the foreground, as children of this script, configured
    in `directory`; stop() ends exactly these three processes."""

    def __init__(self, directory):
        self.dir = directory
        self.processes = []
        self.env = dict(os.environ, SLURM_CONF=os.path.join(directory, "slurm.conf"))

    def start(self):
        d = self.dir
        for sub in ("state", "spool", "munge"):
            os.makedirs(os.path.join(d, sub), mode=0o700, exist_ok=True)
        os.chmod(d, 0o700)
        key = os.path.join(d, "munge", "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o600)
        socket_path = os.path.join(d, "munge", "munge.socket")
        self._spawn("munged", ["munged", "--foreground", "--force", "--key-file=" + key,
                               "--socket=" + socket_path,
                               "--pid-file=" + os.path.join(d, "munge", "munged.pid"),
                               "--log-file=" + os.path.join(d, "munge", "munged.log"),
                               "--seed-file=" + os.path.join(d, "munge", "munged.seed")])
        self._wait_for(lambda: os.path.exists(socket_path), "munged's socket")
        host = socket.gethostname().split(".")[0]
        config = "\n".join([
            "ClusterName=ivshadowtest",
            "SlurmctldHost=%s(127.0.0.1)" % host,
            "SlurmctldPort=%d" % free_port(),
            "SlurmdPort=%d" % free_port(),
            "AuthType=auth/munge",
            "CredType=cred/munge",
            "AuthInfo=socket=" + socket_path,
            "SlurmUser=root",
            "SlurmdUser=root",
            "StateSaveLocation=" + os.path.join(d, "state"),
            "SlurmdSpoolDir=" + os.path.join(d, "spool"),
            "SlurmctldPidFile=" + os.path.join(d, "slurmctld.pid"),
            "SlurmdPidFile=" + os.path.join(d, "slurmd.pid"),
            "SlurmctldLogFile=" + os.path.join(d, "slurmctld.log"),
            "SlurmdLogFile=" + os.path.join(d, "slurmd.log"),
            "ProctrackType=proctrack/linuxproc",
            "TaskPlugin=task/none",
            "SelectType=select/cons_tres",
            "SelectTypeParameters=CR_CPU",
            "SchedulerType=sched/builtin",
            "JobAcctGatherType=jobacct_gather/none",
            "AccountingStorageType=accounting_storage/none",
            "MpiDefault=none",
            "ReturnToService=2",
            "SlurmctldTimeout=30",
            "SlurmdTimeout=30",
            "NodeName=%s NodeAddr=127.0.0.1 CPUs=%d State=UNKNOWN" % (host, os.cpu_count()),
            "PartitionName=test Nodes=%s Default=YES MaxTime=INFINITE State=UP" % host,
            ""])
        with open(self.env["SLURM_CONF"], "w") as f:
            f.write(config)
        self._spawn("slurmctld", ["slurmctld", "-D", "-i"])
        self._spawn("slurmd", ["slurmd", "-D", "-N", host])
        self._wait_for(self._node_idle, "the node to be idle (sinfo)")

    def _spawn(self, name, command):
        log = open(os.path.join(self.dir, name + ".stdout"), "w")
        self.processes.append((name, subprocess.Popen(command, stdout=log, stderr=log,
                                                      env=self.env)))

    def _node_idle(self):
        for name, process in self.processes:
            if process.poll() is not None:
                fail("%s exited %d at start; its log: %s" %
                     (name, process.returncode, self.log_tail(name)))
        out = subprocess.run(["sinfo", "-h", "-o", "%t"], capture_output=True, text=True,
                             env=self.env).stdout.strip()
        return out in ("idle", "mix", "alloc")

    def _wait_for(self, condition, what, seconds=60):
        deadline = time.time() + seconds
        while time.time() < deadline:
            if condition():
                return
            time.sleep(0.2)
        fail("timed out waiting for %s; logs:\n%s" % (what, self.log_tail()))

    def log_tail(self, only=None):
        text = ""
        for name in ("munged", "slurmctld", "slurmd"):
            if only and name != only:
                continue
            for path in (os.path.join(self.dir, name + ".stdout"),
                         os.path.join(self.dir, name + ".log"),
                         os.path.join(self.dir, "munge", name + ".log")):
                if os.path.exists(path):
                    with open(path, errors="replace") as f:
                        text += "--- %s\n%s\n" % (path, "".join(f.readlines()[-15:]))
        return text

    def jobs(self):
        return subprocess.run(["squeue", "-h", "-o", "%i %T"], capture_output=True, text=True,
                              env=self.env).stdout.split("\n")

    def stop(self):
        for name, process in reversed(self.processes):
            if process.poll() is None:
                process.terminate()
                try:
                    process.wait(timeout=15)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait()


def route_slurm(ivshadow, base, sweep, work, local):
    missing = [p for p in ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo")
               if shutil.which(p) is None]
    if missing:
        print("SKIP: Slurm is not installed (Debian packages slurm-wlm and munge): no %s" %
              ", ".join(missing))
        return SKIP
    out = os.path.join(work, "slurm-out")
    shutil.rmtree(out, ignore_errors=True)
    cluster_dir = tempfile.mkdtemp(prefix="cluster-", dir=work)
    cluster = SlurmCluster(cluster_dir)
    try:
        cluster.start()
        # --slurm given relative to where it is run, submit.sh run from elsewhere: the scripts
        # name every path absolutely (docs/VARIANTS.md).
        scripts = os.path.join(work, "slurm-jobs")
        written = run([ivshadow, "variants", base, sweep, "-o", out, "--size", SIZE, "--frames",
                       "1", "--slurm", "slurm-jobs", "--shards", "4", "--limit", "2"],
                      expect=[0], cwd=work)
        if "sh " + os.path.join(scripts, "submit.sh") not in written.stdout:
            fail("--slurm does not say how to submit: %s" % written.stdout)
        with open(os.path.join(scripts, "variants.sbatch")) as f:
            array = f.read()
        for needed in ("#SBATCH --array=0-3%2", '--shard "${SLURM_ARRAY_TASK_ID}/4"'):
            if needed not in array:
                fail("variants.sbatch lacks %r:\n%s" % (needed, array))
        if status_counts(ivshadow, out) != "done 0, failed 0, pending 14 of 14 variants":
            fail("before submitting, --status says %s" % status_counts(ivshadow, out))
        submitted = run(["sh", os.path.join(scripts, "submit.sh")], expect=[0], env=cluster.env,
                        cwd=cluster_dir)
        print(submitted.stdout.strip())
        deadline = time.time() + 300
        while any(line.strip() for line in cluster.jobs()):
            if time.time() > deadline:
                fail("the jobs did not finish in 5 minutes: %s\n%s" %
                     (cluster.jobs(), cluster.log_tail()))
            time.sleep(0.5)
        logs = sorted(os.listdir(os.path.join(out, "logs")))
        tasks = [name for name in logs if name.startswith("variants-")]
        if len(tasks) != 4 or not any(name.startswith("merge-") for name in logs):
            fail("expected 4 array task logs and a merge log, found %s" % logs)
        merge_log = [name for name in logs if name.startswith("merge-")][0]
        with open(os.path.join(out, "logs", merge_log)) as f:
            merged = f.read()
        if "done 13, failed 1, pending 0 of 14 variants" not in merged:
            fail("the merge job says: %s" % merged)
        check_same_as_local(ivshadow, local, out, "Slurm job array of 4 tasks")
    finally:
        cluster.stop()
    shutil.rmtree(cluster_dir, ignore_errors=True)
    return 0


def main():
    ivshadow, base, sweep, work, route = sys.argv[1:6]
    os.makedirs(work, exist_ok=True)
    routes = {"parallel": route_parallel, "retry": route_retry, "slurm": route_slurm}
    local = local_run(ivshadow, base, sweep, work)
    sys.exit(routes[route](ivshadow, base, sweep, work, local))


if __name__ == "__main__":
    main()
