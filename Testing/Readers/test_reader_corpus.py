"""The reader against a fuzz corpus: each malformed or odd file (corpus/make_corpus.py) is opened
in its own pvpython process (a fork of this one, with ParaView and the plugin loaded: a fresh
pvpython per file costs 1.5 s of start-up), under a time limit and an address-space cap, and must
give a clean error or the right data as the manifest says; never a signal, a hang, or a silent
wrong read."""
import json
import os
import resource
import signal
import subprocess
import sys

import pftest

from paraview.simple import LoadPlugin  # noqa: F401 (not *: it would shadow all/any)
from paraview import simple

pftest.load(vars(simple))
here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "corpus"))
import open_one  # noqa: E402

folder = os.path.join(pftest.scratch_dir(), "corpus")
subprocess.run(["/usr/bin/python3", os.path.join(here, "corpus", "make_corpus.py"), folder], check=True)
subprocess.run(["/usr/bin/python3", os.path.join(here, "corpus", "make_layout_corpus.py"), folder], check=True)
manifest = json.load(open(os.path.join(folder, "manifest.json"))) + json.load(open(os.path.join(folder, "layouts.json")))
TIME_LIMIT_S = 60
ADDRESS_SPACE_BYTES = 8 << 30  # a file that makes the reader allocate beyond this fails the test


def start(entry):
    """Forks a copy of this pvpython (ParaView and the plugin already loaded) that opens one file
    under an address-space cap and an alarm, and writes its result to a file."""
    out = os.path.join(folder, entry["file"] + ".result")
    pid = os.fork()
    if pid == 0:
        code = 1
        try:
            resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE_BYTES, ADDRESS_SPACE_BYTES))
            resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
            signal.alarm(TIME_LIMIT_S)  # SIGALRM ends a hung child
            reader = simple.ParaFluidHDF5Particles
            result = open_one.open_file(os.path.join(folder, entry["file"]), reader)
            with open(out, "w") as f:
                json.dump(result, f)
            code = 0
        finally:
            os._exit(code)
    return pid, out


def finish(entry, pid, out):
    _, status = os.waitpid(pid, 0)
    if os.WIFSIGNALED(status):
        sig = os.WTERMSIG(status)
        return None, "hung: no answer in %d s" % TIME_LIMIT_S if sig == signal.SIGALRM else "killed by signal %d" % sig
    if os.WEXITSTATUS(status) != 0 or not os.path.exists(out):
        return None, "exit %d without a result" % os.WEXITSTATUS(status)
    return json.load(open(out)), None


def close(a, b):
    if isinstance(a, str) or isinstance(b, str):
        return str(a) == str(b)
    return abs(a - b) <= 1e-6 * max(1.0, abs(b))


def judge(entry, result):
    """What is wrong with `result` for this entry; empty when it is right."""
    expect = entry["expect"]
    error = result["error"]
    problems = []
    if expect == "error":
        if not error:
            problems.append("expected an error with %s, got data" % entry["error"])
        elif not all(w in error for w in entry["error"]):
            problems.append("error %r lacks %s" % (error, entry["error"]))
        if result.get("points"):
            problems.append("error case produced %d points" % result["points"])
    elif expect == "data":
        if error:
            return ["expected data, got the error %r" % error]
        if result.get("points") != entry["points"]:
            problems.append("points %s, expected %s" % (result.get("points"), entry["points"]))
        for kind in ("arrays", "field", "strings"):
            for name, values in entry.get(kind, {}).items():
                got = result.get(kind, {}).get(name)
                if got is None or len(got) < len(values) or not all(close(g, v) for g, v in zip(got, values)):
                    problems.append("%s %s = %s, expected %s" % (kind, name, got, values))
        for name in entry.get("absent", []):
            if name in result.get("arrays", {}):
                problems.append("array %s should not be read" % name)
        for key in ("steps", "last_points"):
            if key in entry and result.get(key) != entry[key]:
                problems.append("%s %s, expected %s" % (key, result.get(key), entry[key]))
        for word in entry.get("warn", []):
            if word not in result["warning"]:
                problems.append("no warning with %r (warnings: %r)" % (word, result["warning"]))
    return problems


failures = []
running = []
parallel = os.cpu_count() or 2
for k, entry in enumerate(manifest):
    running.append((entry,) + start(entry))
    while running and (len(running) >= parallel or k == len(manifest) - 1):
        entry_done, pid, out = running.pop(0)
        result, crash = finish(entry_done, pid, out)
        if crash:
            failures.append("%s: %s" % (entry_done["file"], crash))
            continue
        for problem in judge(entry_done, result):
            failures.append("%s: %s" % (entry_done["file"], problem))
for failure in failures:
    print(failure)
pftest.check(not failures, "%d of %d corpus cases failed" % (len(failures), len(manifest)))
print("reader corpus: %d cases, all clean" % len(manifest))
