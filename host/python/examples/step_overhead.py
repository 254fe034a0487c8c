"""step_overhead.py - what a call from Python costs beside the steps it runs
(docs/python.md, "What it costs"): fig6's 1 s (50 000 steps) stepped

  run     by the library's own loop (scene.run, a row every 50 000 steps),
  batch   by one sim.step(50000) call, no rows,
  rows    by one sim.step(50000) call with a row (t, s, w_sensor, contacts)
          after every step,
  single  by 50 000 sim.step(1) calls,

in turns (run, batch, rows, single; REPEAT times), each timed by the
process's CPU time; prints the median of each in steps per second and
against `run`.

    PYTHONPATH=build/python/lib /usr/bin/python3 host/python/examples/step_overhead.py [REPEAT] [float32]
"""

import os
import statistics
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def main():
    repeat = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    precision = sys.argv[2] if len(sys.argv) > 2 else "double"
    bs = __import__("beamslider." + precision, fromlist=["Scene"])
    scene = bs.Scene.load(os.path.join(ROOT, "configs", "fig6.ini"), **{"run.t_end": 1})
    n = scene.steps
    rows = bs.Trace(n, ("t", "s", "w_sensor", "contacts"))

    def run():
        scene.run(every=n)

    def batch():
        scene.sim().step(n, every=n, columns=())

    def with_rows():
        scene.sim().step(n, every=1, out=rows)

    def single():
        sim = scene.sim()
        step = sim.step
        for _ in range(n):
            step(1, columns=())

    ways = {"run": run, "batch": batch, "rows": with_rows, "single": single}
    cpu = {name: [] for name in ways}
    for _ in range(repeat):
        for name, way in ways.items():
            start = time.process_time()
            way()
            cpu[name].append(time.process_time() - start)
    base = statistics.median(cpu["run"])
    print("fig6, %d steps, %s, median of %d turns (CPU time):" % (n, bs.precision, repeat))
    for name, times in cpu.items():
        median = statistics.median(times)
        print("  %-7s %8.3g steps/s  %6.1f %% of run  %7.3g us a step" % (name, n / median, 100 * base / median,
                                                                           1e6 * median / n))


if __name__ == "__main__":
    main()
