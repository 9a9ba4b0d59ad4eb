"""A sweep distributed on Dask (issue 39): 40 variants over a LocalCluster of 2 workers
give the table `flapwright sweep` writes for the same variants."""

import io
import os
import subprocess
import sys
import tempfile

import pytest

distributed = pytest.importorskip("dask.distributed")
pandas = pytest.importorskip("pandas")

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "examples", "dask"))

from sweep import sweep_on  # noqa: E402  (the example's own function)

LIGHT = os.path.join(ROOT, "data", "scenes", "light-aircraft.toml")
# 40 variants: the landing gap 1.5-2.475 %c by 0.025.
VARY = "flap[*].settings.landing_gap_percent=1.5:2.475:0.025"


def test_a_sweep_on_two_dask_workers_is_the_command_lines_table():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as client:
        table = sweep_on(client, LIGHT, VARY, shards=4)
        workers = {w for w in client.run(lambda: os.getpid()).values()}
    cluster.close()
    assert len(table) == 40
    assert len(workers) == 2
    binary = os.environ.get("FLAPWRIGHT_BIN", os.path.join(ROOT, "target", "release", "flapwright"))
    with tempfile.TemporaryDirectory() as out:
        subprocess.run([binary, "sweep", LIGHT, "--vary", VARY, "--out", out, "--quiet"], check=True)
        text = open(os.path.join(out, "sweep.csv"), encoding="utf-8").read()
    ours = io.StringIO()
    table.to_csv(ours, index=False)
    cli = pandas.read_csv(io.StringIO(text), dtype=str, keep_default_na=False)
    mine = pandas.read_csv(io.StringIO(ours.getvalue()), dtype=str, keep_default_na=False)
    assert list(cli.columns) == list(mine.columns)
    for column in cli.columns:
        if column in ("variant", "warnings"):
            assert [int(v) for v in cli[column]] == [int(float(v)) for v in mine[column]], column
        elif column in ("scene_sha256", "verdict", "error") or column.startswith("flap["):
            assert list(cli[column]) == list(mine[column]), column
        else:
            assert [float(v) if v else None for v in cli[column]] == [float(v) if v else None for v in mine[column]], column
