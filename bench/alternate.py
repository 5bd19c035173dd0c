#!/usr/bin/env python3
"""Compare builds of Glint on a shared or noisy machine by alternating them run by run, so
that load from other processes falls on every build alike (docs/performance.md uses it).

    bench/alternate.py process RUNS 'COMMAND with {bin}' BIN [BIN ...]
        Whole-process wall and CPU time (user + system, of the command and its children) of
        COMMAND, {bin} replaced by each binary in turn; prints min and median wall time and
        median CPU time per binary, and in how many runs each binary used less CPU time than
        the first one (CPU time moves less than wall time when other work shares the
        machine). Example:
        bench/alternate.py process 9 '{bin} render mesh.ply -o /tmp/x.png -q --width 1 --height 1' \\
            /tmp/glint-before build/glint
        With --idle SECONDS first (bench/alternate.py --idle 3 process ...), the machine
        idles that long before each run, as between a user's renders: on a virtual machine
        whose host takes back the guest's free memory, fresh memory then costs more than in
        runs back to back (docs/performance.md, "Fresh memory on an idle machine").

    bench/alternate.py build RUNS MESH THREADS GLINT_BENCH [GLINT_BENCH ...]
        Glint's BVH build time as glint-bench reports it (--rays primary --reps 3 --json, the
        median of its three builds per run); prints min and median of the runs per binary.

    bench/alternate.py trace RUNS RAYS THREADS GLINT_BENCH [GLINT_BENCH ...] [-- MESH ...]
        Tracing throughput as glint-bench reports it (--reps 3 --json), RAYS and THREADS
        comma-separated (incoherent,primary and 1,2); prints, per mesh, ray set and thread
        count, each binary's median Mrays/s over the runs and its median ratio to Embree in
        the same run, which cancels most of a shared machine's drift. Without meshes,
        glint-bench's default ones.
"""
import json
import resource
import statistics
import subprocess
import sys
import time


def children_cpu_seconds():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def process_times(runs, command, binaries, idle_seconds):
    """Per binary, (wall ms, CPU ms) of each run."""
    times = {b: [] for b in binaries}
    for _ in range(runs):
        for b in binaries:
            time.sleep(idle_seconds)
            cpu_start, start = children_cpu_seconds(), time.perf_counter()
            subprocess.run(command.format(bin=b), shell=True, check=True, stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
            times[b].append((1000.0 * (time.perf_counter() - start), 1000.0 * (children_cpu_seconds() - cpu_start)))
    return times


def print_process_times(times):
    first = next(iter(times.values()))
    for binary, t in times.items():
        wall, cpu = [w for w, _ in t], [c for _, c in t]
        line = (f"{binary}: wall min {min(wall):.1f} ms, median {statistics.median(wall):.1f} ms; "
                f"CPU median {statistics.median(cpu):.1f} ms ({len(t)} runs)")
        if t is not first:
            less = sum(c < c0 for (_, c), (_, c0) in zip(t, first))
            line += f"; less CPU than the first in {less} of {len(t)}"
        print(line)


def build_times(runs, mesh, threads, binaries):
    times = {b: [] for b in binaries}
    for _ in range(runs):
        for b in binaries:
            out = subprocess.run([b, "--mesh", mesh, "--rays", "primary", "--threads", threads, "--reps", "3",
                                  "--json"], capture_output=True, text=True, check=True).stdout
            times[b] += [r["glint_ms"] for r in json.loads(out) if r["rays"] == "build"]
    return times


def trace_rates(runs, rays, threads, binaries, meshes):
    rates = {}
    for _ in range(runs):
        for b in binaries:
            command = [b, "--reps", "3", "--json"]
            command += [a for r in rays.split(",") for a in ("--rays", r)]
            command += [a for t in threads.split(",") for a in ("--threads", t)]
            command += [a for m in meshes for a in ("--mesh", m)]
            records = json.loads(subprocess.run(command, capture_output=True, text=True, check=True).stdout)
            for r in records:
                if r["rays"] != "build":
                    cell = rates.setdefault((r["mesh"], r["rays"], r["threads"]), {b: [] for b in binaries})
                    cell[b].append((r["glint_mrays"], r["glint_mrays"] / r["embree_mrays"]))
    return rates


def print_rates(rates):
    for (mesh, rays, threads), per_binary in rates.items():
        cells = [f"{b}: {statistics.median(m for m, _ in v):.2f} Mrays/s, {statistics.median(q for _, q in v):.3f} "
                 f"of Embree" for b, v in per_binary.items()]
        print(f"{mesh} {rays} {threads} thr | " + " | ".join(cells))


def main():
    args = sys.argv[1:]
    idle_seconds = 0.0
    if len(args) >= 2 and args[0] == "--idle":
        idle_seconds, args = float(args[1]), args[2:]
    if len(args) >= 4 and args[0] == "process":
        print_process_times(process_times(int(args[1]), args[2], args[3:], idle_seconds))
        return
    if len(args) >= 5 and args[0] == "build":
        times = build_times(int(args[1]), args[2], args[3], args[4:])
    elif len(args) >= 5 and args[0] == "trace":
        binaries, meshes = (args[4:args.index("--")], args[args.index("--") + 1:]) if "--" in args else (args[4:], [])
        print_rates(trace_rates(int(args[1]), args[2], args[3], binaries, meshes))
        return
    else:
        sys.exit(__doc__)
    for binary, t in times.items():
        print(f"{binary}: min {min(t):.1f} ms, median {statistics.median(t):.1f} ms ({len(t)} runs)")


if __name__ == "__main__":
    main()
