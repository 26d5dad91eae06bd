#!/usr/bin/env python3
"""Start-up and peak RSS of small runs (bench/README.md "Start-up"): each case runs K times,
median wall time (ms), median CPU time (user + system, ms: steadier when other jobs share the
cores) and median peak RSS (MB) of the process (os.wait4's rusage, per child).

usage: bench/startup.py [--runs K] [--ncc PATH] [--base PATH]
  --base: a second ncc (an older build) measured in the same run, case by case.
Cases: the bracket example by source (eval, jit), as an object (ncc run prog.o), as an
executable (--emit=exe), `ncc --version`, and the small-program row of issue 6: an oracle
program (test/lit/oracle/param_computed.ngc) to a canonical trace file against rs274.
The JIT cases run with a compiled-object cache of their own (NCC_CACHE_DIR in a temporary
folder): "--no-cache" compiles every time (a first run), "cached" hits after the first run."""
import argparse, os, shutil, statistics, subprocess, tempfile, time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ap = argparse.ArgumentParser()
ap.add_argument("--runs", type=int, default=21)
ap.add_argument("--ncc", default=os.path.join(root, "build", "utils", "ncc"))
ap.add_argument("--base")
args = ap.parse_args()


def measure(cmd):
    walls, cpus, rss = [], [], []
    for _ in range(args.runs):
        t = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(p.pid, 0)
        walls.append((time.perf_counter() - t) * 1000)
        if status:
            raise SystemExit(f"failed: {' '.join(cmd)}")
        rss.append(usage.ru_maxrss / 1024)
        cpus.append((usage.ru_utime + usage.ru_stime) * 1000)
    return statistics.median(walls), statistics.median(cpus), statistics.median(rss)


work = tempfile.mkdtemp()
os.environ["NCC_CACHE_DIR"] = os.path.join(work, "cache")
src = os.path.join(work, "bracket.nc")
shutil.copy(os.path.join(root, "examples", "bracket.nc"), src)
obj, exe = os.path.join(work, "bracket.o"), os.path.join(work, "bracket")
subprocess.run([args.ncc, "compile", src, "--emit=obj", "-o", obj], check=True)
subprocess.run([args.ncc, "compile", src, "--emit=exe", "-o", exe], check=True)
oracle = os.path.join(root, "test", "lit", "oracle")
ngc, trace = os.path.join(oracle, "param_computed.ngc"), os.path.join(work, "out.canon")
small = ["run", ngc, "--machine=" + os.path.join(oracle, "Inputs", "oracle.toml"), "--trace=canon", "-o", trace, "-q"]
small_obj = os.path.join(work, "small.o")
subprocess.run([args.ncc, "compile", "--machine=" + os.path.join(oracle, "Inputs", "oracle.toml"), ngc, "--emit=obj",
                "-o", small_obj], check=True)
cases = [("ncc run bracket.nc (eval)", ["run", src]),
         ("ncc run bracket.nc jit --no-cache", ["run", src, "--engine=jit", "--no-cache"]),
         ("ncc run bracket.nc jit cached", ["run", src, "--engine=jit"]),
         ("ncc run bracket.o", ["run", obj]), ("ncc --version", ["--version"]),
         ("small .ngc -> canon (eval)", small), ("small .ngc -> canon (jit --no-cache)", small + ["--engine=jit", "--no-cache"]),
         ("small .ngc -> canon (jit cached)", small + ["--engine=jit"]),
         ("small .o -> canon", ["run", small_obj, "--trace=canon", "-o", trace, "-q"])]
fmt = lambda m: f"{m[0]:8.1f} {m[1]:7.1f} {m[2]:6.1f}"
head = f"{'ms':>8} {'cpu ms':>7} {'MB':>6}"
print(f"{'case':36} {head}" + (f"  base: {head}" if args.base else ""))
for name, a in cases:
    line = f"{name:36} {fmt(measure([args.ncc] + a))}"
    if args.base:
        try:
            line += f"        {fmt(measure([args.base] + a))}"
        except SystemExit:
            line += "        (fails)"
    print(line)
# A first run: compile, store, load (a cache of its own whose limit of 0 removes the entry after each store).
first = ["env", "NCC_CACHE_DIR=" + os.path.join(work, "first"), "NCC_CACHE_MAX_MB=0", args.ncc] + small + ["--engine=jit"]
print(f"{'small .ngc -> canon (jit first run)':36} {fmt(measure(first))}")
print(f"{'./bracket (--emit=exe)':36} {fmt(measure([exe]))}")
if shutil.which("rs274"):
    print(f"{'rs274 -g small.ngc':36} {fmt(measure(['rs274', '-g', ngc, trace]))}")
shutil.rmtree(work)
