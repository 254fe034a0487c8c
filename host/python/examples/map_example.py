"""map_example.py - a small operating map of fig6 run from Python and drawn
with matplotlib (docs/python.md, "Example: a map"): the settled slider
position and the outcome class over excitation frequency and level.

    make python
    PYTHONPATH=build/python/lib /usr/bin/python3 host/python/examples/map_example.py \
        [--out docs/figures/python_map.png] [--t-end 20] [--jobs 2] [--dir DIR] [--small]

--small runs a 2 x 2 grid of 0.2 s runs (what the tests run). It prints the
map's counts and a line per outcome class.
"""

import argparse
import os

import matplotlib

matplotlib.use("Agg")  # no display needed: the figure goes to a file

import matplotlib.pyplot as plt  # noqa: E402 - after the backend is chosen
import numpy  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import beamslider  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))


def run_map(t_end, jobs, small, directory):
    """The map of fig6 over frequency and acceleration: a beamslider Map
    (kept in directory, where a second run finds the cases done; None: a
    temporary folder)."""
    scene = beamslider.Scene.load(os.path.join(ROOT, "configs", "fig6.ini"), **{"run.t_end": t_end})
    if small:
        vary = {"excitation.frequency": [120, 124], "excitation.acceleration": [10, 14]}
    else:
        vary = {"excitation.frequency": (100, 140, 5), "excitation.acceleration": (5, 20, 5)}
    return scene, scene.map(vary=vary, repeat=1, jobs=jobs, dir=directory)


def draw(scene, table, out):
    frequency = table.axes["excitation.frequency"]
    acceleration = table.axes["excitation.acceleration"]
    settled = table.grid("s_settled_mean")          # (frequencies, accelerations)
    outcome = table.grid("outcome")
    classes = sorted(set(outcome.ravel().tolist()))
    index = numpy.vectorize(classes.index)(outcome)

    figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    image = left.pcolormesh(frequency, acceleration, settled.T, shading="nearest", cmap="viridis")
    figure.colorbar(image, ax=left, label="settled s = x_C / L")
    left.set_title("settled position (mean over the last %g s)" % numpy.min(table.points["window_s"]))
    colours = plt.get_cmap("tab10").colors[:len(classes)]
    right.pcolormesh(frequency, acceleration, index.T, shading="nearest", cmap=ListedColormap(colours),
                     vmin=-0.5, vmax=len(classes) - 0.5)
    right.legend(handles=[Patch(color=c, label=name) for c, name in zip(colours, classes)],
                 loc="upper left", bbox_to_anchor=(1.02, 1), fontsize="small")
    right.set_title("outcome class (docs/maps.md, section 2)")
    for axes in (left, right):
        axes.set_xlabel("excitation frequency [Hz]")
        axes.set_ylabel("base acceleration [m/s$^2$]")
    figure.suptitle("%s, %g s runs from s0 = %g: beamslider %s (%s), scene hash %s"
                    % (scene.name, scene.t_end, scene.s0, beamslider.version, beamslider.precision, scene.hash),
                    fontsize="medium")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    figure.savefig(out, dpi=100)
    plt.close(figure)
    return classes, outcome


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "figures", "python_map.png"))
    parser.add_argument("--t-end", type=float, default=20.0)
    parser.add_argument("--jobs", type=int, default=None)
    parser.add_argument("--dir", default=None, help="the map's folder (resumable); default: a temporary one")
    parser.add_argument("--small", action="store_true")
    args = parser.parse_args()
    scene, table = run_map(0.2 if args.small else args.t_end, args.jobs, args.small, args.dir)
    classes, outcome = draw(scene, table, args.out)
    print("map: %d points, %d runs on %d threads in %.3g s" % (table.points_total, table.run, table.jobs,
                                                               table.wall_s))
    for name in classes:
        print("outcome %s: %d points" % (name, numpy.count_nonzero(outcome == name)))
    print("figure: %s" % args.out)


if __name__ == "__main__":
    main()
