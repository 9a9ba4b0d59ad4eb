"""The Python package's API (issue 39): design, check and study of shipped scenes, typed
errors with the command line's located problems, and a sweep equal to the CLI's table.

Run by CI after `pip install .` (see .ci/run); `FLAPWRIGHT_BIN` names the binary the
sweep is compared with (default: target/release/flapwright).
"""

import os
import subprocess
import tempfile

import pytest

import flapwright

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SMALL = os.path.join(ROOT, "data", "scenes", "small-aircraft.toml")
LIGHT = os.path.join(ROOT, "data", "scenes", "light-aircraft.toml")


def test_a_shipped_scene_designs_and_its_report_reads_by_attribute():
    d = flapwright.design(SMALL)
    assert d.interference.passes is True
    assert d["interference"]["passes"] is True
    assert d.scene.name == "small-aircraft"
    assert [s.name for s in d.stations] == ["inner", "outer"]


def test_the_same_scene_as_text_and_as_a_path_gives_the_same_figures():
    text = open(SMALL, encoding="utf-8").read()
    by_path = flapwright.check(SMALL)
    by_text = flapwright.check(text)
    assert by_path.interference.passes == by_text.interference.passes
    assert list(by_path.interference.pairs.min_clearance_m) == list(by_text.interference.pairs.min_clearance_m)


def test_a_scene_problem_raises_scene_error_with_its_line_and_key():
    text = open(LIGHT, encoding="utf-8").read().replace("landing_gap_percent = 2.0", "landing_gap_percent = 200.0")
    with pytest.raises(flapwright.SceneError) as raised:
        flapwright.design(text)
    problems = raised.value.problems
    assert problems, "at least one problem"
    file, line, col, key, message = problems[0]
    assert key.endswith("landing_gap_percent")
    expected = text.splitlines().index("landing_gap_percent = 200.0") + 1
    assert line == expected
    assert isinstance(raised.value, flapwright.DesignError)


def test_a_scene_given_as_a_dict_is_the_same_scene():
    tomllib = pytest.importorskip("tomllib")

    with open(LIGHT, "rb") as f:
        tables = tomllib.load(f)
    by_dict = flapwright.check(tables)
    by_path = flapwright.check(LIGHT)
    assert by_dict.interference.passes == by_path.interference.passes


def test_a_sweep_equals_the_command_lines_table():
    pandas = pytest.importorskip("pandas")
    vary = "flap[*].settings.landing_gap_percent=1.6:2.4:0.4"
    frame = flapwright.sweep(LIGHT, vary=vary)
    assert list(frame["verdict"]) == ["pass", "pass", "pass"]
    binary = os.environ.get("FLAPWRIGHT_BIN", os.path.join(ROOT, "target", "release", "flapwright"))
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([binary, "sweep", LIGHT, "--vary", vary, "--out", out, "--quiet"], check=True)
        table = open(os.path.join(out, "sweep.csv"), encoding="utf-8").read()
    cli = pandas.read_csv(__import__("io").StringIO(table), dtype=str, keep_default_na=False)
    # The scene hash differs only by the label: same text, same hash.
    assert list(cli.columns) == list(frame.columns)
    for column in cli.columns:
        ours = [("" if isinstance(v, float) and v != v else str(v)) for v in frame[column]]
        if column in ("variant", "warnings"):
            assert [int(v) for v in cli[column]] == [int(v) for v in frame[column]]
        elif column in flapwright._FIGURES:
            assert [float(v) for v in cli[column]] == [float(v) for v in frame[column]], column
        else:
            assert list(cli[column]) == ours, column


def test_a_sweep_of_a_key_the_scene_lacks_raises_naming_it():
    with pytest.raises(flapwright.DesignError, match="no element named spoiler"):
        flapwright.sweep(LIGHT, vary="flap[spoiler].settings.landing_deg=30,35")


def test_the_reports_figures_are_numpy_arrays_and_tables():
    numpy = pytest.importorskip("numpy")
    d = flapwright.design(SMALL)
    station = d.stations[0]
    origin = station.plane.frame.origin_m
    assert isinstance(origin, numpy.ndarray) and origin.shape == (3,)
    samples = station.mechanism.load_cases[0].samples
    assert isinstance(samples, flapwright.Table)
    assert samples.actuator_load.dtype == float and samples.actuator_load.shape == (samples.rows,)
    # A row reads back as the report has it; nested rows are tables of their own.
    first = samples.row(0)
    assert first["actuator_load"] == samples.actuator_load[0]
    assert isinstance(samples.reactions_n, flapwright.Table)
    assert first["reactions_n"]["A"] == samples.reactions_n.A[0]
    pairs = d.interference.pairs
    assert pairs.point_a_ac.shape == (pairs.rows, 3)
    assert pairs.min_clearance_m.min() == min(pairs.row(i)["min_clearance_m"] for i in range(pairs.rows))
    assert pairs.evaluations.dtype == numpy.int64
    assert list(pairs.part_a[:1]) == ["flap"]
    with pytest.raises(IndexError):
        pairs.row(pairs.rows)


def test_the_thesis_tracks_lean_sweep_gives_numpy_columns():
    numpy = pytest.importorskip("numpy")
    lean = flapwright.thesis_sweep(1000, "landing")
    assert lean.stopped is None
    assert lean.input_m.shape == (1000,) and lean.actuator_force_n.dtype == numpy.float64
    # The nut positions run evenly; the flap turns monotonically; T_R = k F with one k.
    assert numpy.allclose(numpy.diff(lean.input_m), lean.input_m[1] - lean.input_m[0])
    assert numpy.all(numpy.diff(lean.crank_angle_rad) > 0) or numpy.all(numpy.diff(lean.crank_angle_rad) < 0)
    ratio = lean.raise_torque_nm / lean.actuator_force_n
    assert numpy.allclose(ratio, ratio[0])
    # A's speed is the crank's rate times its radius.
    radius = numpy.hypot(lean.nut_pivot_a_x_m, lean.nut_pivot_a_y_m)
    speed = numpy.hypot(lean.nut_pivot_a_vx_mps, lean.nut_pivot_a_vy_mps)
    assert numpy.allclose(speed, numpy.abs(lean.crank_rate_radps) * radius)
    # The shipped thesis scene's report samples the same deployment under the same cases:
    # the same inputs and actuator forces, from the full path.
    report = flapwright.design(os.path.join(ROOT, "data", "scenes", "thesis-case-study.toml"))
    for case in report.stations[0].mechanism.load_cases:
        samples = case.samples
        same = flapwright.thesis_sweep(samples.rows, case.load_case)
        assert numpy.allclose(same.input_m, samples.input, rtol=0, atol=1e-12)
        assert numpy.allclose(same.actuator_force_n, samples.actuator_load, rtol=1e-12, atol=0)
    with pytest.raises(flapwright.DesignError, match="cruise"):
        flapwright.thesis_sweep(10, "take-off")


def test_records_compare_by_their_values_and_keep_numbers_whole():
    first = flapwright.design(SMALL)
    second = flapwright.check(SMALL)
    # Arrays inside: equality is by the report's values, not an ambiguous array truth.
    assert first.stations[0].plane == second.stations[0].plane
    assert first.stations[0].plane != first.stations[1].plane
    assert first.stations[0].plane == first.stations[0].plane.to_dict()
    big = flapwright.Record.wrap([2**70, 1])
    assert list(big) == [2**70, 1]
