"""low_branch_response.py - what the response on the low branch shows of the friction.

The twin's maps hold |H|(s) only (docs/twin.md, "Friction"); this asks whether the response's
amplitude or phase at the excitation frequency would tell the friction apart at a given s. For
each friction MU and position S, fig6's PCS model (the slider held at S) from rest: HOLD
excitation periods, then RECORD periods of the sensor's deflection w(4L/7), whose component at
the excitation frequency gives the amplitude (over h) and the phase (degrees, against
cos(2 pi f t)). Prints a row per S, then per MU the means over the rows and their scatter from
one position to the next (the rattling's, as a lock-in window of RECORD periods would see it).

    make python
    PYTHONPATH=build/python/lib /usr/bin/python3 host/reports/low_branch_response.py \\
        --mu 0.15,0.2,0.25 --s 0.30:0.38:0.01 --record 400

Run from the repository's root (it reads configs/fig6.ini). The library computes the runs; this
only takes their sums.
"""
import argparse

import numpy

import beamslider


def grid(text):
    """FROM:TO:STEP or v1,v2,..."""
    if ":" in text:
        start, stop, step = (float(v) for v in text.split(":"))
        return [start + k * step for k in range(int(round((stop - start) / step)) + 1)]
    return [float(v) for v in text.split(",")]


def response(mu, s, hold, record):
    """(amplitude / h, phase in degrees) of w(4L/7) at the excitation frequency."""
    scene = beamslider.Scene.load("configs/fig6.ini", **{"contact.friction": mu, "run.model": "pcs",
                                                         "run.s0": s})
    f = scene["excitation.frequency"]
    run = scene.run(t_end=(hold + record) / f, every=1)
    t, w = numpy.asarray(run.t), numpy.asarray(run.w_sensor)
    kept = t > hold / f * (1 + 1e-12)  # the recorded periods: RECORD / f s of rows
    z = 2.0 * numpy.mean(w[kept] * numpy.exp(-2j * numpy.pi * f * t[kept]))
    return abs(z) / scene["beam.thickness"], numpy.degrees(numpy.angle(z))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--mu", default="0.15,0.2,0.25", help="frictions: v1,v2,... or FROM:TO:STEP")
    parser.add_argument("--s", default="0.30:0.38:0.01", help="positions s, as --mu")
    parser.add_argument("--hold", type=int, default=100, help="excitation periods before the record")
    parser.add_argument("--record", type=int, default=25, help="excitation periods recorded")
    options = parser.parse_args()
    mus, positions = grid(options.mu), grid(options.s)
    rows = []
    print("s " + " ".join("amp_h(mu=%g) phase(mu=%g)" % (mu, mu) for mu in mus))
    for s in positions:
        row = [response(mu, s, options.hold, options.record) for mu in mus]
        rows.append(row)
        print("%.4f " % s + " ".join("%.4f %.2f" % value for value in row), flush=True)
    values = numpy.array(rows)  # [s][mu][amplitude, phase]
    for j, mu in enumerate(mus):
        amplitude, phase = values[:, j, 0], values[:, j, 1]
        # the scatter from one position to the next (the standard deviation of the differences
        # of neighbouring rows over sqrt 2: the slow trend with s mostly left out)
        scatter = relative = float("nan")
        if len(positions) > 2:
            scatter = numpy.diff(phase).std() / numpy.sqrt(2.0)
            relative = (numpy.diff(amplitude) / amplitude[1:]).std() / numpy.sqrt(2.0)
        print("mu %g: amp_h mean %.4f scatter %.1f %%, phase mean %.2f scatter %.2f, over %d positions" % (
            mu, amplitude.mean(), 100.0 * relative, phase.mean(), scatter, len(positions)))


if __name__ == "__main__":
    main()
