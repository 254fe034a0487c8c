"""Stepping a Sim: many steps a call, checkpoints, threads, the GIL."""

import threading
import time

import numpy
import pytest

import beamslider
from conftest import config


def test_stepping_is_the_run_of_the_scene(bs):
    scene = bs.Scene.load(config("fig6"), **{"run.t_end": 1})
    sim = scene.sim()
    trace = sim.step(scene.steps, every=1000)
    assert len(trace) == scene.steps // 1000 and trace.t[-1] == pytest.approx(1)
    assert sim.hash == scene.run().hash
    assert sim.steps == scene.steps and sim.t == pytest.approx(1)


def test_a_run_saved_half_way_and_restored_continues_as_the_whole_run(bs):
    scene = bs.Scene.load(config("fig6"), **{"run.t_end": 2})
    whole = scene.sim()
    whole.step(scene.steps, every=scene.steps)
    first = scene.sim()
    first.step(scene.steps // 2, every=scene.steps)
    checkpoint = first.save()
    assert isinstance(checkpoint, bytes) and len(checkpoint) == bs.checkpoint_size
    second = scene.sim(s0=0.2)
    second.restore(checkpoint)
    second.step(scene.steps - scene.steps // 2, every=scene.steps)
    assert second.hash == whole.hash


def test_a_checkpoint_of_the_other_precision_or_a_damaged_one_is_refused():
    import beamslider.double as d
    import beamslider.float32 as f
    sim = d.Scene.load(config("fig6")).sim()
    other = f.Scene.load(config("fig6")).sim()
    before = sim.hash
    with pytest.raises(beamslider.CheckpointError):
        sim.restore(other.save())
    damaged = bytearray(sim.save())
    damaged[len(damaged) // 2] ^= 1
    with pytest.raises(beamslider.CheckpointError):
        sim.restore(damaged)
    assert sim.hash == before


def test_step_measured_writes_a_row_per_step_into_the_given_buffers(bs):
    scene = bs.Scene.load(config("fig6"))
    sim = scene.sim()
    accel = 15 * numpy.sin(2 * numpy.pi * 124 * scene.dt * numpy.arange(1000))
    rows = bs.Trace(1000, ("t", "s", "w_sensor"))
    out = sim.step_measured(accel, out=rows)
    assert out is rows and len(rows) == 1000 and sim.steps == 1000
    first = rows.w_sensor.copy()
    again = scene.sim()
    again.step_measured(accel, out=rows)
    assert numpy.array_equal(rows.w_sensor, first) and again.hash == sim.hash
    with pytest.raises(beamslider.ArgumentError):
        sim.step_measured(numpy.zeros((2, 2)))


def test_a_step_the_core_refuses_raises_with_the_rows_up_to_it(bs):
    sim = bs.Scene.load(config("fig6")).sim()
    with pytest.raises(beamslider.RunError, match="step 3") as caught:
        sim.step_measured([1.0, 2.0, float("nan"), 4.0])
    assert sim.steps == 2 and len(caught.value.result) == 2 and caught.value.status


def test_a_progress_callback_hears_the_steps_in_chunks(bs):
    sim = bs.Scene.load(config("fig6")).sim()
    heard = []
    trace = sim.step(200000, every=1000, progress=lambda fraction, detail: heard.append(fraction))
    assert len(heard) == 4 and heard[-1] == 1.0 and heard == sorted(heard)
    assert len(trace) == 200 and sim.steps == 200000


def test_four_threads_run_four_scenes_as_four_serial_runs(bs):
    scenes = [bs.Scene.load(config(name), **{"run.t_end": 1}) for name in ("fig6", "fig7", "fig8", "fig9")]
    serial = [scene.run().hash for scene in scenes]
    threaded = [None] * 4

    def run(i):
        threaded[i] = scenes[i].run().hash

    threads = [threading.Thread(target=run, args=(i,)) for i in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert threaded == serial


def test_the_gil_is_released_while_steps_run():
    """Python code in another thread goes on while a long step(n) runs in C:
    with the GIL held, the main loop would not tick at all in the middle of
    the call."""
    sim = beamslider.Scene.load(config("fig6")).sim()
    span = {}

    def work():
        span["start"] = time.perf_counter()
        sim.step(400000, every=400000)
        span["end"] = time.perf_counter()

    thread = threading.Thread(target=work)
    ticks = []
    thread.start()
    while thread.is_alive():
        ticks.append(time.perf_counter())
    thread.join()
    start, end = span["start"], span["end"]
    middle = [t for t in ticks if start + (end - start) / 4 < t < end - (end - start) / 4]
    assert end - start > 0.01 and len(middle) > 10
