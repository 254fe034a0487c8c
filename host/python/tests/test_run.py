"""Runs, sweeps and maps against what the `beamslider` program prints."""

import _thread
import json
import signal
import threading
import time

import numpy
import pytest

import beamslider
from conftest import cli, cli_run, config

# figures of the summary that are measured, not computed
MEASURED = ("wall_s", "steps_per_s", "revision")


@pytest.mark.parametrize("precision", ["double", "float32"])
def test_the_fig6_60_s_run_gives_the_cli_summary_and_hash(precision):
    bs = __import__("beamslider." + precision, fromlist=["Scene"])
    cli = cli_run(precision, "fig6", "run.t_end=60")
    run = bs.Scene.load(config("fig6")).run(t_end=60, every=100)
    assert run.hash == cli["hash"]
    mine = {key: value for key, value in run.summary.items() if key not in MEASURED}
    assert mine == {key: value for key, value in cli.items() if key not in MEASURED}
    # the rows: t = 0 and every 100th step, the last one the summary's
    assert len(run.t) == run.steps // 100 + 1 == 30001
    assert run.t[0] == 0 and run.t[-1] == pytest.approx(60, rel=1e-12)
    assert run.s[-1] == pytest.approx(cli["s_final"], rel=1e-8)
    assert run.s.dtype == numpy.float64 and run.contacts.dtype == numpy.uint32
    assert numpy.all(numpy.isfinite(run.w_sensor))


def test_a_progress_callback_hears_the_run_and_can_stop_it(bs):
    scene = bs.Scene.load(config("fig6"), **{"run.t_end": 4})
    heard = []
    scene.run(progress=lambda fraction, detail: heard.append(fraction))
    assert heard and heard == sorted(heard) and 0 <= heard[0] and heard[-1] <= 1

    class Enough(Exception):
        pass

    def stop(fraction, detail):
        if fraction > 0:
            raise Enough()

    with pytest.raises(Enough):
        scene.run(progress=stop)


def test_ctrl_c_stops_a_run_at_its_next_progress_report():
    """A KeyboardInterrupt arriving while the run is in C is raised by the
    progress hook's first bytecode, outside its try: it must stop the run
    and be raised, not be printed and lost by cffi."""
    scene = beamslider.Scene.load(config("fig6"), **{"run.t_end": 120})
    # Python's own SIGINT handler, which interrupt_main needs: a process
    # started in the background by a non-interactive shell (make test under
    # nohup, `&` in a script) inherits SIGINT ignored, and the interrupt is
    # then dropped
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, _thread.interrupt_main)
    start = time.process_time()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            scene.run(every=100000)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert time.process_time() - start < 1.0   # the whole run takes 1-2 CPU-s


@pytest.mark.parametrize("precision", ["double", "float32"])
def test_a_sweep_gives_the_cli_points_and_summary(precision, tmp_path):
    bs = __import__("beamslider." + precision, fromlist=["Scene"])
    grid = ("--from", "0.3", "--to", "0.32", "--step", "0.01", "--hold", "2", "--record", "2")
    cli_summary = json.loads(cli(precision, "sweep", config("fig6"), "--dir", "down", "--out",
                                 str(tmp_path / "sweep.csv"), *grid))
    cli_points = numpy.genfromtxt(tmp_path / "sweep.csv", delimiter=",", names=True)
    sweep = bs.Scene.load(config("fig6")).sweep(direction="down", start=0.3, stop=0.32, step=0.01, hold=2,
                                                record=2)
    assert {k: v for k, v in sweep.summary.items() if k not in MEASURED} == \
        {k: v for k, v in cli_summary.items() if k not in MEASURED}
    assert len(sweep) == 3 and list(sweep.s) == pytest.approx([0.32, 0.31, 0.3])
    for column in ("s", "amp_h", "v_mean"):  # the CSV's 7 digits
        assert getattr(sweep, column) == pytest.approx(cli_points[column], rel=1e-6, abs=1e-12)


def test_a_map_writes_the_tables_of_the_cli(tmp_path):
    vary = ("excitation.frequency=120:124:2", "excitation.acceleration=10,14")
    cli("double", "map", config("fig6"), "--set", "run.t_end=0.2", "--vary", vary[0], "--vary", vary[1],
        "--repeat", "2", "--jobs", "2", "--out", str(tmp_path / "cli"))
    beamslider.Scene.load(config("fig6"), **{"run.t_end": 0.2}).map(vary=list(vary), repeat=2, jobs=1,
                                                                      dir=tmp_path / "python")
    for table in ("map.csv", "runs.csv"):
        assert (tmp_path / "python" / table).read_text() == (tmp_path / "cli" / table).read_text()


def test_a_map_returns_its_tables(bs, tmp_path):
    scene = bs.Scene.load(config("fig6"), **{"run.t_end": 0.2})
    table = scene.map(vary={"excitation.frequency": (120, 124, 2), "excitation.acceleration": [10, 14]},
                      repeat=1, jobs=2, dir=tmp_path / "map")
    assert table.complete is True and len(table.points) == 6 and len(table.runs) == 6
    assert list(table.axes["excitation.frequency"]) == [120, 122, 124]
    assert table.grid("amp_h_mean").shape == (3, 2)
    assert (tmp_path / "map" / "map.csv").exists()
    with pytest.raises(beamslider.SceneError, match="no_such"):
        scene.map(vary={"excitation.no_such": [1, 2]})
