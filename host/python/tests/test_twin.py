"""The twin: the observer's design, and the observer following a plant."""

import numpy
import pytest

import beamslider
from conftest import config


@pytest.mark.slow
def test_the_observer_finds_the_plants_slider_from_a_wrong_start():
    scene = beamslider.Scene.load(config("fig6"))
    gains = scene.twin_gains(1e-6, map_frequencies=[124])
    assert gains.signal == "deflection" and gains.map_frequency == [124]
    n = 500000                                   # 10 s
    omega, dt, k = 2 * numpy.pi * 124, scene.dt, numpy.arange(n)
    accel = 14 * (numpy.cos(omega * k * dt) - numpy.cos(omega * (k + 1) * dt)) / (omega * dt)  # step means
    plant = scene.sim()
    truth = plant.step_measured(accel, columns=("s", "w_sensor"))
    twin = scene.sim(s0=0.27)
    observer = beamslider.Observer(twin, gains)
    noise = 1e-6 * numpy.random.default_rng(1).standard_normal(n)
    estimates = observer.step(accel, truth.w_sensor + noise, every=5000)
    assert len(estimates) == 100 and numpy.all(numpy.isfinite(estimates.s))
    assert abs(observer.estimate()["s"] - plant.s) < 0.02
    assert twin.steps == n


def test_gains_refuse_a_bad_noise():
    scene = beamslider.Scene.load(config("fig6"))
    with pytest.raises(beamslider.SceneError, match="noise"):
        scene.twin_gains(-1.0)


def test_gains_refuse_map_frictions_out_of_order():
    scene = beamslider.Scene.load(config("fig6"))
    with pytest.raises(beamslider.SceneError, match="map friction 2"):
        scene.twin_gains(1e-6, map_frictions=[0.2, 0.1])
    with pytest.raises(beamslider.ArgumentError, match="map_frictions"):
        scene.twin_gains(1e-6, map_frictions=[])
