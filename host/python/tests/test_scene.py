"""Scenes: loading, fields by their INI names, errors that name the field."""

import pytest

import beamslider
from conftest import config


def test_precision_version_and_build_tag_are_exposed():
    import beamslider.double as d
    import beamslider.float32 as f
    assert (d.precision, f.precision) == ("double", "float")
    assert d.real is not f.real and f.real().dtype.itemsize == 4
    assert d.version == f.version == beamslider.__version__
    assert d.build_tag != f.build_tag
    assert beamslider.Scene is d.Scene


def test_fields_read_by_their_ini_names(bs):
    scene = bs.Scene.load(config("fig6"), **{"excitation.frequency": 110}, run={"t_end": 2.5})
    assert scene["excitation.frequency"] == 110
    assert scene["run.t_end"] == 2.5 and scene.t_end == 2.5
    assert scene["run.model"] == "free" and scene.model == "free"
    assert scene.name == "fig6"
    assert scene.steps == round(2.5 / scene.dt)
    with pytest.raises(KeyError, match="no_such"):
        scene["run.no_such"]


def test_from_text_reads_a_scene_relative_to_its_name(bs):
    with open(config("fig6")) as f:
        text = f.read()
    scene = bs.Scene.from_text(text, name=config("fig6"))
    assert scene.hash == bs.Scene.load(config("fig6")).hash


def test_a_bad_line_raises_scene_error_naming_file_line_field_and_range(bs):
    text = "[scene]\nname = broken\n[numerics]\ndt = -1\n"
    with pytest.raises(beamslider.SceneError) as caught:
        bs.Scene.from_text(text, name="broken.ini")
    error = caught.value
    assert (error.file, error.line, error.field) == ("broken.ini", 4, "numerics.dt")
    assert error.allowed and "(0, inf)" in error.allowed
    assert str(error).startswith("broken.ini:4: [numerics] dt = -1")


def test_a_bad_override_raises_scene_error_naming_it(bs):
    with pytest.raises(beamslider.SceneError) as caught:
        bs.Scene.load(config("fig6"), **{"excitation.frequency": -5})
    assert caught.value.override == "excitation.frequency=-5"
    assert caught.value.field == "excitation.frequency"
    with pytest.raises(beamslider.SceneError, match="no_such"):
        bs.Scene.load(config("fig6"), **{"excitation.no_such": 1})


def test_a_missing_file_raises_scene_error_naming_it(bs):
    with pytest.raises(beamslider.SceneError, match="nowhere.ini"):
        bs.Scene.load("nowhere.ini")
