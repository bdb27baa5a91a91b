#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The C API tests (ctest names api.*) and the C and Fortran examples (example.*) of a normal,
unsanitized build, run under valgrind's memcheck: an invalid read or write, a use of an
uninitialised value or a definitely lost block in the library, the tests or the Fortran module
makes the run fail. It complements the sanitizers, which do not see the Fortran code (a
sanitized build has no Fortran) nor uninitialised reads (MemorySanitizer would need every
library rebuilt with it), and runs the programs as the build made them, with nothing rebuilt.

    tests/valgrind/run_valgrind.py BUILD_DIR [JOBS]

The tests are those of `ctest --show-only=json-v1`, with their commands, working directories
and environments, two at a time by default, each on one thread (OMP_NUM_THREADS=1: valgrind
runs every thread on one core anyway, and libgomp's idle threads only slow it down).
Suppressions, each with its reason, are in valgrind.supp next to this script. To find where
an uninitialised value came from, run the test's command by hand with --track-origins=yes
(left out here: it doubles the run's time).
"""
import json
import os
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))

# Tests left out, and why.
SKIPPED = {
    # They ask for arrays larger than the machine's memory on purpose, to check that the
    # library returns ASP_ERR_OUT_OF_MEMORY; under valgrind's allocator such requests are
    # refused too, but valgrind reports them as errors ("fishy" sizes), and checking what they
    # check needs no valgrind: the sanitized build runs them.
    "api.defects": "asks for arrays larger than memory on purpose",
    "api.free_substrate": "asks for arrays larger than memory on purpose",
    # They solve the same scenes on 1 to 4 threads and compare the results: under valgrind the
    # threads take turns on one core, so the two took a third of the run's time (90 s each here)
    # to check what the build's own test suite checks; the single-threaded calls they make are
    # those of api.c_interface and the examples.
    "api.grid_threads": "solves on 1 to 4 threads, which valgrind runs one at a time (slow)",
    "api.grid_threads_from_environment": "as api.grid_threads",
}


def selected(name):
    if name in SKIPPED:
        return False
    # The distributed examples run under mpiexec: valgrind would check mpiexec, not the example,
    # and Open MPI's transports are full of reads valgrind cannot follow. The serial examples
    # cover the same library code.
    if name.startswith("example.") and "distributed" in name:
        return False
    return name.startswith("api.") or name.startswith("example.")


def tests_of(build_dir):
    listing = subprocess.run(["ctest", "--test-dir", build_dir, "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    for test in json.loads(listing)["tests"]:
        if not selected(test["name"]) or "command" not in test:
            continue
        properties = {p["name"]: p["value"] for p in test.get("properties", [])}
        environment = dict(os.environ, OMP_NUM_THREADS="1")
        for setting in properties.get("ENVIRONMENT", []):
            key, _, value = setting.partition("=")
            environment[key] = value
        yield (test["name"], test["command"], properties.get("WORKING_DIRECTORY", build_dir),
               environment)


def run(test, valgrind, log_dir):
    name, command, directory, environment = test
    log = os.path.join(log_dir, name + ".log")
    started = time.monotonic()
    result = subprocess.run(
        [valgrind, "--quiet", "--error-exitcode=99", "--leak-check=full",
         "--errors-for-leak-kinds=definite",
         "--suppressions=" + os.path.join(HERE, "valgrind.supp"), "--log-file=" + log] + command,
        cwd=directory, env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
        text=True)
    return name, result.returncode, time.monotonic() - started, log, result.stdout


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    build_dir = os.path.abspath(sys.argv[1])
    jobs = int(sys.argv[2]) if len(sys.argv) == 3 else 2
    valgrind = shutil.which("valgrind")
    if valgrind is None:
        sys.exit("run_valgrind.py: valgrind is not installed (Debian: apt-get install valgrind)")
    log_dir = os.path.join(build_dir, "valgrind")
    os.makedirs(log_dir, exist_ok=True)
    tests = list(tests_of(build_dir))
    if not tests:
        sys.exit("run_valgrind.py: no api.* or example.* test in " + build_dir)
    failed = []
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for name, status, seconds, log, output in pool.map(lambda t: run(t, valgrind, log_dir),
                                                            tests):
            verdict = "ok" if status == 0 else "FAILED (%s)" % (
                "valgrind found errors" if status == 99 else "exit status %d" % status)
            print("%-45s %6.1f s  %s" % (name, seconds, verdict), flush=True)
            if status != 0:
                failed.append(name)
                sys.stdout.write(output)
                with open(log) as f:
                    sys.stdout.write(f.read())
    for name, reason in sorted(SKIPPED.items()):
        print("%-45s skipped: %s" % (name, reason))
    if failed:
        sys.exit("run_valgrind.py: %d of %d failed: %s" % (len(failed), len(tests),
                                                           " ".join(failed)))
    print("run_valgrind.py: %d tests clean under valgrind" % len(tests))


if __name__ == "__main__":
    main()
