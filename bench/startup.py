#!/usr/bin/env python3
"""Start-up and peak RSS of small runs (bench/README.md "Start-up"): each case runs K times,
median wall time (ms) and median peak RSS (MB) of the process (os.wait4's rusage, per child).

usage: bench/startup.py [--runs K] [--ncc PATH] [--base PATH]
  --base: a second ncc (an older build) measured in the same run, case by case.
Cases: the bracket example by source (eval, jit), as an object (ncc run prog.o), as an
executable (--emit=exe), and `ncc --version`."""
import argparse, os, shutil, statistics, subprocess, tempfile, time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ap = argparse.ArgumentParser()
ap.add_argument("--runs", type=int, default=21)
ap.add_argument("--ncc", default=os.path.join(root, "build", "utils", "ncc"))
ap.add_argument("--base")
args = ap.parse_args()


def measure(cmd):
    walls, rss = [], []
    for _ in range(args.runs):
        t = time.perf_counter()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(p.pid, 0)
        walls.append((time.perf_counter() - t) * 1000)
        if status:
            raise SystemExit(f"failed: {' '.join(cmd)}")
        rss.append(usage.ru_maxrss / 1024)
    return statistics.median(walls), statistics.median(rss)


work = tempfile.mkdtemp()
src = os.path.join(work, "bracket.nc")
shutil.copy(os.path.join(root, "examples", "bracket.nc"), src)
obj, exe = os.path.join(work, "bracket.o"), os.path.join(work, "bracket")
subprocess.run([args.ncc, "compile", src, "--emit=obj", "-o", obj], check=True)
subprocess.run([args.ncc, "compile", src, "--emit=exe", "-o", exe], check=True)
cases = [("ncc run bracket.nc (eval)", ["run", src]), ("ncc run bracket.nc --engine=jit", ["run", src, "--engine=jit"]),
         ("ncc run bracket.o", ["run", obj]), ("ncc --version", ["--version"])]
print(f"{'case':36} {'ncc ms':>8} {'MB':>6}" + (f" {'base ms':>8} {'MB':>6}" if args.base else ""))
for name, a in cases:
    w, r = measure([args.ncc] + a)
    line = f"{name:36} {w:8.1f} {r:6.1f}"
    if args.base:
        try:
            bw, br = measure([args.base] + a)
            line += f" {bw:8.1f} {br:6.1f}"
        except SystemExit:
            line += f" {'-':>8} {'-':>6}"
    print(line)
w, r = measure([exe])
print(f"{'./bracket (--emit=exe)':36} {w:8.1f} {r:6.1f}")
shutil.rmtree(work)
